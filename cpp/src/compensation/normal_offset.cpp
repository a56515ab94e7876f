#include "toolcomp/compensation/normal_offset.hpp"

#include <cmath>
#include <limits>

namespace toolcomp {

namespace {
Vec3 unit_or_zero(const Vec3& v) {
    const double l = v.norm();
    return l > 1e-15 ? Vec3(v / l) : Vec3(Vec3::Zero());
}
}  // namespace

Vec3 across_axis(const Vec3& n_in, const Vec3& t_in) {
    const Vec3 n = unit_or_zero(n_in), t = unit_or_zero(t_in);
    const Vec3 w = -n + n.dot(t) * t;
    return w.norm() < 1e-12 ? Vec3(Vec3::Zero()) : Vec3(w.normalized());
}

Vec3 delta_3d(const Vec3& n_in, const Vec3& t, double d_r, double d_r2) {
    const Vec3 n = unit_or_zero(n_in);
    return d_r2 * n - (d_r - d_r2) * across_axis(n, t);
}

Vec3 contact_point(const Vec3& pt, const Vec3& n_in, const Vec3& t, double r, double r2) {
    const Vec3 n = unit_or_zero(n_in);
    return pt + (r - r2) * across_axis(n, t) - r2 * n;
}

void compensate_3d(const double* points, const double* normals, const double* tool_axes, std::size_t n, double d_r,
                   double d_r2, double* out) {
    const bool ball_like = d_r == d_r2;  // w does not matter: a displacement along N only
    for (std::size_t i = 0; i < n; ++i) {
        const double* p = points + 3 * i;
        const double* q = normals + 3 * i;
        const double len = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
        double* o = out + 3 * i;
        if (len < 1e-15) {
            o[0] = p[0], o[1] = p[1], o[2] = p[2];
            continue;
        }
        if (ball_like) {
            const double k = d_r2 / len;
            o[0] = p[0] + k * q[0], o[1] = p[1] + k * q[1], o[2] = p[2] + k * q[2];
            continue;
        }
        const Vec3 t = tool_axes ? Vec3(tool_axes[3 * i], tool_axes[3 * i + 1], tool_axes[3 * i + 2]) : Vec3(0, 0, 1);
        const Vec3 d = delta_3d(Vec3(q[0], q[1], q[2]), t, d_r, d_r2);
        o[0] = p[0] + d.x(), o[1] = p[1] + d.y(), o[2] = p[2] + d.z();
    }
}

std::size_t first_bad_row(const double* normals, const double* tool_axes, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) {
        const double* q = normals + 3 * i;
        const double len2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2];
        // Not finite components give a NaN or infinite square (or an overflow to infinity).
        if (!(len2 >= 1e-30 && len2 <= std::numeric_limits<double>::max())) return i;
        if (tool_axes) {
            const double* t = tool_axes + 3 * i;
            const double t2 = t[0] * t[0] + t[1] * t[1] + t[2] * t[2];
            if (!(t2 >= 1e-30 && t2 <= std::numeric_limits<double>::max())) return i;
        }
    }
    return n;
}

}  // namespace toolcomp
