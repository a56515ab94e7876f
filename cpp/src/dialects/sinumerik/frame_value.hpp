#pragma once
// The 840D's frames: the matrix form the interpreter maps coordinates with (Frame), and the
// components the control keeps and programs read and write (FrameValue: per geometry axis a
// coarse translation TR, a fine translation FI, a rotation RT, a scale SC and a mirror MI).
// A frame maps coordinates v' in its system to v in the system below it:
// v = R(RT) · S(SC) · M(MI) · v' + (TR + FI), R the RPY rotation (Z, then the new Y, then the
// newest X: MD10600 = 1). `A : B` chains B after A: v'' -> A(B(v'')).
#include <optional>
#include <string_view>

#include <Eigen/Dense>

#include "toolcomp/geometry/vec.hpp"
#include "toolcomp/program/expr.hpp"

namespace toolcomp::sinumerik {

using Mat3 = Eigen::Matrix3d;

Mat3 rotation(int axis, double deg);  // about the geometry axis 0, 1, 2, counter-clockwise

struct Frame {
    Mat3 a = Mat3::Identity();
    Vec3 t = Vec3::Zero();
    Mat3 inv = Mat3::Identity();  // a.inverse(), kept with `a` for each block's invert()
    Vec3 apply(const Vec3& p) const { return a * p + t; }
    Vec3 invert(const Vec3& q) const { return inv * (q - t); }
    // a ROT, SCALE or MIRROR after the frame so far (the only way `a` changes)
    void then(const Mat3& m) {
        a = a * m;
        inv = a.inverse();
    }
    // this frame, then `inner` in its system
    Frame operator*(const Frame& inner) const;
};

enum Component : int { comp_tr, comp_fi, comp_rt, comp_sc, comp_mi };

struct FrameValue {
    Vec3 tr = Vec3::Zero(), fi = Vec3::Zero();
    Vec3 rt = Vec3::Zero();  // degrees
    Vec3 sc = Vec3::Ones();
    Vec3 mi = Vec3::Zero();  // 1: mirrored

    Mat3 rotation() const;
    Mat3 linear() const;  // R S M
    Frame frame() const;
    double& at(int axis, Component c);
    bool turned() const { return rt != Vec3::Zero(); }
    bool diagonal_uniform() const { return sc.x() == sc.y() && sc.y() == sc.z() && mi == Vec3::Zero(); }
};

// A : B, or nothing when the chain is not a frame of components (a scale that differs between
// the axes, or a mirror... followed by a rotation would shear: the control keeps no such frame).
std::optional<FrameValue> chain(const FrameValue& a, const FrameValue& b);

// The 840D's frame variables a program reads and assigns, and how many indices name the
// whole frame ($P_UIFR[n]: 1; $P_PFRAME: 0). -1: not a frame variable.
int frame_indices(std::string_view name);

// In an expression, `$P_UIFR[1, X, TR]` / `$P_PFRAME[Y, RT]`: the axis and component names
// become numbers (0-2, Component) the interpreter reads as a component access.
void rewrite_frame_components(expr::Expr& e);

}  // namespace toolcomp::sinumerik
