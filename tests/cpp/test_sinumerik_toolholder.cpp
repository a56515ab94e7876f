// Sinumerik toolholder with orientation capability ($TC_CARR) and TRAFO5 equivalence
// (spec §3.6, §3.7).
#include <catch2/catch.hpp>

#include <cmath>

#include "toolcomp/compensation/toolholder.hpp"
#include "toolcomp/program/diagnostic.hpp"

using namespace toolcomp;

namespace {

bool near(const Vec3& a, const Vec3& b, double eps = 1e-9) { return (a - b).norm() < eps; }

// W1 manual head data (spec §3.6 worked example type T).
Toolholder head_t() {
    Toolholder h;
    h.l1 = Vec3(-200, 0, 0);
    h.l3 = Vec3(-100, 0, 0);
    h.v1 = Vec3(1, 0, 0);
    h.v2 = Vec3(-1, 0, 1) / std::sqrt(2.0);
    return h;
}

}  // namespace

TEST_CASE("sinumerik toolholder: Rodrigues rotation follows the right-hand rule", "[sinumerik]") {
    CHECK(near(rotate_about_axis(Vec3(1, 0, 0), Vec3(0, 0, 1), 90), Vec3(0, 1, 0)));
    CHECK(near(rotate_about_axis(Vec3(0, 0, 1), Vec3(0, 2, 0), 90), Vec3(1, 0, 0)));  // axis normalised
    CHECK(near(rotate_about_axis(Vec3(1, 2, 3), Vec3::Zero(), 30), Vec3(1, 2, 3)));  // zero axis
}

TEST_CASE("sinumerik toolholder: type P zero-point offset (W1 manual, A0 B45)", "[sinumerik]") {
    // l4 = (0,0,15), B axis about +Y, 45 deg: right-hand rule turns +Z towards +X, so
    // Rot(Y,45)(0,0,15) = (10.607, 0, 10.607) and the offset is that minus l4:
    // (15 sin45, 0, -15 (1 - cos45)) = (10.607, 0, -4.393) as the manual states.
    Toolholder h;
    h.set_text(23, "P");
    h.l4 = Vec3(0, 0, 15);
    h.v1 = Vec3(0, 1, 0);
    h.alpha1 = 45;
    const Vec3 off = table_zero_offset(h);
    CHECK(off.x() == Approx(10.607).margin(5e-4));
    CHECK(off.y() == Approx(0).margin(1e-12));
    CHECK(off.z() == Approx(-4.393).margin(5e-4));
    // The manual's setting: v1 = A (X axis) at 0, v2 = B (Y axis) at 45 gives the same.
    Toolholder ab = h;
    ab.v1 = Vec3(1, 0, 0);
    ab.v2 = Vec3(0, 1, 0);
    ab.alpha1 = 0;
    ab.alpha2 = 45;
    CHECK(near(table_zero_offset(ab), off));
    // The tool length is not influenced by a type P holder.
    CHECK(near(resulting_tool_length(h, Vec3(0, 0, 250)), Vec3(0, 0, 250)));
}

TEST_CASE("sinumerik toolholder: type T lengths", "[sinumerik]") {
    const Vec3 tool(0, 0, 250);
    Toolholder h = head_t();
    // alpha1 = alpha2 = 0: l1 + l3 + tool = (-300, 0, 250) (spec §3.6).
    CHECK(near(resulting_tool_length(h, tool), Vec3(-300, 0, 250)));
    CHECK(near(table_zero_offset(h), Vec3::Zero()));

    // alpha1 = 90 about +X: inner vector l2 + l3 + tool = (-100, 0, 250); rotating about X by
    // +90 maps (x, y, z) -> (x, -z, y) = (-100, -250, 0); plus l1: (-300, -250, 0).
    h.alpha1 = 90;
    CHECK(near(resulting_tool_length(h, tool), Vec3(-300, -250, 0)));

    // alpha2 = 180 about n = (-1,0,1)/sqrt2: Rot180(x) = 2 n (n.x) - x. For x = (-100, 0, 250):
    // n.x = 350/sqrt2, 2 n (n.x) = (-350, 0, 350), minus x = (-250, 0, 100); plus l1:
    // (-450, 0, 100). (The tool alone (0,0,250) becomes (-250,0,0): the head turns horizontal.)
    h = head_t();
    h.alpha2 = 180;
    CHECK(near(resulting_tool_length(h, tool), Vec3(-450, 0, 100)));
    // The same via $TC_CARR25 (rotary axis offset) instead of the angle [U: offsets add].
    h.alpha2 = 0;
    h.set(25, 180);
    CHECK(near(resulting_tool_length(h, tool), Vec3(-450, 0, 100)));

    // With v1 = v2 = 0 the vectors simply add, whatever the angles.
    Toolholder plain;
    plain.l1 = Vec3(1, 2, 3);
    plain.l2 = Vec3(10, 0, 0);
    plain.l3 = Vec3(0, 5, 0);
    plain.alpha1 = 30;
    plain.alpha2 = 60;
    CHECK(near(resulting_tool_length(plain, tool), Vec3(11, 7, 253)));
}

