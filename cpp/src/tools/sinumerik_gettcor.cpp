// GETTCOR (spec §3.5); conventions and assumptions in sinumerik_gettcor.hpp.
#include "toolcomp/tools/sinumerik_gettcor.hpp"

#include <string>

#include "toolcomp/program/text.hpp"

namespace toolcomp::sinumerik {

namespace {

// Parses "<components>[:<coordinate system>]"; returns a status, fills the letters in order.
int parse_comp(std::string_view comp, std::string& letters) {
    std::string s;
    for (char ch : comp)
        if (!ascii_space(ch))
            s += ascii_upper(ch);
    const auto colon = s.find(':');
    const std::string head = s.substr(0, colon);
    if (head.empty()) return gettcor_bad_comp;
    for (char ch : head) {
        if (std::string_view("GWESC").find(ch) == std::string_view::npos) return gettcor_bad_comp;
        if (letters.find(ch) != std::string::npos) return gettcor_bad_comp;
        letters += ch;
    }
    if (colon != std::string::npos) {
        const std::string tail = s.substr(colon + 1);
        if (tail.size() != 1 || std::string_view("MBWKT").find(tail[0]) == std::string_view::npos)
            return gettcor_bad_coord;
    }
    return gettcor_ok;
}

}  // namespace

int gettcor(std::array<double, 11>& len, std::string_view comp, const SinumerikEdge& edge,
            const GettcorSettings& s, std::string_view stat, int dl) {
    if (!stat.empty()) return s.tool_env_memory == 0 ? gettcor_no_env_memory : gettcor_env_missing;
    std::string letters;
    if (int st = parse_comp(comp, letters); st != gettcor_ok) return st;
    if (dl != -1 && dl != 0 && dl != edge.dl) return gettcor_bad_dl;
    const bool use_dl = dl != 0;

    const double ws = s.lengths.wear_sign();
    const int type = edge.type();
    std::array<double, 11> out{};
    out[0] = edge.DP(1);
    out[1] = edge.DP(2);
    Vec3 axis_len = Vec3::Zero();  // (X, Y, Z)
    for (char c : letters) {
        // first: DP-style index of length 1 (and radius at +3, extras at +4..+8) in `arr`
        const std::array<double, 25>* arr = &edge.dp;
        int first = 3;
        double sign = 1.0;
        bool diameter = s.geometry_diameter;
        switch (c) {
            case 'G': break;
            case 'C': first = 21; break;
            case 'W': first = 12; sign = ws; diameter = s.wear_diameter; break;
            case 'E': arr = &edge.ecp; first = 12; sign = ws; diameter = s.wear_diameter; break;
            default /* 'S' */: arr = &edge.scp; first = 12; sign = ws; diameter = s.wear_diameter; break;
        }
        if ((c == 'E' || c == 'S') && !use_dl) continue;
        auto at = [&](int n) { return (*arr)[static_cast<std::size_t>(n - 1)]; };
        Vec3 v = place_lengths(Vec3(at(first), at(first + 1), at(first + 2)) * sign, type, s.plane, s.lengths);
        if (diameter && s.transverse_axis >= 0 && s.transverse_axis < 3) v[s.transverse_axis] *= 0.5;
        axis_len += v;
        if (c == 'C') continue;
        out[5] += sign * at(first + 3);
        for (int k = 0; k < 5; ++k) out[static_cast<std::size_t>(6 + k)] += at(first + 4 + k);
    }
    const auto ax = axes(s.plane);  // abscissa, ordinate, applicate
    out[2] = axis_len[ax.a];
    out[3] = axis_len[ax.b];
    out[4] = axis_len[ax.c];
    len = out;
    return gettcor_ok;
}

int gettcor(std::array<double, 11>& len, std::string_view comp, const SinumerikEdgeMap& edges, int t, int d,
            const GettcorSettings& s, std::string_view stat, int dl) {
    if (!stat.empty()) return s.tool_env_memory == 0 ? gettcor_no_env_memory : gettcor_env_missing;
    std::string letters;
    if (int st = parse_comp(comp, letters); st != gettcor_ok) return st;
    auto it = edges.find({t, d});
    if (it == edges.end()) {
        auto first = edges.lower_bound({t, 0});
        return (first != edges.end() && first->first.first == t) ? gettcor_bad_d : gettcor_bad_t;
    }
    return gettcor(len, comp, it->second, s, stat, dl);
}

}  // namespace toolcomp::sinumerik
