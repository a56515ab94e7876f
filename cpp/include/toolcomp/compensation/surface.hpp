#pragma once
// The 3D compensation stage: moves with a surface normal (Heidenhain LN) end displaced by
// ΔPT = ΔR2·N − (ΔR − ΔR2)·w (normal_offset.hpp); the next move starts where that one ended.
#include "toolcomp/motion/motion.hpp"

namespace toolcomp {

class SurfaceCompensation : public MotionSink {
public:
    explicit SurfaceCompensation(MotionSink& out) : out_(out) {}
    void push(const Motion& m) override;
    void control(const ControlEvent& e) override { out_.control(e); }
    void finish() override { out_.finish(); }

private:
    void displace(const Motion& m);  // a move with a surface normal, or the one after it

    MotionSink& out_;
    bool shifted_ = false;  // the last move ended displaced
    Vec3 last_ = Vec3::Zero();
};

}  // namespace toolcomp
