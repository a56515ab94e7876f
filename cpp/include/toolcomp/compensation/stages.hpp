#pragma once
// The compensation stages between the Motion stream and the compensated Path.
//
// Tool length compensation is resolved by the interpreter into each move's tool_offset
// (LinuxCNC reports program coordinates with the offset beside them, so the length stage
// only carries it). Cutter radius compensation is the next stage to plug in here; until
// then a move that requests it is refused.
#include <vector>

#include "toolcomp/compensation/profile.hpp"
#include "toolcomp/motion/motion.hpp"
#include "toolcomp/program/diagnostic.hpp"

namespace toolcomp {

class CompensationChain : public MotionSink {
public:
    CompensationChain(const ControlProfile& profile, MotionSink& out, std::vector<Diagnostic>& diagnostics)
        : profile_(profile), out_(out), diags_(diagnostics) {}
    void push(const Motion& m) override;
    void finish() override { out_.finish(); }

private:
    const ControlProfile& profile_;
    MotionSink& out_;
    std::vector<Diagnostic>& diags_;
};

}  // namespace toolcomp
