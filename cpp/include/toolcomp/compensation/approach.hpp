#pragma once
// Heidenhain contour approach and departure (APPR / DEP, spec §2.5) as pure functions that
// return the tool-centre path in plane coordinates.
//
// Conventions (spec §0.2, §2.5.3):
//   * n_s = side · left_normal(t) is the unit normal towards the tool side (side +1 RL, -1 RR).
//   * PS (approach start) and PN (departure end) are tool-centre points reached with R0.
//   * PA / PE are programmed contour points; PA_tool = PA + r·n_s(t_A), PE_tool = PE + r·n_s(t_E).
//   * CT / LCT arcs turn d = side · sign(R) (+1 CCW, -1 CW): RL & R>0 CCW, RL & R<0 CW,
//     RR & R>0 CW, RR & R<0 CCW. LCT always has R > 0, so d = side.
//   * Arc centre C = P + R·n_s (R signed) with P = PA / PE when R is the contour radius
//     (ApproachOptions::ct_radius_on_contour, default), or P = PA_tool / PE_tool when R is the
//     tool-centre radius. Tool arc radius: R - r (R > 0) or |R| + r (R < 0) on the contour,
//     |R| in the tool-centre reading. A tool arc radius <= 0 throws "TOOL RADIUS TOO LARGE".
//   * LCT: PH is the tangent point of the line PS -> PH (APPR) or PH -> PN (DEP) on the tool-centre
//     circle (lct_tangency_tool_space, default), or the tangent point on the contour circle of
//     radius (tool arc radius + r), moved radially onto the tool-centre circle (alternative; the
//     line then meets the tool arc at a small kink, flagged by tangent_in/tangent_out = false).
//     Of the two tangent roots, the one whose line direction continues the arc direction is used.
//
// Errors throw CompensationError without a source position (the caller adds the line).
#include <vector>

#include "toolcomp/geometry/vec.hpp"

namespace toolcomp {

enum class ApproachKind { LT, LN, CT, LCT };

struct ApproachOptions {
    // R of CT/LCT is the contour radius (tool arc R - r); false: R is the tool-centre radius.
    bool ct_radius_on_contour = true;
    // LCT tangency in tool-centre space; false: tangency on the contour circle, then offset.
    bool lct_tangency_tool_space = true;
};

// One element of the tool-centre path, in plane coordinates.
struct PathPiece {
    bool arc = false;
    Vec2 end = Vec2::Zero();
    Vec2 centre = Vec2::Zero();  // arcs
    int dir = 0;                 // arcs: +1 CCW, -1 CW
    // Extensions:
    Vec2 start = Vec2::Zero();   // start point (= end of the previous piece)
    double sweep = 0;            // arcs: swept angle in radians, in [0, 2π] (2π: full circle, end == start)
    // The start tangent equals the end tangent of what precedes: the previous piece, or for the
    // first piece of a departure the last contour element (t_E).
    bool tangent_in = false;
    // The end tangent equals the start tangent of what follows: the next piece, or for the last
    // piece of an approach the first contour element (t_A).
    bool tangent_out = false;

    double radius() const { return arc ? (start - centre).norm() : 0.0; }
    double length() const { return arc ? radius() * sweep : (end - start).norm(); }
};

struct Approach {
    ApproachKind kind = ApproachKind::LT;
    Vec2 ps = Vec2::Zero();   // starting point PS (tool centre, reached with R0)
    Vec2 pa = Vec2::Zero();   // first contour point PA (programmed)
    Vec2 t_a = Vec2::Zero();  // unit tangent of the first contour element at PA (normalised here)
    int side = -1;            // +1 RL, -1 RR
    double r = 0;             // effective tool radius (>= 0); APPR with R0: side -1 and r 0
    double len = 0;           // LT, LN (> 0)
    double cca = 0;           // CT: centre angle in degrees (0 < cca <= 360)
    double radius = 0;        // CT: signed R (!= 0); LCT: R > 0
};

// PS -> PH (line), then PH -> PA_tool (line for LT/LN, arc for CT/LCT): always two pieces; the
// first ends at PH_tool, the last at PA_tool. A piece may be degenerate (zero length, sweep 0),
// e.g. LCT with PS on the tangent at PA_tool; callers may skip such pieces.
std::vector<PathPiece> approach_path(const Approach& a, const ApproachOptions& o = {});

struct Departure {
    ApproachKind kind = ApproachKind::LT;
    Vec2 pe = Vec2::Zero();   // last contour point PE (programmed)
    Vec2 t_e = Vec2::Zero();  // unit tangent of the last contour element at PE (normalised here)
    int side = -1;
    double r = 0;
    double len = 0, cca = 0, radius = 0;
    Vec2 pn = Vec2::Zero();   // LCT: programmed end point PN (tool centre, R0)
};

// From PE_tool = PE + r·n_s: DEP LT/LN one line to PN; CT one arc ending at PN_tool; LCT an arc
// PE_tool -> PH_tool then a line PH_tool -> PN.
std::vector<PathPiece> departure_path(const Departure& d, const ApproachOptions& o = {});

// Arc direction of APPR/DEP CT and LCT (spec §2.5.2 table): side · sign(R).
inline int approach_arc_dir(int side, double radius) { return radius < 0 ? -side : side; }

}  // namespace toolcomp