TEST_CASE("sinumerik toolholder: type M uses l1 and l2 with the head axis", "[sinumerik]") {
    Toolholder h = head_t();
    h.set_text(23, "m");
    h.l2 = Vec3(0, 0, 50);
    h.l4 = Vec3(0, 0, 15);
    h.v2 = Vec3(0, 0, 1);
    // alpha1 = 90 about X: l2 + tool = (0, 0, 300) -> (0, -300, 0); plus l1 (-200, 0, 0).
    // l3 = (-100,0,0) belongs to the table and does not enter.
    h.alpha1 = 90;
    CHECK(near(resulting_tool_length(h, Vec3(0, 0, 250)), Vec3(-200, -300, 0)));
    // Table axis C (about Z) leaves a zero point on the axis where it is.
    h.alpha2 = 30;
    CHECK(near(table_zero_offset(h), Vec3::Zero()));
}

TEST_CASE("sinumerik toolholder: $TC_CARRn setter and alarm 14153", "[sinumerik]") {
    Toolholder h;
    const double values[] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20};
    for (int n = 1; n <= 20; ++n) h.set(n, values[n - 1]);
    CHECK(near(h.l1, Vec3(1, 2, 3)));
    CHECK(near(h.l2, Vec3(4, 5, 6)));
    CHECK(near(h.v1, Vec3(7, 8, 9)));
    CHECK(near(h.v2, Vec3(10, 11, 12)));
    CHECK((h.alpha1 == 13 && h.alpha2 == 14));
    CHECK(near(h.l3, Vec3(15, 16, 17)));
    CHECK(near(h.l4, Vec3(18, 19, 20)));
    h.set(24, 5);
    CHECK(h.angle1() == 18);
    h.set_text(21, "A");
    h.set_text(34, "HEAD1");
    CHECK((h.axis1 == "A" && h.name == "HEAD1"));
    CHECK_THROWS_AS(h.set(23, 1), CompensationError);
    CHECK_THROWS_AS(h.set(41, 1), CompensationError);
    try {
        h.set_text(23, "X");
        FAIL("no error");
    } catch (const CompensationError& e) {
        CHECK(e.code() == "toolholder_bad_kinematic_type");
        CHECK(std::string(e.what()).find("14153") != std::string::npos);
    }
    h.kind = 'Q';
    CHECK_THROWS_WITH(resulting_tool_length(h, Vec3::Zero()), Catch::Contains("14153"));
}

TEST_CASE("sinumerik toolholder: TRAFO5 types 24/56 equal the equivalent toolholder", "[sinumerik]") {
    Trafo5Data t;
    t.base_tool = Vec3(0, 0, 40);
    t.joint_offset = Vec3(-200, 0, 0);
    t.joint_offset_part = Vec3(-100, 0, 0);
    t.part_offset = Vec3(0, 0, 15);
    t.axis1 = Vec3(1, 0, 0);
    t.axis2 = Vec3(-1, 0, 1) / std::sqrt(2.0);
    const Vec3 tool(0, 0, 250);
    for (int type : {24, 56}) {
        t.type = type;
        for (double a1 : {0.0, 30.0, -75.0})
            for (double a2 : {0.0, 45.0, 180.0}) {
                INFO("type " << type << " a1 " << a1 << " a2 " << a2);
                const Toolholder h = to_toolholder(t, a1, a2);
                CHECK(h.kind == (type == 24 ? 'T' : 'M'));
                CHECK(near(resulting_tool_length(h, tool), trafo5_tool_length(t, a1, a2, tool)));
            }
    }
    // Type 24 at zero angles: JOINT_OFFSET + BASE_TOOL + JOINT_OFFSET_PART + tool.
    t.type = 24;
    CHECK(near(trafo5_tool_length(t, 0, 0, tool), Vec3(-300, 0, 290)));
    // JOINT_OFFSET_PART = 0: the old behaviour, JOINT_OFFSET (then l1 + l3) enters unrotated.
    t.type = 56;
    t.joint_offset_part = Vec3::Zero();
    t.joint_offset = Vec3(-300, 0, 0);
    CHECK(near(resulting_tool_length(to_toolholder(t, 90, 0), tool), Vec3(-300, -290, 0)));
    t.type = 40;
    CHECK_THROWS_AS(to_toolholder(t, 0, 0), CompensationError);
}
