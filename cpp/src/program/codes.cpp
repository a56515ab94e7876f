// The catalogue of diagnostic codes (toolcomp/program/codes.inc) as a table.
#include "toolcomp/program/codes.hpp"

namespace toolcomp {

namespace {
constexpr CodeInfo kCatalogue[] = {
#define TOOLCOMP_CODE(name, code_text, kind, severity, alarm, text) {code_text, ErrorKind::kind, Severity::severity, alarm, text},
#include "toolcomp/program/codes.inc"
#undef TOOLCOMP_CODE
};
}  // namespace

std::span<const CodeInfo> code_catalogue() { return kCatalogue; }

}  // namespace toolcomp
