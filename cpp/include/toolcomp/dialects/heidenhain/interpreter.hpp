#pragma once
// The Heidenhain conversational interpreter: runs Klartext blocks and emits the Motion
// stream (tool-centre requests for RL/RR, length offsets from TOOL CALL).
#include <functional>
#include <vector>

#include "toolcomp/compensation/profile.hpp"
#include "toolcomp/motion/motion.hpp"
#include "toolcomp/program/diagnostic.hpp"
#include "toolcomp/program/program.hpp"

namespace toolcomp {
class ToolTable;
}

namespace toolcomp::heidenhain {

// `progress` (optional) is called with the blocks executed so far every `progress_every`.
void interpret(const Program& program, const ToolTable* tools, const ControlProfile& profile, MotionSink& sink,
               std::vector<Diagnostic>& diagnostics, const std::function<void(std::size_t)>& progress = {},
               std::size_t progress_every = 1 << 16);

}  // namespace toolcomp::heidenhain
