#pragma once
// Decimal text (digits with at most one point; no sign, no exponent) to double, rounded as
// std::from_chars rounds it (to the nearest double). Up to 15 digits take the exact fast
// path: the digits as an integer (below 2^53, so exact) divided by an exact power of ten is
// one correctly rounded division. Longer numbers go to from_chars.
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <system_error>

namespace toolcomp {

// The number of up to 15 digits `m` with `frac` of them after the point (0..15).
inline double decimal_value(std::uint64_t m, int frac) {
    static constexpr double kPow10[16] = {1e0, 1e1, 1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                          1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};
    return frac > 0 ? static_cast<double>(m) / kPow10[frac] : static_cast<double>(m);
}

// A run of digits and points from s[i] on (a number's text after its sign), as the ISO
// lexers read it: where it ends, the integer of its first 15 digits, how many digits and
// points there are, and how many digits follow the point.
struct DecimalRun {
    std::size_t end = 0;
    std::uint64_t m = 0;
    int digits = 0, points = 0, frac = 0;
    // A number decimal_value(m, frac) gives exactly (else: an error, or from_chars).
    bool plain() const { return digits > 0 && digits <= 15 && points <= 1; }
};
inline DecimalRun scan_decimal_run(const char* s, std::size_t i, std::size_t n) {
    DecimalRun r;
    for (; i < n; ++i) {
        const char c = s[i];
        if (c >= '0' && c <= '9') {
            if (++r.digits <= 15) r.m = r.m * 10 + static_cast<std::uint64_t>(c - '0');
            r.frac += r.points;  // digits after the point (more than one point is refused)
        } else if (c == '.') {
            ++r.points;
        } else {
            break;
        }
    }
    r.end = i;
    return r;
}

// False when the text is not such a number (or from_chars refuses it).
inline bool parse_decimal(std::string_view s, double& out) {
    const DecimalRun run = scan_decimal_run(s.data(), 0, s.size());
    if (run.end != s.size() || run.points > 1 || run.digits == 0) return false;
    if (run.plain()) {
        out = decimal_value(run.m, run.frac);
        return true;
    }
    const auto r = std::from_chars(s.data(), s.data() + s.size(), out);
    return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

}  // namespace toolcomp
