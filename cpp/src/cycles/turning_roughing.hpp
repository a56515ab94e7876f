#pragma once
// Stock removal of a lathe's roughing cycles (Fanuc G71 / G72, types I and II): the passes that cut
// a finishing contour out of the stock between it and the start point. Dialect-free: the
// interpreter reads the cycle's words and the contour's blocks; this computes the moves.
//
// Plane coordinates of the cut: `u` along the passes (Z for G71, X radius for G72), `v`
// across them, the direction the passes step in (X radius for G71, Z for G72).
#include <cstdint>
#include <string>
#include <vector>

#include "toolcomp/geometry/vec.hpp"

namespace toolcomp::cycles {

// An element of the contour, from the end of the one before: a line, or an arc about
// `center` (dir +1 counter-clockwise in (u, v), -1 clockwise).
struct ContourPiece {
    Vec2 end;
    Vec2 center = Vec2::Zero();
    int dir = 0;   // 0: a line
    int line = 0;  // the block's source line
};

struct Contour {
    Vec2 start = Vec2::Zero();  // its first point: where the P block ends
    std::vector<ContourPiece> pieces;
};

enum class StepKind : std::uint8_t { rapid, feed, arc };

// A move of the cycle, from the end of the one before.
struct Step {
    StepKind kind;
    Vec2 end;
    Vec2 center = Vec2::Zero();
    int dir = 0;
    int line = 0;  // the contour block it follows (0: the cycle's own block)
};

struct Roughing {
    Vec2 start = Vec2::Zero();      // where the tool stands when the cycle begins (A)
    double depth = 0;               // depth of cut of a pass (Δd), > 0
    double retract = 0;             // the escape after each pass, at 45 degrees (e), >= 0
    Vec2 allowance = Vec2::Zero();  // finishing allowance: the contour is shifted by it
    Vec2 rough_allowance = Vec2::Zero();  // more left by the levels (Haas I, K), taken by the contour pass
    bool rapid_infeed = true;       // the P block is G00: the passes start at rapid, else at feed
    std::size_t max_passes = 1000000;
    std::size_t max_moves = SIZE_MAX;  // beyond: MoveLimit
};

// Thrown by a cycle that would make more than the moves it was allowed (the interpreter's
// remaining block budget), before it has built them all.
struct MoveLimit {};

// A contour or parameters the control refuses: the catalogue code, the control's alarm
// text, and the contour block it concerns (0: the cycle's block).
struct CycleError {
    const char* code;
    std::string message;
    int line = 0;
};

// Type I: the contour's v never turns back towards the start's side of where it began, u
// never turns back. The passes step from the start point by `depth` while they lie short of
// the contour's first point; each runs along u to the shifted contour, escapes at 45
// degrees by `retract` and goes back to the start's u at rapid. Then one pass along the
// shifted contour (what the passes left, at most `depth`, and an even allowance) and a
// rapid back to the start point. Throws CycleError.
std::vector<Step> rough_type1(const Contour& contour, const Roughing& r);

// Type II: the contour's v may turn back (pockets), its u never. Each level cuts where the
// boundary (the line from the start point to the contour's first point, then the contour)
// lies beyond it; a pass goes down the wall to the level, cuts to where the contour rises
// to it, follows the contour back up to the level before, retracts by `retract` across the
// cut and returns over its start at rapid. Where a level is split by a hump, the pockets
// are roughed one after the other, each to its bottom. Then one pass along the shifted
// contour from the start point and a rapid back to it (above the stock first). Throws
// CycleError.
std::vector<Step> rough_type2(const Contour& contour, const Roughing& r);

// Pattern repeating (G73): `passes` passes along the contour, the first shifted by `first`,
// the last by `last`, the ones between evenly; each from the start point to the shifted
// contour's first point (rapid or feed), along it at feed, and at rapid back to the start
// (return_shifted: to the start shifted as the next pass is, the last pass to the start).
std::vector<Step> pattern_repeat(const Contour& contour, const Vec2& start, const Vec2& first, const Vec2& last,
                                 int passes, bool rapid_approach, bool return_shifted,
                                 std::size_t max_moves = SIZE_MAX);

}  // namespace toolcomp::cycles
