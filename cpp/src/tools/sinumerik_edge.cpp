// Sinumerik cutting-edge totals and the L1/L2/L3 -> axis mapping (spec §3.1, §3.2).
#include "toolcomp/tools/sinumerik_edge.hpp"
#include "toolcomp/program/codes.hpp"

#include <cmath>

#include "toolcomp/program/diagnostic.hpp"

namespace toolcomp::sinumerik {

namespace {

void check_n(int n, const char* what) {
    if (n < 1 || n > 25)
        throw ToolTableError(code::sinumerik_bad_dp, std::string(what) + " number " + std::to_string(n) +
                                                     " is outside 1..25");
}

void bad_setting(const std::string& msg) { throw ToolTableError(code::sinumerik_bad_setting, msg); }

constexpr int X = 0, Y = 1, Z = 2;
using Axes = std::array<int, 3>;

// Rows G17, G18, G19 of the SD42940 tables (spec §3.2).
constexpr Axes kMilling[3] = {{Z, Y, X}, {Y, X, Z}, {X, Z, Y}};
constexpr Axes kTurning[3] = {{Y, X, Z}, {X, Z, Y}, {Z, Y, X}};
// Negative TOOL_LENGTH_CONST -17, -18, -19.
constexpr Axes kMillingNeg[3] = {{Z, X, Y}, {Y, Z, X}, {X, Y, Z}};
constexpr Axes kTurningNeg[3] = {{X, Y, Z}, {Z, X, Y}, {Y, Z, X}};

int plane_row(Plane p) {
    switch (p) {
        case Plane::xy: return 0;
        case Plane::zx: return 1;
        default: return 2;
    }
}

}  // namespace

double SinumerikEdge::DP(int n) const {
    check_n(n, "$TC_DP");
    return dp[static_cast<std::size_t>(n - 1)];
}
double& SinumerikEdge::DP(int n) {
    check_n(n, "$TC_DP");
    return dp[static_cast<std::size_t>(n - 1)];
}
double SinumerikEdge::ECP(int n) const {
    check_n(n, "$TC_ECP");
    return ecp[static_cast<std::size_t>(n - 1)];
}
double SinumerikEdge::SCP(int n) const {
    check_n(n, "$TC_SCP");
    return scp[static_cast<std::size_t>(n - 1)];
}

int SinumerikEdge::type() const { return static_cast<int>(std::lround(DP(1))); }

double SinumerikEdge::length(int i, double wear_sign) const {
    if (i < 1 || i > 3) throw ToolTableError(code::sinumerik_bad_length, "length index must be 1, 2 or 3");
    return DP(2 + i) + wear_sign * (DP(11 + i) + SCP(11 + i) + ECP(11 + i)) + DP(20 + i);
}

double SinumerikEdge::radius(double wear_sign, double offn) const {
    return DP(6) + wear_sign * (DP(15) + SCP(15) + ECP(15)) + offn;
}

bool is_turning_type(int tool_type) { return tool_type >= 400 && tool_type <= 599; }

std::array<int, 3> length_axes(int tool_type, Plane plane, const SinumerikLengthSettings& s) {
    bool turning = false;
    switch (s.tool_length_type) {
        case 0: turning = is_turning_type(tool_type); break;
        case 1: turning = false; break;
        case 2: turning = true; break;
        default: bad_setting("TOOL_LENGTH_TYPE (SD42950) must be 0, 1 or 2");
    }
    const int c = s.tool_length_const;
    if (c == 0) return (turning ? kTurning : kMilling)[plane_row(plane)];
    if (c >= 17 && c <= 19) return (turning ? kTurning : kMilling)[c - 17];
    if (c <= -17 && c >= -19) return (turning ? kTurningNeg : kMillingNeg)[-c - 17];
    bad_setting("TOOL_LENGTH_CONST (SD42940) must be 0, +-17, +-18 or +-19");
    return {};
}

Vec3 place_lengths(const Vec3& l123, int tool_type, Plane plane, const SinumerikLengthSettings& s) {
    const auto ax = length_axes(tool_type, plane, s);
    Vec3 v = Vec3::Zero();
    for (int i = 0; i < 3; ++i) v[ax[static_cast<std::size_t>(i)]] += l123[i];
    return v;
}

Vec3 tool_length_vector(const SinumerikEdge& e, Plane plane, const SinumerikLengthSettings& s) {
    const double w = s.wear_sign();
    return place_lengths(Vec3(e.length(1, w), e.length(2, w), e.length(3, w)), e.type(), plane, s);
}

SinumerikEdge edge_from_common(const CuttingEdge& c) {
    SinumerikEdge e;
    const bool turning = c.orientation != 0;
    e.DP(1) = turning ? 500 : 120;
    e.DP(2) = c.orientation;
    const std::array<int, 3> axis = turning ? std::array<int, 3>{0, 2, 1} : std::array<int, 3>{2, 1, 0};
    for (int i = 0; i < 3; ++i) {
        e.DP(3 + i) = c.length[axis[static_cast<std::size_t>(i)]];
        e.DP(12 + i) = c.length_wear[axis[static_cast<std::size_t>(i)]];
    }
    e.DP(6) = c.radius;
    e.DP(7) = c.corner_radius;
    e.DP(15) = c.radius_wear;
    e.DP(16) = c.corner_radius_wear;
    return e;
}

}  // namespace toolcomp::sinumerik
