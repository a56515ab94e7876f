#pragma once
// Vectors, working planes and tolerances.
#include <Eigen/Core>
#include <cstdint>

namespace toolcomp {

using Vec3 = Eigen::Vector3d;
using Vec2 = Eigen::Vector2d;

// Working plane. In plane coordinates (a, b) with applicate c (spec §0.1):
// XY: a=X b=Y c=Z;  ZX: a=Z b=X c=Y;  YZ: a=Y b=Z c=X. CW/CCW are seen from +c.
enum class Plane : std::uint8_t { xy = 0, zx = 1, yz = 2 };

struct PlaneAxes {
    int a, b, c;  // indices into (X, Y, Z)
};
constexpr PlaneAxes axes(Plane p) {
    switch (p) {
        case Plane::zx: return {2, 0, 1};
        case Plane::yz: return {1, 2, 0};
        default: return {0, 1, 2};
    }
}
// A point's plane coordinates (a, b), and the point with them replaced (c kept). Written out
// per plane: an element picked by a run-time index goes through memory (a store, then a
// vector load that waits for it), on every move of the radius stage.
inline Vec2 in_plane(const Vec3& v, Plane p) {
    switch (p) {
        case Plane::zx: return {v.z(), v.x()};
        case Plane::yz: return {v.y(), v.z()};
        default: return {v.x(), v.y()};
    }
}
inline Vec3 with_plane(const Vec3& v, const Vec2& ab, Plane p) {
    switch (p) {
        case Plane::zx: return {ab.y(), v.y(), ab.x()};
        case Plane::yz: return {v.x(), ab.x(), ab.y()};
        default: return {ab.x(), ab.y(), v.z()};
    }
}

inline double cross2(const Vec2& u, const Vec2& v) { return u.x() * v.y() - u.y() * v.x(); }
inline Vec2 left_normal(const Vec2& t) { return {-t.y(), t.x()}; }

namespace tol {
constexpr double length = 1e-9;  // mm: points closer than this are the same point
}

constexpr double kPi = 3.14159265358979323846;
constexpr double kMmPerInch = 25.4;

}  // namespace toolcomp
