#pragma once
// The compensation stages between the Motion stream and the compensated Path.
//
// Tool length compensation is resolved by the interpreter into each move's tool_offset
// (LinuxCNC reports program coordinates with the offset beside them, so the length stage
// only carries it). Cutter radius compensation (and lathe nose radius, its G18 case) is
// the radius stage; 3D compensation along surface normals follows it.
#include <vector>

#include "toolcomp/control/profile.hpp"
#include "toolcomp/compensation/radius.hpp"
#include "toolcomp/compensation/surface.hpp"
#include "toolcomp/motion/motion.hpp"
#include "toolcomp/program/diagnostic.hpp"

namespace toolcomp {

class CompensationChain : public MotionSink {
public:
    // `threads`: the overcut watch may run on a thread of its own (RunOptions::threads).
    CompensationChain(const ControlProfile& profile, MotionSink& out, std::vector<Diagnostic>& diagnostics,
                      bool threads = true)
        : surface_(out), radius_(profile, surface_, diagnostics, threads) {}
    void push(const Motion& m) override { radius_.push(m); }
    void control(const ControlEvent& e) override { radius_.control(e); }
    void finish() override { radius_.finish(); }
    void settle() { radius_.settle(); }

private:
    SurfaceCompensation surface_;  // after the radius stage
    RadiusCompensation radius_;
};

}  // namespace toolcomp
