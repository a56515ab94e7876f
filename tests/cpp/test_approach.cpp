// Heidenhain APPR / DEP geometry (spec §2.5): worked examples of §2.5.4, the R0 rule, the
// option alternatives, errors and a randomized consistency property.
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <random>
#include <string>

#include "toolcomp/compensation/approach.hpp"
#include "toolcomp/program/diagnostic.hpp"

using namespace toolcomp;

namespace {

constexpr double kEps = 1e-3;  // the spec prints 3 decimals

bool near(const Vec2& a, double x, double y, double eps = kEps) {
    return std::fabs(a.x() - x) <= eps && std::fabs(a.y() - y) <= eps;
}
#define CHECK_PT(PT_, X_, Y_)                                               \
    do {                                                                    \
        const Vec2 pt_ = (PT_);                                             \
        INFO(#PT_ " = (" << pt_.x() << ", " << pt_.y() << ")");             \
        CHECK(near(pt_, (X_), (Y_)));                                       \
    } while (0)

double deg(double rad) { return rad * 180.0 / kPi; }

// Manual examples: PS = (40,10), r = 5, RR.
const Vec2 kPS{40, 10};
const Vec2 kPA{10, 20};
const Vec2 kTA = Vec2(10, 15).normalized();  // next block L X+20 Y+35

Approach appr(ApproachKind k, Vec2 pa, Vec2 t) {
    Approach a;
    a.kind = k;
    a.ps = kPS;
    a.pa = pa;
    a.t_a = t;
    a.side = -1;
    a.r = 5;
    return a;
}

Departure dep(ApproachKind k) {
    Departure d;
    d.kind = k;
    d.pe = {10, 20};
    d.t_e = {0, 1};  // last element L X+10 Y+20 from (10,0)
    d.side = -1;
    d.r = 5;
    return d;
}

std::string error_code(const std::function<void()>& f, std::string* msg = nullptr) {
    try {
        f();
    } catch (const CompensationError& e) {
        if (msg) *msg = e.what();
        CHECK(e.line() == 0);
        return e.code();
    }
    return "";
}

Vec2 start_tangent(const PathPiece& p) {
    if (p.arc) return p.dir * left_normal(p.start - p.centre).normalized();
    return (p.end - p.start).normalized();
}
Vec2 end_tangent(const PathPiece& p) {
    if (p.arc) return p.dir * left_normal(p.end - p.centre).normalized();
    return (p.end - p.start).normalized();
}

}  // namespace

TEST_CASE("APPR LT worked example", "[approach]") {
    auto a = appr(ApproachKind::LT, {20, 20}, Vec2(1, 1).normalized());
    a.len = 15;
    auto p = approach_path(a);
    REQUIRE(p.size() == 2);
    CHECK_FALSE(p[0].arc);
    CHECK_FALSE(p[1].arc);
    CHECK_PT(p[0].start, 40, 10);
    CHECK_PT(p[0].end, 12.929, 5.858);
    CHECK_PT(p[1].start, 12.929, 5.858);
    CHECK_PT(p[1].end, 23.536, 16.464);
    CHECK(p[1].tangent_out);
    CHECK(p[1].length() == Approx(15));
}

TEST_CASE("APPR LN worked example", "[approach]") {
    auto a = appr(ApproachKind::LN, kPA, kTA);
    a.len = 15;
    auto p = approach_path(a);
    REQUIRE(p.size() == 2);
    CHECK_PT(p[0].end, 26.641, 8.906);
    CHECK_PT(p[1].end, 14.160, 17.226);
    CHECK(p[1].length() == Approx(15));  // the tool travels exactly LEN on the normal
    CHECK(std::fabs(end_tangent(p[1]).dot(kTA)) < 1e-12);
    CHECK_FALSE(p[1].tangent_out);
}

TEST_CASE("APPR CT worked example", "[approach]") {
    auto a = appr(ApproachKind::CT, kPA, kTA);
    a.cca = 180;
    a.radius = 10;
    auto p = approach_path(a);
    REQUIRE(p.size() == 2);
    CHECK_FALSE(p[0].arc);
    REQUIRE(p[1].arc);
    CHECK_PT(p[0].end, 22.481, 11.679);
    CHECK_PT(p[1].centre, 18.321, 14.453);
    CHECK_PT(p[1].end, 14.160, 17.226);
    CHECK(p[1].dir == -1);  // RR, R > 0: CW
    CHECK(p[1].radius() == Approx(5));
    CHECK(deg(p[1].sweep) == Approx(180));
    CHECK(p[1].tangent_out);
}

TEST_CASE("APPR LCT worked example, tool-space tangency and the contour-space alternative", "[approach]") {
    auto a = appr(ApproachKind::LCT, kPA, kTA);
    a.radius = 10;
    auto p = approach_path(a);
    REQUIRE(p.size() == 2);
    REQUIRE(p[1].arc);
    CHECK_PT(p[0].end, 18.447, 9.455);
    CHECK(p[0].length() == Approx(21.560).margin(kEps));
    CHECK(p[1].dir == -1);
    CHECK(deg(p[1].sweep) == Approx(125.14).margin(0.01));
    CHECK_PT(p[1].end, 14.160, 17.226);
    CHECK_PT(p[1].centre, 18.321, 14.453);
    CHECK(p[1].radius() == Approx(5));
    CHECK(p[0].tangent_out);
    CHECK(p[1].tangent_in);
    CHECK((end_tangent(p[0]) - start_tangent(p[1])).norm() < 1e-9);

    ApproachOptions o;
    o.lct_tangency_tool_space = false;
    auto q = approach_path(a, o);
    REQUIRE(q.size() == 2);
    CHECK_PT(q[0].end, 19.636, 9.629);
    CHECK_PT(q[1].end, 14.160, 17.226);
    CHECK(q[1].radius() == Approx(5));
    CHECK_FALSE(q[0].tangent_out);
    CHECK_FALSE(q[1].tangent_in);
    // the line PS -> PH_contour (20.952, 4.805) is tangent to the contour circle
    const Vec2 c = q[1].centre;
    const Vec2 ph_c = c + (q[0].end - c) * 2.0;  // contour radius 10 = 2 x tool radius 5
    CHECK_PT(ph_c, 20.952, 4.805);
    CHECK(std::fabs((ph_c - kPS).dot(ph_c - c)) < 1e-9);
}

TEST_CASE("DEP worked examples", "[approach]") {
    SECTION("LT") {
        auto d = dep(ApproachKind::LT);
        d.len = 12.5;
        auto p = departure_path(d);
        REQUIRE(p.size() == 1);
        CHECK_PT(p[0].start, 15, 20);
        CHECK_PT(p[0].end, 15, 32.5);
        CHECK(p[0].tangent_in);
    }
    SECTION("LN") {
        auto d = dep(ApproachKind::LN);
        d.len = 20;
        auto p = departure_path(d);
        REQUIRE(p.size() == 1);
        CHECK_PT(p[0].start, 15, 20);
        CHECK_PT(p[0].end, 35, 20);
        CHECK_FALSE(p[0].tangent_in);
    }
    SECTION("CT") {
        auto d = dep(ApproachKind::CT);
        d.cca = 180;
        d.radius = 8;
        auto p = departure_path(d);
        REQUIRE(p.size() == 1);
        REQUIRE(p[0].arc);
        CHECK_PT(p[0].start, 15, 20);
        CHECK_PT(p[0].centre, 18, 20);
        CHECK_PT(p[0].end, 21, 20);
        CHECK(p[0].dir == -1);
        CHECK(p[0].radius() == Approx(3));
        CHECK(p[0].tangent_in);
        CHECK((start_tangent(p[0]) - Vec2(0, 1)).norm() < 1e-12);
    }
    SECTION("LCT") {
        auto d = dep(ApproachKind::LCT);
        d.radius = 8;
        d.pn = {40, 40};
        auto p = departure_path(d);
        REQUIRE(p.size() == 2);
        REQUIRE(p[0].arc);
        CHECK_PT(p[0].start, 15, 20);
        CHECK_PT(p[0].centre, 18, 20);
        CHECK_PT(p[0].end, 16.216, 22.412);
        CHECK(p[0].dir == -1);
        CHECK(deg(p[0].sweep) == Approx(53.52).margin(0.01));
        CHECK_FALSE(p[1].arc);
        CHECK_PT(p[1].end, 40, 40);
        CHECK(p[1].length() == Approx(29.580).margin(kEps));
        CHECK(p[0].tangent_out);
        CHECK((end_tangent(p[0]) - start_tangent(p[1])).norm() < 1e-9);
    }
}

TEST_CASE("APPR with R0: tool radius 0 and RR", "[approach]") {
    // The caller maps R0 to side -1 (RR) and r = 0: the path runs on the contour.
    auto a = appr(ApproachKind::LN, kPA, kTA);
    a.r = 0;
    a.len = 15;
    auto p = approach_path(a);
    CHECK_PT(p[0].end, 10 + 15 * 0.83205, 20 - 15 * 0.55470);
    CHECK_PT(p[1].end, 10, 20);

    a = appr(ApproachKind::CT, kPA, kTA);
    a.r = 0;
    a.cca = 180;
    a.radius = 10;
    p = approach_path(a);
    CHECK_PT(p[0].end, 26.641, 8.906);  // PH_contour
    CHECK_PT(p[1].end, 10, 20);
    CHECK(p[1].dir == -1);
    CHECK(p[1].radius() == Approx(10));

    // LCT: with r = 0 both tangency readings coincide and stay smooth.
    a = appr(ApproachKind::LCT, kPA, kTA);
    a.r = 0;
    a.radius = 10;
    ApproachOptions contour;
    contour.lct_tangency_tool_space = false;
    auto q1 = approach_path(a), q2 = approach_path(a, contour);
    CHECK_PT(q1[0].end, 20.952, 4.805);
    CHECK((q1[0].end - q2[0].end).norm() < 1e-12);
    CHECK(q2[0].tangent_out);
}

TEST_CASE("CT/LCT radius read as the tool-centre radius (alternative option)", "[approach]") {
    ApproachOptions o;
    o.ct_radius_on_contour = false;
    auto a = appr(ApproachKind::CT, kPA, kTA);
    a.cca = 180;
    a.radius = 10;
    auto p = approach_path(a, o);
    CHECK_PT(p[1].centre, 22.481, 11.679);  // PA_tool + 10 n_s
    CHECK(p[1].radius() == Approx(10));
    CHECK_PT(p[0].end, 30.801, 6.132);
    CHECK_PT(p[1].end, 14.160, 17.226);

    // R smaller than r is accepted: R is the tool arc itself.
    a.radius = 2;
    p = approach_path(a, o);
    CHECK(p[1].radius() == Approx(2));
    CHECK(error_code([&] { approach_path(a); }) == "tool_radius_too_large");

    a = appr(ApproachKind::LCT, kPA, kTA);
    a.radius = 10;
    p = approach_path(a, o);
    CHECK_PT(p[0].end, 27.352, 2.946);
    CHECK(p[0].length() == Approx(14.483).margin(kEps));
    CHECK(p[1].dir == -1);
    CHECK(p[1].radius() == Approx(10));

    auto d = dep(ApproachKind::CT);
    d.cca = 180;
    d.radius = 8;
    auto q = departure_path(d, o);
    CHECK_PT(q[0].centre, 23, 20);
    CHECK_PT(q[0].end, 31, 20);
}

TEST_CASE("CT arc direction table and negative R", "[approach]") {
    // Straight contour along +X from PA = (0,0); r = 1; CCA 90; |R| = 4.
    for (int side : {1, -1}) {
        for (double R : {4.0, -4.0}) {
            Approach a;
            a.kind = ApproachKind::CT;
            a.ps = {-20, 0};
            a.pa = {0, 0};
            a.t_a = {1, 0};
            a.side = side;
            a.r = 1;
            a.cca = 90;
            a.radius = R;
            auto p = approach_path(a);
            const int expect = (side == 1) == (R > 0) ? 1 : -1;  // RL&R>0 CCW, RR&R<0 CCW
            INFO("side " << side << " R " << R);
            CHECK(p[1].dir == expect);
            CHECK(p[1].radius() == Approx(R > 0 ? 3 : 5));
            CHECK_PT(p[1].centre, 0, side * R);
            CHECK_PT(p[1].end, 0, side * 1.0);
            // PH lies a quarter turn back: behind PA, at the height of the centre
            CHECK_PT(p[0].end, -(R > 0 ? 3 : 5), side * R);
            CHECK((end_tangent(p[1]) - Vec2(1, 0)).norm() < 1e-12);
        }
    }
}

TEST_CASE("CCA 360 is a full circle", "[approach]") {
    auto a = appr(ApproachKind::CT, kPA, kTA);
    a.cca = 360;
    a.radius = 10;
    auto p = approach_path(a);
    CHECK((p[0].end - p[1].end).norm() < 1e-9);
    CHECK(p[1].sweep == Approx(2 * kPi));
}

TEST_CASE("APPR/DEP errors", "[approach]") {
    std::string msg;
    auto ct = appr(ApproachKind::CT, kPA, kTA);
    ct.cca = 90;
    ct.radius = 5;  // R - r = 0
    CHECK(error_code([&] { approach_path(ct); }, &msg) == "tool_radius_too_large");
    CHECK(msg == "TOOL RADIUS TOO LARGE");
    ct.radius = 4;
    CHECK(error_code([&] { approach_path(ct); }) == "tool_radius_too_large");
    ct.radius = -4;  // |R| + r: fine
    CHECK(error_code([&] { approach_path(ct); }) == "");
    ct.radius = 0;
    CHECK(error_code([&] { approach_path(ct); }) == "approach_radius_zero");
    ct.radius = 10;
    for (double cca : {0.0, -10.0, 360.5, std::nan("")}) {
        ct.cca = cca;
        CHECK(error_code([&] { approach_path(ct); }) == "approach_cca_out_of_range");
    }

    auto dct = dep(ApproachKind::CT);
    dct.cca = 90;
    dct.radius = 3;
    CHECK(error_code([&] { departure_path(dct); }, &msg) == "tool_radius_too_large");
    CHECK(msg == "TOOL RADIUS TOO LARGE");
    dct.cca = 400;
    dct.radius = 8;
    CHECK(error_code([&] { departure_path(dct); }) == "approach_cca_out_of_range");

    for (auto k : {ApproachKind::LT, ApproachKind::LN}) {
        for (double len : {0.0, -15.0}) {
            auto a = appr(k, kPA, kTA);
            a.len = len;
            CHECK(error_code([&] { approach_path(a); }) == "approach_len_not_positive");
            auto d = dep(k);
            d.len = len;
            CHECK(error_code([&] { departure_path(d); }) == "approach_len_not_positive");
        }
    }

    auto lct = appr(ApproachKind::LCT, kPA, kTA);
    for (double R : {0.0, -10.0}) {
        lct.radius = R;
        CHECK(error_code([&] { approach_path(lct); }) == "approach_lct_radius_not_positive");
    }
    lct.radius = 5;
    CHECK(error_code([&] { approach_path(lct); }) == "tool_radius_too_large");
    lct.radius = 10;
    lct.ps = {18, 14};  // inside the tool circle about (18.321, 14.453), radius 5
    CHECK(error_code([&] { approach_path(lct); }) == "approach_start_inside_circle");
    // between the tool circle (5) and the contour circle (10): only tool-space tangency exists
    lct.ps = Vec2(18.321, 14.453) + Vec2(7, 0);
    CHECK(error_code([&] { approach_path(lct); }) == "");
    ApproachOptions contour;
    contour.lct_tangency_tool_space = false;
    CHECK(error_code([&] { approach_path(lct, contour); }) == "approach_start_inside_circle");

    auto dl = dep(ApproachKind::LCT);
    dl.radius = 8;
    dl.pn = {19, 21};
    CHECK(error_code([&] { departure_path(dl); }) == "departure_end_inside_circle");
    dl.radius = -8;
    CHECK(error_code([&] { departure_path(dl); }) == "approach_lct_radius_not_positive");

    auto bad = appr(ApproachKind::LT, kPA, kTA);
    bad.len = 10;
    bad.side = 0;
    CHECK(error_code([&] { approach_path(bad); }) == "approach_bad_side");
    bad.side = 1;
    bad.r = -1;
    CHECK(error_code([&] { approach_path(bad); }) == "approach_bad_tool_radius");
    bad.r = 1;
    bad.t_a = Vec2::Zero();
    CHECK(error_code([&] { approach_path(bad); }) == "approach_no_tangent");
}

TEST_CASE("APPR/DEP paths are consistent: chained, on their circles, tangent where flagged", "[approach]") {
    std::mt19937 rng(20240517);
    std::uniform_real_distribution<double> u(0, 1);
    auto chk_pt = [](const Vec2& a, const Vec2& b) { return (a - b).norm() < 1e-8; };
    auto chk_dir = [](const Vec2& a, const Vec2& b) { return (a - b).norm() < 1e-8; };
    int checked = 0, tangencies = 0;
    for (int iter = 0; iter < 4000; ++iter) {
        const auto kind = static_cast<ApproachKind>(iter % 4);
        const int side = u(rng) < 0.5 ? 1 : -1;
        const double r = u(rng) < 0.2 ? 0.0 : 5 * u(rng);
        ApproachOptions o;
        o.ct_radius_on_contour = u(rng) < 0.7;
        o.lct_tangency_tool_space = u(rng) < 0.7;
        const double ang = 2 * kPi * u(rng);
        const Vec2 t(std::cos(ang), std::sin(ang));
        const Vec2 p(100 * u(rng) - 50, 100 * u(rng) - 50);
        const Vec2 far(200 * u(rng) - 100, 200 * u(rng) - 100);
        double R = r + 0.5 + 20 * u(rng);
        if (kind == ApproachKind::CT && u(rng) < 0.4) R = -R;
        const double len = 0.1 + 20 * u(rng), cca = 0.5 + 359.5 * u(rng);
        const Vec2 n = side * left_normal(t);
        INFO("iter " << iter);

        std::vector<PathPiece> path;
        Vec2 first_start, t_in = Vec2::Zero(), t_out = Vec2::Zero();
        bool is_appr = iter % 8 < 4;
        try {
            if (is_appr) {
                Approach a{kind, far, p, t, side, r, len, cca, R};
                path = approach_path(a, o);
                first_start = far;
                t_out = t;
                REQUIRE(path.size() == 2);
                CHECK(chk_pt(path.back().end, p + r * n));
            } else {
                Departure d{kind, p, t, side, r, len, cca, R, far};
                path = departure_path(d, o);
                first_start = p + r * n;
                t_in = t;
                REQUIRE(path.size() == (kind == ApproachKind::LCT ? 2u : 1u));
                if (kind == ApproachKind::LCT) CHECK(chk_pt(path.back().end, far));
            }
        } catch (const CompensationError& e) {
            CHECK((kind == ApproachKind::LCT &&
                   (e.code() == "approach_start_inside_circle" || e.code() == "departure_end_inside_circle")));
            continue;
        }
        ++checked;
        CHECK(chk_pt(path.front().start, first_start));
        for (std::size_t i = 0; i < path.size(); ++i) {
            const auto& pc = path[i];
            if (i > 0) CHECK(chk_pt(pc.start, path[i - 1].end));
            if (pc.arc) {
                const double rho = pc.radius();
                CHECK(rho > 0);
                CHECK(std::fabs((pc.end - pc.centre).norm() - rho) < 1e-8);
                CHECK((pc.dir == 1 || pc.dir == -1));
                CHECK(pc.sweep >= 0);
                CHECK(pc.sweep <= 2 * kPi + 1e-12);
                // the end is the start swept by `sweep` in direction `dir`
                const double a0 = std::atan2(pc.start.y() - pc.centre.y(), pc.start.x() - pc.centre.x());
                const double a1 = a0 + pc.dir * pc.sweep;
                CHECK(chk_pt(pc.end, pc.centre + rho * Vec2(std::cos(a1), std::sin(a1))));
                // CT/LCT: tool arc radius by the options
                double expect = o.ct_radius_on_contour ? (R > 0 ? R - r : -R + r) : std::fabs(R);
                CHECK(rho == Approx(expect));
                CHECK(pc.dir == (R > 0 ? side : -side));
            }
            const bool degenerate = pc.length() < 1e-9;
            if (pc.tangent_out && !degenerate) {
                if (i + 1 < path.size()) {
                    if (path[i + 1].length() >= 1e-9) {
                        CHECK(chk_dir(end_tangent(pc), start_tangent(path[i + 1])));
                        ++tangencies;
                    }
                } else {
                    CHECK(is_appr);
                    CHECK(chk_dir(end_tangent(pc), t_out));
                    ++tangencies;
                }
            }
            if (pc.tangent_in && !degenerate) {
                if (i > 0) {
                    CHECK(path[i - 1].tangent_out);
                } else {
                    CHECK_FALSE(is_appr);
                    CHECK(chk_dir(start_tangent(pc), t_in));
                    ++tangencies;
                }
            }
        }
        // LT/CT/LCT join the contour tangentially, LN perpendicularly.
        if (is_appr) {
            CHECK(path.back().tangent_out == (kind != ApproachKind::LN));
            if (kind == ApproachKind::LN) CHECK(std::fabs(end_tangent(path.back()).dot(t)) < 1e-9);
            if (kind == ApproachKind::LCT)
                CHECK(path[0].tangent_out == (o.lct_tangency_tool_space || r == 0));
        } else {
            CHECK(path.front().tangent_in == (kind != ApproachKind::LN));
            if (kind == ApproachKind::LN) CHECK(std::fabs(start_tangent(path.front()).dot(t)) < 1e-9);
        }
    }
    CHECK(checked > 3000);
    CHECK(tangencies > 3000);
}
