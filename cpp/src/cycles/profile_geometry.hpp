#pragma once
// The geometry under LinuxCNC's profile cycles (profile_cycles.hpp): pieces in the normal
// frame, their offsets and intersections, the corners made from fillets and chamfers, and
// the stepwise offset of a whole profile. Private to profile_cycles.cpp.
#include <string>
#include <vector>

#include "profile_cycles.hpp"

namespace toolcomp::cycles::profile {

inline constexpr double kTol = 1e-6;      // LinuxCNC's tolerance of the cycles
inline constexpr double kShort = 1e-3;    // pieces shorter than this drop out
inline constexpr double kGap = 1e-2;      // an offset corner opened wider than this gets an arc
inline constexpr Point kI{0.0, 1.0};

[[noreturn]] void geometry_error(const std::string& what);  // CycleError "G7X error: <what>"

bool is_round(const Piece& p);
// LinuxCNC's "radius" of a piece, the measure of its shortness: a line's length, for an arc
// the smaller of its chord and its radius.
double extent(const Piece& p);
// The piece runs toward -Z (arcs: within one half, above or below their centre).
bool monotonic(const Piece& p);
// Parallel by d (lines: to the right of the travel in the (Z, X) plane; arcs: the radius
// grows by d counter-clockwise, shrinks clockwise).
void offset(Piece& p, double d);

// Where the piece crosses the level X = x, in LinuxCNC's order (at most two Z values).
struct Crossings {
    double z[2] = {0, 0};
    int n = 0;
    bool empty() const { return n == 0; }
    double front() const { return z[0]; }
    double back() const { return z[n - 1]; }
};
Crossings crossings(const Piece& p, double x);

// Moves a's end and b's start to where the two pieces (or their lines and circles) meet.
void intersect(Piece& a, Piece& b);

// The profile and the frame it is in: bit 4 turned (-i·p), bit 2 X mirrored, bit 1 Z mirrored.
struct Profile {
    std::vector<Piece> pieces;
    int frame = 0;
    void turn();       // G72: (z, x) -> (x, -z)
    void normalise();  // mirrored to run toward -Z, ending no lower than the first piece's end
    void make_corners();   // fillets and chamfers between pieces; too short pieces dropped
    void check_monotonic();  // the lead-in's start no further in -Z than its end; "Not monotonic"
    void add_distance(double distance);  // the allowance, toward the start point's side
};

}  // namespace toolcomp::cycles::profile
