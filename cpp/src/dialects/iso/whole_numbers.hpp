#pragma once
// Words that must be whole numbers, as each control reads them. LinuxCNC allows a little
// slack (a value computed by an expression may miss by rounding): its read_integer_value
// (M, T, H, L) takes a value up to 0.0001 above an integer as that integer and one within
// 0.0001 below the next integer as the next; G41/G42 D (is_near_int) a value within 0.0001
// of the nearest integer; G2/G3 P within 0.001. Fanuc words are taken as written.
#include <cmath>

#include "toolcomp/program/dialect.hpp"

namespace toolcomp::iso {

inline bool linuxcnc_whole(double v) {
    const double frac = v - std::floor(v);
    return frac <= 0.0001 || frac > 0.9999;
}

// M, T, H, L words: whole for the dialect (the value then rounds to its integer).
inline bool whole_word(double v, Dialect d) {
    return d == Dialect::linuxcnc ? linuxcnc_whole(v) : std::fabs(v - std::round(v)) <= 1e-9;
}

// Within `slack` of the nearest integer (LinuxCNC), exactly one otherwise.
inline bool near_whole(double v, double slack, Dialect d) {
    return std::fabs(v - std::round(v)) < (d == Dialect::linuxcnc ? slack : 1e-9);
}

}  // namespace toolcomp::iso
