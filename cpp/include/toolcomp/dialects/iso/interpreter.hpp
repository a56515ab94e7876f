#pragma once
#include <functional>
// The ISO interpreter: runs a Program block by block with LinuxCNC's modal semantics (or
// Fanuc's where the profile says so) and emits the Motion stream.
#include <vector>

#include "toolcomp/compensation/profile.hpp"
#include "toolcomp/motion/motion.hpp"
#include "toolcomp/program/diagnostic.hpp"
#include "toolcomp/program/program.hpp"

namespace toolcomp {
class ToolTable;
}

namespace toolcomp::iso {

struct InterpretOptions {
    bool block_delete = false;  // skip blocks that start with '/'
    std::function<void(std::size_t)> progress;  // blocks read so far, every progress_every
    std::size_t progress_every = 1 << 16;
};

// Emits every move into `sink`; non-fatal messages go to `diagnostics`.
// Throws ProgramError (code, message, line, column) at the first error, after the moves
// before the failing block have been emitted.
void interpret(const Program& program, const ToolTable* tools, const ControlProfile& profile,
               const InterpretOptions& options, MotionSink& sink, std::vector<Diagnostic>& diagnostics);

}  // namespace toolcomp::iso
