#include "toolcomp/tools/tool.hpp"
#include "toolcomp/program/codes.hpp"

#include <cmath>

#include "toolcomp/program/diagnostic.hpp"

#include <algorithm>

namespace toolcomp {

Eigen::Vector3d CuttingEdge::effective_length() const { return length + length_wear; }
double CuttingEdge::effective_radius() const { return radius + radius_wear; }
double CuttingEdge::effective_corner_radius() const { return corner_radius + corner_radius_wear; }

bool operator==(const CuttingEdge& a, const CuttingEdge& b) {
    return a.number == b.number && a.length == b.length && a.rotary == b.rotary &&
           a.uvw == b.uvw && a.radius == b.radius && a.corner_radius == b.corner_radius &&
           a.length_wear == b.length_wear && a.radius_wear == b.radius_wear &&
           a.corner_radius_wear == b.corner_radius_wear && a.orientation == b.orientation &&
           a.front_angle == b.front_angle && a.back_angle == b.back_angle;
}

bool operator==(const Tool& a, const Tool& b) {
    return a.number == b.number && a.pocket == b.pocket && a.name == b.name &&
           a.comment == b.comment && a.edges == b.edges;
}

bool Tool::has_edge(int d) const {
    return std::any_of(edges.begin(), edges.end(), [d](const CuttingEdge& e) { return e.number == d; });
}

const CuttingEdge& Tool::edge(int d) const {
    for (const auto& e : edges)
        if (e.number == d) return e;
    throw ToolTableError(code::tool_no_such_edge,
                         "tool T" + std::to_string(number) + " has no cutting edge D" + std::to_string(d));
}

CuttingEdge& Tool::edge(int d) {
    return const_cast<CuttingEdge&>(static_cast<const Tool&>(*this).edge(d));
}

void Tool::set_edge(const CuttingEdge& e) {
    for (auto& x : edges)
        if (x.number == e.number) {
            x = e;
            return;
        }
    edges.push_back(e);
}

void validate_tool(const Tool& t) {
    const std::string who = "tool T" + std::to_string(t.number);
    if (t.number < 0) throw ToolTableError(code::tool_bad_number, "negative tool number " + std::to_string(t.number));
    if (t.pocket < 0) throw ToolTableError(code::tool_bad_number, who + ": negative pocket number");
    if (t.edges.empty()) throw ToolTableError(code::tool_no_edges, who + " has no cutting edge");
    for (std::size_t i = 0; i < t.edges.size(); ++i) {
        const auto& e = t.edges[i];
        if (e.orientation < 0 || e.orientation > 9)
            throw ToolTableError(code::tool_bad_orientation,
                                 who + ": orientation " + std::to_string(e.orientation) + " is outside 0..9");
        // Every number finite, the sums the runs use too (a NaN radius would compensate nothing
        // without a word).
        double z = 0;
        for (int k = 0; k < 3; ++k)
            z += e.length[k] * 0 + e.length_wear[k] * 0 + (e.length[k] + e.length_wear[k]) * 0 + e.rotary[k] * 0 +
                 e.uvw[k] * 0;
        for (double v : {e.radius, e.corner_radius, e.radius_wear, e.corner_radius_wear, e.front_angle, e.back_angle,
                         e.effective_radius(), e.effective_corner_radius()})
            z += v * 0;
        if (z != 0)
            throw ToolTableError(code::tool_bad_value,
                                 who + " D" + std::to_string(e.number) + ": a value (or its sum with the wear) is not a "
                                                                          "finite number");
        for (std::size_t j = 0; j < i; ++j)
            if (t.edges[j].number == e.number)
                throw ToolTableError(code::tool_duplicate_edge,
                                     who + ": cutting edge D" + std::to_string(e.number) + " appears twice");
    }
}

ToolShape tool_shape(const CuttingEdge& e) {
    const double r = e.effective_radius(), r2 = e.effective_corner_radius();
    if (r2 <= 1e-12) return ToolShape::end_mill;
    if (std::fabs(r2 - r) <= 1e-12) return ToolShape::ball;
    return ToolShape::toroid;
}

}  // namespace toolcomp
