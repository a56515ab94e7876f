#pragma once
// Words that must be whole numbers, as each control reads them. LinuxCNC allows a little
// slack (a value computed by an expression may miss by rounding): its read_integer_value
// (M, T, H, L) takes a value up to 0.0001 above an integer as that integer and one within
// 0.0001 below the next integer as the next; G41/G42 D (is_near_int) a value within 0.0001
// of the nearest integer; G2/G3 P within 0.001. Fanuc words are taken as written.
// `slack`: ControlProfile::integer_word_slack.
#include <cmath>


namespace toolcomp::iso {

inline bool linuxcnc_whole(double v) {
    const double frac = v - std::floor(v);
    return frac <= 0.0001 || frac > 0.9999;
}

// M, T, H, L words: whole for the control (the value then rounds to its integer).
inline bool whole_word(double v, bool slack) {
    return slack ? linuxcnc_whole(v) : std::fabs(v - std::round(v)) <= 1e-9;
}

// G41/G42 D: LinuxCNC's is_near_int, the integer v + 0.5 truncates to, if v is within
// 0.0001 of it (so a negative D, or one beyond the int range, is no whole number there);
// exactly one otherwise.
inline bool d_word_whole(double v, bool slack) {
    if (!slack) return std::fabs(v - std::round(v)) <= 1e-9;
    if (!(v > -2147483648.0 && v < 2147483647.0)) return false;
    return std::fabs(std::trunc(v + 0.5) - v) < 0.0001;
}

}  // namespace toolcomp::iso
