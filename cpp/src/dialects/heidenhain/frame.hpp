#pragma once
// The TNC's coordinate transformations (CYCL DEF 7 DATUM SHIFT, 8 MIRROR IMAGE, 10 ROTATION,
// 11 SCALING, 26 AXIS-SPECIFIC SCALING): independent values, composed in a fixed order
// whatever order they were defined in. A program point P is, from the preset,
//
//     shift + Mirror( Rotate( Scale11( Scale26(P) ) ) )
//
// with the rotation about the tool axis in the working plane (counter-clockwise from the
// plane's first axis), the mirror in the axes named, scaling 11 about the datum in all three
// axes and scaling 26 about its centre CCX/CCY/CCZ. The interpreter works in program
// coordinates; FrameSink hands the moves on from the preset, so that radius compensation
// offsets the transformed contour by the tool's own radius (an odd mirror turns arcs and
// swaps RL/RR, as on the TNC).
#include <array>

#include <Eigen/Core>

#include "toolcomp/geometry/vec.hpp"
#include "toolcomp/motion/motion.hpp"

namespace toolcomp::heidenhain {

struct Transformations {
    Vec3 shift = Vec3::Zero();                // cycle 7
    std::array<bool, 3> mirror{};             // cycle 8: X, Y, Z
    double rotation = 0;                      // cycle 10, degrees
    double scale = 1;                         // cycle 11
    Vec3 axis_scale = Vec3::Ones();           // cycle 26
    Vec3 axis_scale_centre = Vec3::Zero();    // cycle 26: CCX, CCY, CCZ
    Plane plane = Plane::xy;                  // the working plane the rotation turns in

    bool operator==(const Transformations&) const = default;
};

class Frame {
public:
    Frame() = default;
    explicit Frame(const Transformations& t);
    bool identity() const { return identity_; }
    bool shift_only() const { return linear_identity_; }
    bool flips() const { return flips_; }                 // an odd number of mirrored axes
    bool isometric() const { return isometric_; }         // no scaling
    bool conformal_in(Plane p) const;                     // arcs in plane p stay circles
    Vec3 point(const Vec3& p) const { return linear_ * p + offset_; }       // program -> preset
    Vec3 to_program(const Vec3& p) const { return inverse_ * (p - offset_); }
    Vec3 vector(const Vec3& v) const { return linear_ * v; }
    Vec3 vector_to_program(const Vec3& v) const { return inverse_ * v; }
    Motion apply(Motion m) const;

private:
    Eigen::Matrix3d linear_ = Eigen::Matrix3d::Identity(), inverse_ = Eigen::Matrix3d::Identity();
    Vec3 offset_ = Vec3::Zero();
    bool identity_ = true, linear_identity_ = true, flips_ = false, isometric_ = true;
};

// Hands the interpreter's moves on, taken from program coordinates to the preset's.
class FrameSink : public MotionSink {
public:
    explicit FrameSink(MotionSink& out) : out_(out) {}
    void set(const Frame& f) { frame_ = f; }
    const Frame& frame() const { return frame_; }
    void push(const Motion& m) override { out_.push(frame_.identity() ? m : frame_.apply(m)); }
    void control(const ControlEvent& e) override { out_.control(e); }
    void finish() override { out_.finish(); }

private:
    MotionSink& out_;
    Frame frame_;
};

}  // namespace toolcomp::heidenhain
