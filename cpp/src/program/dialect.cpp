#include "toolcomp/program/dialect.hpp"

#include <algorithm>
#include <string>

#include "toolcomp/program/diagnostic.hpp"
#include "toolcomp/program/text.hpp"

namespace toolcomp {

namespace {
struct Entry {
    Dialect d;
    std::string_view name;
};
constexpr Entry kDialects[] = {{Dialect::linuxcnc, "linuxcnc"},
                               {Dialect::fanuc, "fanuc"},
                               {Dialect::sinumerik, "sinumerik"},
                               {Dialect::heidenhain, "heidenhain"},
                               {Dialect::rockwell, "rockwell"}};
}  // namespace

std::string_view dialect_name(Dialect d) {
    for (const auto& e : kDialects)
        if (e.d == d) return e.name;
    return "unknown";
}

Dialect dialect_from_name(std::string_view name) {
    std::string lower(name);
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](char c) { return ascii_lower(c); });
    for (const auto& e : kDialects)
        if (e.name == lower) return e.d;
    throw ParseError("unknown_dialect",
                     "Unknown dialect '" + std::string(name) +
                         "' (expected linuxcnc, fanuc, sinumerik, heidenhain or rockwell)");
}

std::optional<Dialect> dialect_from_suffix(std::string_view path) {
    auto dot = path.rfind('.');
    if (dot == std::string_view::npos) return std::nullopt;
    std::string ext(path.substr(dot + 1));
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](char c) { return ascii_lower(c); });
    if (ext == "ngc") return Dialect::linuxcnc;
    if (ext == "nc" || ext == "tap") return Dialect::fanuc;
    if (ext == "mpf" || ext == "spf") return Dialect::sinumerik;
    if (ext == "h") return Dialect::heidenhain;
    return std::nullopt;
}

Dialect dialect_of_file(std::string_view path, std::optional<Dialect> given) {
    if (given) return *given;
    if (auto s = dialect_from_suffix(path)) return *s;
    throw ParseError("unknown_dialect",
                     "Cannot tell the dialect of '" + std::string(path) + "' from its suffix; pass dialect=");
}

}  // namespace toolcomp
