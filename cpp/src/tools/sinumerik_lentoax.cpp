#include "toolcomp/tools/sinumerik_lentoax.hpp"

#include <string>

#include "toolcomp/program/text.hpp"

namespace toolcomp::sinumerik {

namespace {
bool known_coordinate_system(std::string_view coord) {
    std::string c;
    for (char ch : coord)
        if (!ascii_space(ch)) c += ascii_upper(ch);
    for (const char* k : {"M", "MCS", "B", "BCS", "W", "WCS", "K", "KCS", "T", "TCS"})
        if (c == k) return true;
    return false;
}
}  // namespace

LentoaxResult lentoax(int tool_type, Plane plane, const SinumerikLengthSettings& s, std::string_view coord) {
    LentoaxResult r;
    if (!known_coordinate_system(coord)) {
        r.status = -1;
        return r;
    }
    const auto axes = length_axes(tool_type, plane, s);
    for (int i = 0; i < 3; ++i) {
        r.axind[static_cast<std::size_t>(i)] = axes[static_cast<std::size_t>(i)] + 1;
        r.matrix(i, axes[static_cast<std::size_t>(i)]) = 1.0;
    }
    return r;
}

}  // namespace toolcomp::sinumerik
