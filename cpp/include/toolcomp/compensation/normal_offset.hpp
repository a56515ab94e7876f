#pragma once
// 3D tool compensation along surface normals (spec §1.9, Heidenhain LN blocks).
//
// A tool of radius R and corner radius R2 (R2 = 0 end mill, R2 = R ball, between: toroid)
// whose datum PT (the point on the axis R2 above the tip) was placed by CAM for the nominal
// tool touches the surface at Cc = PT + a·w − R2·N, with a = R − R2, N the unit surface normal
// (from the surface towards the tool), T the unit tool axis and w = normalize(−N + (N·T)·T)
// (the direction of −N across the axis; zero when N is along T). Replacing the tool by one
// with R + ΔR, R2 + ΔR2 and keeping the contact point moves the datum by
//     ΔPT = ΔR2·N − (ΔR − ΔR2)·w
// which for a ball (ΔR = ΔR2) is ΔR2·N: "displace along the normal by the sum of the deltas".
#include <cstddef>

#include "toolcomp/geometry/vec.hpp"

namespace toolcomp {

// w of the formula above (N and T need not be unit length; a zero N gives zero).
Vec3 across_axis(const Vec3& n, const Vec3& t);
Vec3 delta_3d(const Vec3& n, const Vec3& t, double d_r, double d_r2);
Vec3 contact_point(const Vec3& pt, const Vec3& n, const Vec3& t, double r, double r2);

// Batch form for CAM data: points, normals (and tool axes, or nullptr for +Z) as n rows of
// three doubles; out may alias points. Normals are normalised; a zero normal leaves the point
// (callers refuse such data first: first_bad_row).
void compensate_3d(const double* points, const double* normals, const double* tool_axes, std::size_t n, double d_r,
                   double d_r2, double* out);
// The first row whose normal or tool axis is not a direction (a component not finite, or of
// zero length); n when every row is good.
std::size_t first_bad_row(const double* normals, const double* tool_axes, std::size_t n);

}  // namespace toolcomp
