#include "toolcomp/tools/sinumerik_settcor.hpp"

#include <string>

#include "toolcomp/program/text.hpp"

namespace toolcomp::sinumerik {

namespace {
// Where component `c` keeps length i (1..3) or the radius (i = 0); nullptr when it has none.
double* slot(SinumerikEdge& e, char c, int i) {
    switch (c) {
        case 'G': return i == 0 ? &e.dp[5] : &e.dp[static_cast<std::size_t>(1 + i)];    // DP6, DP3..5
        case 'W': return i == 0 ? &e.dp[14] : &e.dp[static_cast<std::size_t>(10 + i)];  // DP15, DP12..14
        case 'E': return i == 0 ? &e.ecp[14] : &e.ecp[static_cast<std::size_t>(10 + i)];
        case 'S': return i == 0 ? &e.scp[14] : &e.scp[static_cast<std::size_t>(10 + i)];
        case 'C': return i == 0 ? nullptr : &e.dp[static_cast<std::size_t>(19 + i)];    // DP21..23
        default: return nullptr;
    }
}
}  // namespace

int settcor(SinumerikEdge& edge, const Vec3& corval, std::string_view comp, int corcomp, int cormode, int geoax,
            Plane plane, const SinumerikLengthSettings& s) {
    std::string letters;
    std::size_t i = 0;
    for (; i < comp.size() && comp[i] != ':'; ++i) {
        const char c = ascii_upper(comp[i]);
        if (c == ' ' || c == '\t') continue;
        if (std::string_view("GWESC").find(c) == std::string_view::npos || letters.find(c) != std::string::npos)
            return gettcor_bad_comp;
        letters.push_back(c);
    }
    if (letters.empty() || letters.size() > 2) return gettcor_bad_comp;
    if (i < comp.size()) {
        std::string coord;
        for (std::size_t k = i + 1; k < comp.size(); ++k)
            if (comp[k] != ' ' && comp[k] != '\t')
                coord.push_back(ascii_upper(comp[k]));
        if (coord != "W" && coord != "T") return gettcor_bad_coord;
    }
    if (corcomp < 0 || corcomp > 6) return settcor_bad_corcomp;
    if (cormode != 0 && cormode != 1) return settcor_bad_cormode;
    if (corcomp == 0 && (geoax < 1 || geoax > 3)) return settcor_bad_geoax;
    if (corcomp == 6 && letters[0] == 'C') return settcor_no_radius;

    // The correction per target: index 0 the radius, 1..3 the lengths L1..L3.
    std::array<bool, 4> touch{};
    std::array<double, 4> value{};
    if (corcomp == 6) {
        touch[0] = true;
        value[0] = corval[0];
    } else if (corcomp >= 3) {
        touch[static_cast<std::size_t>(corcomp - 2)] = true;
        value[static_cast<std::size_t>(corcomp - 2)] = corval[0];
    } else {
        const auto axes = length_axes(edge.type(), plane, s);  // axis of L1..L3
        Vec3 v = corcomp == 0 ? Vec3::Zero() : corval;
        if (corcomp == 0) v[geoax - 1] = corval[0];
        for (std::size_t l = 0; l < 3; ++l) {
            const double x = v[axes[l]];
            if (corcomp == 0 && axes[l] != geoax - 1) continue;
            touch[l + 1] = true;
            value[l + 1] = x;
        }
    }
    SinumerikEdge out = edge;
    for (int k = 0; k < 4; ++k) {
        if (!touch[static_cast<std::size_t>(k)]) continue;
        double* first = slot(out, letters[0], k);
        const double v = value[static_cast<std::size_t>(k)];
        if (cormode == 1) {
            *first += v;
        } else {
            double* second = letters.size() > 1 ? slot(out, letters[1], k) : nullptr;
            *first = v - (second ? *second : 0.0);
        }
    }
    edge = out;
    return 0;
}

int settcor(SinumerikEdgeMap& edges, int t, int d, const Vec3& corval, std::string_view comp, int corcomp,
            int cormode, int geoax, Plane plane, const SinumerikLengthSettings& s) {
    auto it = edges.find({t, d});
    if (it == edges.end()) {
        auto first = edges.lower_bound({t, 0});
        return first != edges.end() && first->first.first == t ? gettcor_bad_d : gettcor_bad_t;
    }
    return settcor(it->second, corval, comp, corcomp, cormode, geoax, plane, s);
}

}  // namespace toolcomp::sinumerik
