#include "toolcomp/tools/format_sinumerik.hpp"

#include <cmath>
#include <map>

#include "text_lines.hpp"
#include "toolcomp/program/diagnostic.hpp"

namespace toolcomp {

namespace {

using sinumerik::SinumerikEdge;
using sinumerik::SinumerikEdgeMap;

// Geometry-axis index (0 X, 1 Y, 2 Z) of L1, L2, L3 in the common model's vector.
std::array<int, 3> model_axes(const SinumerikEdge& e) {
    return sinumerik::is_turning_type(e.type()) ? std::array<int, 3>{0, 2, 1} : std::array<int, 3>{2, 1, 0};
}

CuttingEdge to_common(const SinumerikEdge& e, int d, double mm) {
    CuttingEdge c;
    c.number = d;
    const auto ax = model_axes(e);
    for (int i = 0; i < 3; ++i) {
        const auto k = static_cast<std::size_t>(ax[static_cast<std::size_t>(i)]);
        c.length[static_cast<long>(k)] = (e.DP(3 + i) + e.DP(21 + i)) * mm;
        c.length_wear[static_cast<long>(k)] = (e.DP(12 + i) + e.SCP(12 + i) + e.ECP(12 + i)) * mm;
    }
    c.radius = e.DP(6) * mm;
    c.radius_wear = (e.DP(15) + e.SCP(15) + e.ECP(15)) * mm;
    c.corner_radius = e.DP(7) * mm;
    c.corner_radius_wear = e.DP(16) * mm;
    if (sinumerik::is_turning_type(e.type())) c.orientation = static_cast<int>(std::lround(e.DP(2)));
    return c;
}

// The common edge written back over the data read (or a new edge).
SinumerikEdge from_common(const CuttingEdge& c, const SinumerikEdge* base, double mm) {
    SinumerikEdge e = base ? *base : sinumerik::edge_from_common(CuttingEdge{});
    if (!base) e.DP(1) = c.orientation != 0 ? 500 : 120;
    if (c.orientation != 0) e.DP(2) = c.orientation;
    const auto ax = model_axes(e);
    for (int i = 0; i < 3; ++i) {
        const long k = ax[static_cast<std::size_t>(i)];
        e.DP(3 + i) = c.length[k] / mm - e.DP(21 + i);
        e.DP(12 + i) = c.length_wear[k] / mm - e.SCP(12 + i) - e.ECP(12 + i);
    }
    e.DP(6) = c.radius / mm;
    e.DP(15) = c.radius_wear / mm - e.SCP(15) - e.ECP(15);
    e.DP(7) = c.corner_radius / mm;
    e.DP(16) = c.corner_radius_wear / mm;
    return e;
}

struct SnSource : detail::TableSource {
    TableFormat format() const override { return TableFormat::sinumerik; }
    std::vector<tables::TextLine> lines;
    std::vector<int> tool_of_line;  // tool number of the line's assignment, -1 for other lines
    SinumerikEdgeMap edges;         // as read, file units
    std::map<int, Tool> snapshot;   // the tools as read (mm)
    double mm = 1;
};

}  // namespace

ToolTable read_sinumerik_table(std::string_view text, LengthUnit units) {
    auto src = std::make_shared<SnSource>();
    src->units = units;
    src->mm = mm_per_unit(units);
    src->edges = sinumerik::parse_tc_dp(text);
    src->lines = tables::split_lines(text);
    for (const auto& l : src->lines) {
        int t = -1;
        try {
            auto one = sinumerik::parse_tc_dp(l.text);
            if (!one.empty()) t = one.begin()->first.first;
        } catch (const Error&) {
        }
        src->tool_of_line.push_back(t);
    }
    ToolTable table(units);
    for (const auto& [key, e] : src->edges) {
        const auto [t, d] = key;
        Tool* tool = table.find(t);
        if (!tool) {
            Tool nt;
            nt.number = t;
            nt.edges.clear();
            nt.edges.push_back(to_common(e, d, src->mm));
            table.set(std::move(nt));
        } else {
            tool->set_edge(to_common(e, d, src->mm));
        }
    }
    for (const Tool& t : table.tools()) src->snapshot.emplace(t.number, t);
    table.set_source(src);
    return table;
}

std::string write_sinumerik_table(const ToolTable& table) {
    const auto* src = dynamic_cast<const SnSource*>(table.source());
    const double mm = mm_per_unit(table.units());
    auto edges_of = [&](const Tool& t) {
        SinumerikEdgeMap m;
        for (const CuttingEdge& c : t.edges) {
            const SinumerikEdge* base = nullptr;
            if (src && src->mm == mm)
                if (auto it = src->edges.find({t.number, c.number}); it != src->edges.end()) base = &it->second;
            m[{t.number, c.number}] = from_common(c, base, mm);
        }
        return sinumerik::write_tc_dp(m);
    };
    if (!src || src->mm != mm) {
        std::string out;
        for (const Tool& t : table.tools()) out += edges_of(t);
        return out;
    }
    std::string out;
    std::map<int, bool> written;
    for (std::size_t i = 0; i < src->lines.size(); ++i) {
        const int t = src->tool_of_line[i];
        const auto& line = src->lines[i];
        if (t < 0) {
            out += line.text + line.eol;
            continue;
        }
        const Tool* now = table.find(t);
        if (!now) continue;  // removed
        auto snap = src->snapshot.find(t);
        if (snap != src->snapshot.end() && snap->second == *now) {
            out += line.text + line.eol;
            continue;
        }
        if (written[t]) continue;
        written[t] = true;
        std::string block = edges_of(*now);
        if (line.eol != "\n") {  // keep the file's line ending
            std::string conv;
            for (char c : block) {
                if (c == '\n') conv += line.eol.empty() ? "\n" : line.eol;
                else conv.push_back(c);
            }
            block = conv;
        }
        out += block;
    }
    for (const Tool& t : table.tools())
        if (!src->snapshot.count(t.number)) {
            if (!out.empty() && out.back() != '\n') out += '\n';
            out += edges_of(t);
        }
    return out;
}

const sinumerik::SinumerikEdge* sinumerik_source_edge(const ToolTable& table, int t, int d) {
    const auto* src = dynamic_cast<const SnSource*>(table.source());
    if (!src || src->mm != 1.0) return nullptr;
    const Tool* now = table.find(t);
    auto snap = src->snapshot.find(t);
    if (!now || snap == src->snapshot.end() || !(snap->second == *now)) return nullptr;
    auto it = src->edges.find({t, d});
    return it == src->edges.end() ? nullptr : &it->second;
}

}  // namespace toolcomp
