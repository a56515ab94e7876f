#pragma once
// Decimal spelling of doubles with a fixed number of decimals, as printf's "%.*f" and
// Python's f"{v:.{n}f}" write them (correctly rounded), for the Path's text writers.
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace toolcomp::text {

struct Fixed {
    char text[360];
    std::size_t n = 0;
    std::string_view view() const { return {text, n}; }
    bool operator==(const Fixed& o) const { return n == o.n && std::memcmp(text, o.text, n) == 0; }
};

// The common case without the general algorithm: |v|·10^digits below 2^44 and not within
// 0.01 of a half (the product's rounding error is below 2^-9 there, so rounding it to an
// integer rounds the exact value the same way).
inline bool fast_fixed(double v, int digits, Fixed& f) {
    static constexpr std::uint64_t kPow10[10] = {1, 10, 100, 1000, 10000, 100000, 1000000, 10000000, 100000000, 1000000000};
    if (digits < 0 || digits > 9) return false;
    const double scaled = std::fabs(v) * static_cast<double>(kPow10[digits]);
    if (!(scaled < 17592186044416.0)) return false;  // 2^44 (NaN and infinities too)
    const double whole = std::floor(scaled), frac = scaled - whole;
    if (std::fabs(frac - 0.5) < 0.01) return false;
    const auto r = static_cast<std::uint64_t>(whole) + (frac > 0.5 ? 1 : 0);
    char* p = f.text;
    if (std::signbit(v)) *p++ = '-';
    p = std::to_chars(p, f.text + sizeof f.text, r / kPow10[digits]).ptr;
    if (digits > 0) {
        *p++ = '.';
        std::uint64_t rest = r % kPow10[digits];
        for (int i = digits - 1; i >= 0; --i) {
            p[i] = static_cast<char>('0' + rest % 10);
            rest /= 10;
        }
        p += digits;
    }
    f.n = static_cast<std::size_t>(p - f.text);
    return true;
}

// `digits` (0..30) decimals; NaN "nan", infinities "inf"/"-inf". `trim`: trailing zeros of
// the decimals and a bare point dropped, and a zero is "0" whatever its sign.
inline Fixed fixed(double v, int digits, bool trim) {
    Fixed f;
    if (std::isnan(v)) {
        std::memcpy(f.text, "nan", 3);
        f.n = 3;
        return f;
    }
    if (!fast_fixed(v, digits, f))
        f.n = static_cast<std::size_t>(std::to_chars(f.text, f.text + sizeof f.text, v, std::chars_format::fixed, digits).ptr - f.text);
    if (!trim) return f;
    if (std::memchr(f.text, '.', f.n)) {
        while (f.text[f.n - 1] == '0') --f.n;
        if (f.text[f.n - 1] == '.') --f.n;
    }
    if (f.n == 2 && f.text[0] == '-' && f.text[1] == '0') {
        f.text[0] = '0';
        f.n = 1;
    }
    return f;
}

inline void append(std::string& out, const Fixed& f) { out.append(f.text, f.n); }

template <class Int>
void append_int(std::string& out, Int v) {
    char buf[24];
    out.append(buf, static_cast<std::size_t>(std::to_chars(buf, buf + sizeof buf, v).ptr - buf));
}

}  // namespace toolcomp::text
