#pragma once
// Sinumerik 840D cutting-edge data ($TC_DPn[t,d]) and tool lengths (spec §3.1, §3.2).
//
// Conventions and choices:
// * `dp[n-1]` holds $TC_DPn (n = 1..25). `ecp` / `scp` hold the setup and sum offsets of
//   the one active DL set ($TC_ECPn / $TC_SCPn). Choice [U]: they use the numbering of the
//   wear block of $TC_DP (12-14 lengths, 15 radius, 16-20 the additional values); the other
//   indices are stored and written back but take no part in any computation.
// * Totals: L_i = DP(2+i) + s*(DP(11+i) + SCP(11+i) + ECP(11+i)) + DP(20+i),
//   R = DP6 + s*(DP15 + SCP15 + ECP15) + OFFN, with s = wear sign (+1, or -1 when SD42930
//   WEAR_SIGN is set). Choice [U]: the wear sign also applies to the sum and setup offsets.
// * Vectors are in geometry-axis order (1st, 2nd, 3rd geometry axis = X, Y, Z); the axis
//   order, not the letter, is decisive (spec §3.2).
// * Errors are ToolTableError; settings outside their ranges give "sinumerik_bad_setting".
#include <array>
#include <map>
#include <string>
#include <string_view>
#include <utility>

#include "toolcomp/geometry/vec.hpp"
#include "toolcomp/tools/tool.hpp"

namespace toolcomp::sinumerik {

/// One cutting edge $TC_DPn[t,d] (n = 1..25) with the setup ($TC_ECP) and sum ($TC_SCP) offsets
/// of its active DL set. Values are copies, not references into a table.
struct SinumerikEdge {
    /// writable float64 (25,) view: dp[i] is $TC_DP(i+1)
    std::array<double, 25> dp{};   // $TC_DP1..25
    /// writable float64 (25,) view: ecp[i] is $TC_ECP(i+1) (setup offsets, active DL)
    std::array<double, 25> ecp{};  // $TC_ECP1..25 (setup offsets, active DL)
    /// writable float64 (25,) view: scp[i] is $TC_SCP(i+1) (sum offsets, active DL)
    std::array<double, 25> scp{};  // $TC_SCP1..25 (sum offsets, active DL)
    /// number of the stored DL set
    int dl = 1;                    // number of the stored DL set (for GETTCOR's _DL check)

    // $TC_DPn, n = 1..25; throws ToolTableError("sinumerik_bad_dp") otherwise.
    /// $TC_DPn, n = 1..25
    double DP(int n) const;
    double& DP(int n);
    /// $TC_ECPn, n = 1..25
    double ECP(int n) const;
    /// $TC_SCPn, n = 1..25
    double SCP(int n) const;

    /// DP1 rounded to an integer
    int type() const;
    // Total length L_i, i = 1..3 (adapter DP21..23 included); throws for other i.
    /// total length L_i (i = 1..3): geometry + wear (+ sum/setup offsets) + adapter
    double length(int i, double wear_sign = 1.0) const;
    // Total radius, with an optional OFFN allowance.
    /// total radius DP6 + wear (+ sum/setup offsets) + OFFN
    double radius(double wear_sign = 1.0, double offn = 0.0) const;

    bool operator==(const SinumerikEdge&) const = default;
};

// True for turning and grinding tools (types 400..599); everything else maps like milling.
/// True for turning and grinding tools (types 400..599)
bool is_turning_type(int tool_type);

/// SD42940 TOOL_LENGTH_CONST, SD42950 TOOL_LENGTH_TYPE, SD42930 WEAR_SIGN
struct SinumerikLengthSettings {
    /// SD42940: 0, 17, 18, 19, -17, -18, -19
    int tool_length_const = 0;
    /// SD42950: 0 by tool type, 1 always milling, 2 always turning
    int tool_length_type = 0;
    /// SD42930 WEAR_SIGN != 0
    bool wear_sign_inverted = false;
    /// +1.0, or -1.0 when inverted
    double wear_sign() const { return wear_sign_inverted ? -1.0 : 1.0; }
};

// Geometry-axis index (0 = X, 1 = Y, 2 = Z) on which L1, L2, L3 act (§3.2 tables).
// The plane is toolcomp::Plane: xy = G17, zx = G18, yz = G19.
std::array<int, 3> length_axes(int tool_type, Plane plane, const SinumerikLengthSettings& s = {});

// Places (L1, L2, L3) on the axes; the building block of tool_length_vector and GETTCOR.
Vec3 place_lengths(const Vec3& l123, int tool_type, Plane plane, const SinumerikLengthSettings& s = {});

// The tool length vector (x, y, z) of the edge's total lengths L1..L3.
Vec3 tool_length_vector(const SinumerikEdge& e, Plane plane, const SinumerikLengthSettings& s = {});

// ---- the common tool model ---------------------------------------------------------------
// A cutting edge of the common model (tool-length vector X Y Z, radius, wear) as $TC_DP data,
// the way a Sinumerik stores the same tool: a milling tool (tip orientation 0) becomes type
// 120 with L1 = Z, L2 = Y, L3 = X (so that G17 gives the vector back); a lathe tool (tip
// 1..9) becomes type 500 with DP2 = tip and L1 = X, L2 = Z, L3 = Y (G18 gives it back).
// Radius DP6, corner radius DP7, wear DP12..DP16 likewise.
SinumerikEdge edge_from_common(const CuttingEdge& e);

// ---- initialisation-file form: "$TC_DPn[t,d]=value" ---------------------------------------
// One assignment per line; $TC_ECPn and $TC_SCPn are read the same way. Tolerated: blank
// lines, ';' comments, a leading block number "N<digits>", names in any case, blanks around
// the tokens, and lines consisting of M17/M30/M02 only. Errors (ToolTableError, 1-based line,
// column of the offending token): "sinumerik_bad_line", "sinumerik_bad_dp" (n outside
// 1..25), "sinumerik_bad_tool" (t outside 1..max_t), "sinumerik_bad_edge" (d outside
// 1..max_d). Choice [U]: limits default to 32000 (flat D numbers range).
using EdgeKey = std::pair<int, int>;  // (t, d)
using SinumerikEdgeMap = std::map<EdgeKey, SinumerikEdge>;

SinumerikEdgeMap parse_tc_dp(std::string_view text, int max_t = 32000, int max_d = 32000);

// The same form back, ordered by (t, d): DP1 always, other DP/ECP/SCP values when non-zero,
// shortest round-trip numbers. parse_tc_dp(write_tc_dp(m)) == m (the `dl` field excepted).
/// {(t, d): Edge} back to '$TC_DPn[t,d]=value' lines, ordered by (t, d)
std::string write_tc_dp(const SinumerikEdgeMap& edges);

}  // namespace toolcomp::sinumerik
