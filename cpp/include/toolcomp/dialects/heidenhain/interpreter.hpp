#pragma once
// The Heidenhain conversational interpreter: runs Klartext blocks and emits the Motion
// stream (tool-centre requests for RL/RR, length offsets from TOOL CALL).
#include <vector>

#include "toolcomp/compensation/profile.hpp"
#include "toolcomp/motion/motion.hpp"
#include "toolcomp/program/diagnostic.hpp"
#include "toolcomp/program/program.hpp"

namespace toolcomp {
class ToolTable;
}

namespace toolcomp::heidenhain {

void interpret(const Program& program, const ToolTable* tools, const ControlProfile& profile, MotionSink& sink,
               std::vector<Diagnostic>& diagnostics);

}  // namespace toolcomp::heidenhain
