// The TNC's coordinate transformations as one affine map (frame.hpp).
#include "frame.hpp"

#include <cmath>

#include <Eigen/LU>

namespace toolcomp::heidenhain {

Frame::Frame(const Transformations& t) {
    const PlaneAxes ax = axes(t.plane);
    Eigen::Matrix3d mirror = Eigen::Matrix3d::Identity(), rotate = Eigen::Matrix3d::Identity();
    for (int i = 0; i < 3; ++i)
        if (t.mirror[static_cast<std::size_t>(i)]) mirror(i, i) = -1;
    const double a = t.rotation * kPi / 180, c = std::cos(a), s = std::sin(a);
    rotate(ax.a, ax.a) = c, rotate(ax.a, ax.b) = -s;
    rotate(ax.b, ax.a) = s, rotate(ax.b, ax.b) = c;
    if (t.rotation == 0) rotate.setIdentity();  // exact where nothing turns
    const Eigen::Matrix3d outer = mirror * rotate * t.scale;
    const Eigen::Matrix3d k = t.axis_scale.asDiagonal();
    linear_ = outer * k;
    offset_ = t.shift + outer * (t.axis_scale_centre - k * t.axis_scale_centre);
    inverse_ = linear_.inverse();
    linear_identity_ = linear_ == Eigen::Matrix3d::Identity();
    identity_ = linear_identity_ && offset_ == Vec3::Zero();
    flips_ = linear_.determinant() < 0;
    isometric_ = t.scale == 1 && t.axis_scale == Vec3::Ones();
}

bool Frame::conformal_in(Plane p) const {
    const PlaneAxes ax = axes(p);
    const Vec3 u = linear_.col(ax.a), v = linear_.col(ax.b);
    return std::fabs(u.norm() - v.norm()) <= 1e-12 * u.norm() && std::fabs(u.dot(v)) <= 1e-12 * u.squaredNorm();
}

Motion Frame::apply(Motion m) const {
    m.start = point(m.start);
    m.end = point(m.end);
    if (m.is_arc()) m.center = point(m.center);
    if (m.surface.active()) m.surface.normal = vector(m.surface.normal).normalized();
    if (flips_) {
        if (m.kind == MotionKind::arc_cw) m.kind = MotionKind::arc_ccw;
        else if (m.kind == MotionKind::arc_ccw) m.kind = MotionKind::arc_cw;
        m.radius.side = static_cast<std::int8_t>(-m.radius.side);
    }
    return m;
}

}  // namespace toolcomp::heidenhain
