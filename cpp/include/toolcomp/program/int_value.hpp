#pragma once
// Whole numbers out of the doubles a program's words hold: rounded to nearest (`int_value`)
// or truncated (`int_value_truncated`). Values beyond the int range saturate at INT_MIN /
// INT_MAX (NaN gives INT_MIN), where the word's own range check rejects them, instead of
// wrapping round to a small valid number (T4294967297 is not tool 1) or converting with
// undefined behaviour. Every front end converts through these.
#include <climits>
#include <cmath>

namespace toolcomp {

inline int int_value_truncated(double v) {
    if (!(v > static_cast<double>(INT_MIN) - 1)) return INT_MIN;  // also NaN
    if (v >= static_cast<double>(INT_MAX) + 1) return INT_MAX;
    return static_cast<int>(v);
}

inline int int_value(double v) { return int_value_truncated(std::round(v)); }

}  // namespace toolcomp
