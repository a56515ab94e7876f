#pragma once
// Small helpers for the C++ tests: run program text and look at the segments.
#include <string>

#include "toolcomp/run.hpp"
#include "toolcomp/tools/tool_table.hpp"

namespace tctest {

inline toolcomp::Result run_text(const std::string& text, const toolcomp::ToolTable* tools = nullptr,
                                 toolcomp::Dialect d = toolcomp::Dialect::linuxcnc) {
    return toolcomp::run(toolcomp::parse_program(text, d), tools);
}

inline toolcomp::Vec3 end_of(const toolcomp::Path& p, std::size_t i) {
    return {p.end[3 * i], p.end[3 * i + 1], p.end[3 * i + 2]};
}

}  // namespace tctest
