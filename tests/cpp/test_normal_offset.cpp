// 3D compensation along surface normals: spec §1.9 numbers and an independent check of the
// toroid case (the contact point of nominal and actual tool found on the torus numerically).
#include <catch2/catch.hpp>
#include <cmath>

#include <Eigen/Geometry>

#include "toolcomp/compensation/normal_offset.hpp"

using namespace toolcomp;

TEST_CASE("ball cutter: displaced along the normal by the deltas (spec 1.9 example)", "[3d]") {
    const Vec3 n(0.2637581, 0.0078922, -0.8764339);  // |N| = 0.9153: normalised inside
    const Vec3 d = delta_3d(n, Vec3(0, 0, 1), -0.1, -0.1);
    CHECK(d.x() == Approx(-0.02882).margin(1e-5));
    CHECK(d.y() == Approx(-0.00086).margin(1e-5));
    CHECK(d.z() == Approx(0.09575).margin(1e-5));
}

TEST_CASE("flat end mill: face milling and periphery", "[3d]") {
    // Face (N along T): w = 0, only DR2 acts, so nothing for R2 = 0 and DR2 = 0.
    CHECK(delta_3d(Vec3(0, 0, 1), Vec3(0, 0, 1), -0.2, 0).norm() < 1e-15);
    // Periphery (N across T): w = -N, ΔPT = ΔR·N: an undersize tool moves towards the surface.
    const Vec3 d = delta_3d(Vec3(1, 0, 0), Vec3(0, 0, 1), -0.2, 0);
    CHECK(d.isApprox(Vec3(-0.2, 0, 0)));
}

namespace {
// The point of a torus (axis T through datum PT, ring radius a, tube radius rho) farthest in
// direction -N: where the tool touches a surface with normal N. On each tube circle that
// point is the ring point minus rho·N; the ring angle is found by search, independently of
// the formula under test.
Vec3 touch(const Vec3& pt, const Vec3& t, double a, double rho, const Vec3& n) {
    const Vec3 e1 = t.unitOrthogonal(), e2 = t.cross(e1);
    auto point = [&](double phi) { return Vec3(pt + a * (std::cos(phi) * e1 + std::sin(phi) * e2) - rho * n); };
    auto depth = [&](double phi) { return -n.dot(point(phi)); };
    const int k = 3600;
    double best = 0;
    for (int i = 0; i < k; ++i)
        if (depth(2 * kPi * i / k) > depth(best)) best = 2 * kPi * i / k;
    double lo = best - 2 * kPi / k, hi = best + 2 * kPi / k;  // then golden-section refinement
    for (int i = 0; i < 200; ++i) {
        const double m1 = lo + (hi - lo) * 0.381966, m2 = lo + (hi - lo) * 0.618034;
        if (depth(m1) < depth(m2)) lo = m1; else hi = m2;
    }
    return point(0.5 * (lo + hi));
}
}  // namespace

TEST_CASE("toroid: nominal and compensated actual tool touch the surface at the same point", "[3d]") {
    const Vec3 n = Vec3(0.3, -0.2, 0.9).normalized(), t(0, 0, 1), pt(10, 20, 5);
    const double R = 6, R2 = 2, dR = -0.15, dR2 = -0.05;
    const Vec3 nominal = touch(pt, t, R - R2, R2, n);
    const Vec3 moved = pt + delta_3d(n, t, dR, dR2);
    const Vec3 actual = touch(moved, t, (R + dR) - (R2 + dR2), R2 + dR2, n);
    CHECK((nominal - actual).norm() < 1e-6);
    CHECK((contact_point(pt, n, t, R, R2) - nominal).norm() < 1e-6);
}

TEST_CASE("batch form equals the single-point form", "[3d]") {
    const double pts[6] = {1, 2, 3, -4, 5, 6};
    const double nrm[6] = {0, 0, 2, 1, 1, 0};
    const double axs[6] = {0, 0, 1, 0, 0, 1};
    double out[6];
    compensate_3d(pts, nrm, axs, 2, -0.3, -0.1, out);
    for (int i = 0; i < 2; ++i) {
        const Vec3 e = Vec3(pts[3 * i], pts[3 * i + 1], pts[3 * i + 2]) +
                       delta_3d(Vec3(nrm[3 * i], nrm[3 * i + 1], nrm[3 * i + 2]), Vec3(0, 0, 1), -0.3, -0.1);
        CHECK(Vec3(out[3 * i], out[3 * i + 1], out[3 * i + 2]).isApprox(e));
    }
}
