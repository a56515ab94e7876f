#pragma once
// What a probe move (LinuxCNC G38.2-G38.5) met. Where the probe stops depends on the part,
// which a program does not hold: a run is given the results, one per probe move in order;
// a probe move beyond them touches at its target.
#include <array>

namespace toolcomp {

struct ProbeResult {
    bool contact = true;  // the probe tripped (G38.2 / G38.3) or cleared (G38.4 / G38.5)
    // Where, in the program's coordinates of the active system (tool length offset off):
    // X Y Z in mm, A B C in degrees; `axes` of them given (3: X Y Z), the rest the target's.
    std::array<double, 6> point{};
    int axes = 3;
};

}  // namespace toolcomp
