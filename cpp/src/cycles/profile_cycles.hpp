#pragma once
// LinuxCNC's lathe profile cycles: G70 finishing and G71 / G72 roughing (with their .1 and .2
// variants), computed as LinuxCNC 2.9.10 computes them. Dialect-free: the interpreter reads
// the profile's subroutine into pieces; this computes the moves.
//
// How LinuxCNC sees a profile: points are complex numbers z + i·x (X a radius). The profile is
// brought into a normal frame (G72: turned by 90 degrees first; then mirrored so that it runs
// toward -Z and ends no lower than it starts), its fillets and chamfers are made, it is offset
// by the allowance in small steps (each at most half the shortest piece, so pieces that vanish
// drop out one step at a time), and it is cut in levels of constant X that step down from the
// start point, pockets included. The moves are mapped back to the program's frame.
#include <complex>
#include <cstdint>
#include <vector>

#include "turning_roughing.hpp"  // Step, CycleError

namespace toolcomp::cycles::profile {

using Point = std::complex<double>;  // z + i·x, program units, X a radius

// A piece of the profile as the subroutine gives it. The first is the lead-in: from the
// cycle's start point to the first point of the subroutine. A fillet (A word) or a chamfer
// (C word) stands between the two pieces it joins, at their common point, with its size.
struct Piece {
    enum Kind : std::uint8_t { line, arc, fillet, chamfer } kind = line;
    Point start, end, centre;
    bool ccw = false;  // arcs: G3 in the ZX plane
    double size = 0;   // fillet radius, chamfer size
};

struct Finishing {           // G70
    double start_distance = 0;  // D
    double end_distance = 0;    // E
    double passes = 1;          // P (LinuxCNC divides by it as given, counts its whole part)
};

struct Roughing {          // G71 / G72
    int variant = 0;       // 0: with pockets, 1 (.1): no pockets, 2 (.2): only what .1 left
    bool facing = false;   // G72: levels of constant Z
    double allowance = 0;  // D
    double depth = 1;      // I, > 0
    double escape = 0.5;   // R
};

// The moves, in (Z, X) of the program: rapids, feeds and arcs (dir +1: G3). An arc LinuxCNC
// would leave out (it ends where the tool stands) is left out; straight moves of no length
// are kept, as LinuxCNC emits them. Throws CycleError with LinuxCNC's text after "G7X error: ";
// beyond `max_moves` moves it throws MoveLimit.
std::vector<Step> finish(std::vector<Piece> profile, const Finishing& f, std::size_t max_moves);
std::vector<Step> rough(std::vector<Piece> profile, const Roughing& r, std::size_t max_moves);

}  // namespace toolcomp::cycles::profile
