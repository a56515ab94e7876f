// Where a machining cycle runs besides the tool's position: CYCL CALL POS, PATTERN DEF with
// CYCL CALL PAT, and the pattern cycles 220 POLAR PATTERN and 221 CARTESIAN PATTERN (which
// run the cycle defined before them at each of their points as soon as they are defined).
// Points are in the working plane, measured from the datum (CYCL DEF 7); a point's Z (the
// tool axis) shifts the cycle's surface Q203.
#include <cmath>
#include <string>

#include "interp.hpp"
#include "toolcomp/program/codes.hpp"
#include "toolcomp/program/text.hpp"

namespace toolcomp::heidenhain {

namespace {

constexpr std::string_view kAxis[3] = {"X", "Y", "Z"};
constexpr std::string_view kIncAxis[3] = {"IX", "IY", "IZ"};
constexpr std::size_t kMaxPatternPoints = 100000;

Vec2 rotated(const Vec2& v, double degrees) {
    const double a = degrees * kPi / 180;
    return {v.x() * std::cos(a) - v.y() * std::sin(a), v.x() * std::sin(a) + v.y() * std::cos(a)};
}

// A grid of nx x ny points `step` apart from `start`, turned by `degrees` about it, line by
// line, each line back the way the one before came (PATTERN DEF PAT and cycle 221).
std::vector<Vec2> meander(const Vec2& start, const Vec2& step, int nx, int ny, double degrees) {
    std::vector<Vec2> out;
    for (int j = 0; j < ny; ++j)
        for (int k = 0; k < nx; ++k) {
            const int i = j % 2 == 0 ? k : nx - 1 - k;
            out.push_back(start + rotated({i * step.x(), j * step.y()}, degrees));
        }
    return out;
}

}  // namespace

// The feed of the moves to a cycle's position (CYCL CALL POS / PAT): F, or FMAX; without
// either FMAX. M functions act as in any block; the block's F is for these moves only.
double Interp::call_feed(Tokens t, std::size_t from) {
    double feed = INFINITY;
    for (std::size_t i = from; i < t.size(); ++i) {
        const Token& k = t[i];
        if (k.is("F") && k.has_value) feed = k.value * (prog_.inch ? 2.54 : 1.0);
        else if (k.is("FMAX")) feed = INFINITY;
        else if (k.is("M") && k.has_value) m_function(t, k);
        else if (std::find(std::begin(kAxis), std::end(kAxis), k.key) == std::end(kAxis) &&
                 std::find(std::begin(kIncAxis), std::end(kIncAxis), k.key) == std::end(kIncAxis))
            fail(code::bad_word, (k.key.empty() ? std::string("A number") : k.key.str()) + " is not read in CYCL CALL " + t[2].key +
                                     " blocks",
                 k.column);
    }
    if (!(feed > 0)) fail(code::no_feed, "The feed of CYCL CALL " + t[2].key + " must be above 0", t[0].column);
    return feed;
}

// A move in the working plane to `to` at `feed` mm/min (+inf: FMAX), R0.
void Interp::plane_move(const Vec2& to, double feed) { straight_to(with_plane(pos_, to), feed); }

const Interp::CycleDef& Interp::machining_cycle(int column, const std::string& caller) const {
    if (!cycle_def_) fail(code::unsupported_block, caller + " without a cycle defined (CYCL DEF)", column);
    if (cycle_def_->number < 200)
        fail(code::unsupported_block, caller + " of the old cycle " + std::to_string(cycle_def_->number) +
                                          ": toolcomp runs it with CYCL CALL only",
             column);
    return *cycle_def_;
}

// CYCL CALL POS X.. Y.. Z..: to X, Y in the plane (first up to the 2nd set-up clearance if the
// tool stands at or below the surface), then the cycle with its surface shifted by Z.
void Interp::call_at_position(Tokens t) {
    const CycleDef& d = machining_cycle(t[0].column, "CYCL CALL POS");
    const PlaneAxes ax = axes(plane_);
    for (int a : {ax.a, ax.b, ax.c})
        if (!find(t, kAxis[a]) && !find(t, kIncAxis[a]))
            fail(code::missing_value, "CYCL CALL POS needs " + std::string(kAxis[a]), t[2].column);
    const double feed = call_feed(t, 3);
    const Vec3 target = end_point(t, 3);
    const double shift = target[ax.c];
    const double surface = d.q.at(203) + shift;
    if (pos_[ax.c] <= surface) axis_move(surface + d.q.at(204), INFINITY);
    plane_move(plane2(target), feed);
    call_cycle(t[0].column, shift);
}

// PATTERN DEF: POS1 ( X.. Y.. Z.. ) ... POS9, ROW1 ( X Y D NUM ROT Z ), PAT1 ( X Y DX DY NUMX
// NUMY ROT ROTX ROTY Z ), CIRC1 ( X Y D START NUM Z ), PITCHCIRC1 ( X Y D START STEP NUM Z ),
// their points in order. FRAME (the border of a grid) is refused: the order the TNC takes its
// points in is not documented.
void Interp::pattern_def(Tokens t) {
    pattern_.clear();
    std::size_t i = 2;
    while (i < t.size()) {
        const Token& head = t[i];
        if (i + 1 >= t.size() || !t[i + 1].is("("))
            fail(code::bad_word, "PATTERN DEF: " + (head.key.empty() ? std::string("a number") : head.key.str()) +
                                     " where a pattern (POS, ROW, PAT, CIRC, PITCHCIRC) with its values in parentheses "
                                     "belongs",
                 head.column);
        std::size_t close = i + 2;
        while (close < t.size() && !t[close].is(")")) ++close;
        if (close == t.size()) fail(code::bad_word, "PATTERN DEF: ')' missing", head.column);
        pattern_item(head, t.subspan(i + 2, close - i - 2));
        i = close + 1;
    }
    if (pattern_.empty()) fail(code::missing_value, "PATTERN DEF without a pattern", t[0].column);
}

void Interp::pattern_item(const Token& head, Tokens v) {
    const PlaneAxes ax = axes(plane_);
    std::vector<std::string_view> allowed;
    const std::string& kind = head.key;
    if (kind == "POS") allowed = {kAxis[ax.a], kAxis[ax.b], kIncAxis[ax.a], kIncAxis[ax.b], kAxis[ax.c]};
    else if (kind == "ROW") allowed = {kAxis[ax.a], kAxis[ax.b], "D", "NUM", "ROT", kAxis[ax.c]};
    else if (kind == "PAT") allowed = {kAxis[ax.a], kAxis[ax.b], "DX", "DY", "NUMX", "NUMY", "ROT", "ROTX", "ROTY", kAxis[ax.c]};
    else if (kind == "CIRC") allowed = {kAxis[ax.a], kAxis[ax.b], "D", "START", "NUM", kAxis[ax.c]};
    else if (kind == "PITCHCIRC") allowed = {kAxis[ax.a], kAxis[ax.b], "D", "START", "STEP", "NUM", kAxis[ax.c]};
    else if (kind == "FRAME")
        fail(code::unsupported_block, "PATTERN DEF FRAME is not supported by toolcomp yet (the order of its points)", head.column);
    else
        fail(code::bad_word, "PATTERN DEF: unknown pattern '" + kind + "'", head.column);
    for (const Token& k : v)
        if (std::find(allowed.begin(), allowed.end(), k.key) == allowed.end() || !k.has_value)
            fail(code::bad_word, (k.key.empty() ? std::string("A number") : k.key.str()) + " is not read in a " + kind + " pattern",
                 k.column);
    auto get = [&](std::string_view key, std::optional<double> otherwise = std::nullopt) {
        if (const auto x = number(v, key)) return *x;
        if (!otherwise) fail(code::missing_value, "PATTERN DEF " + kind + ": " + std::string(key) + " missing", head.column);
        return *otherwise;
    };
    auto count = [&](std::string_view key) {
        const double n = get(key);
        if (n < 1 || n != std::floor(n) || n > static_cast<double>(kMaxPatternPoints))
            fail(code::cycle_bad_value, "PATTERN DEF " + kind + ": " + std::string(key) + " is a number of points, 1 or more",
                 head.column);
        return static_cast<int>(n);
    };
    const double z = get(kAxis[ax.c], 0.0);
    auto add = [&](const Vec2& p) {
        if (pattern_.size() >= kMaxPatternPoints) fail(code::cycle_bad_value, "PATTERN DEF: more than 100000 points", head.column);
        pattern_.push_back({p, z});
    };
    if (kind == "POS") {  // incremental from the point before (the first: from the tool)
        const Vec2 before = pattern_.empty() ? plane2(pos_) : pattern_.back().at;
        Vec2 p;
        for (int i = 0; i < 2; ++i) {
            const int a = i == 0 ? ax.a : ax.b;
            if (const auto inc = number(v, kIncAxis[a])) p[i] = before[i] + *inc;
            else p[i] = get(kAxis[a]);
        }
        return add(p);
    }
    const Vec2 start(get(kAxis[ax.a]), get(kAxis[ax.b]));
    if (kind == "ROW") {
        const int n = count("NUM");
        for (int i = 0; i < n; ++i) add(start + rotated({i * get("D"), 0}, get("ROT", 0.0)));
    } else if (kind == "PAT") {  // row by row, each back the way the one before came (as cycle 221)
        if (get("ROTX", 0.0) != 0 || get("ROTY", 0.0) != 0)
            fail(code::unsupported_word, "PATTERN DEF PAT with ROTX / ROTY (a sheared grid) is not supported by toolcomp yet",
                 head.column);
        const int nx = count("NUMX"), ny = count("NUMY");
        if (static_cast<double>(nx) * ny + static_cast<double>(pattern_.size()) > static_cast<double>(kMaxPatternPoints))
            fail(code::cycle_bad_value, "PATTERN DEF: more than 100000 points", head.column);
        for (const Vec2& p : meander(start, {get("DX"), get("DY")}, nx, ny, get("ROT", 0.0))) add(p);
    } else {  // CIRC: NUM points evenly on the full circle; PITCHCIRC: STEP apart
        const int n = count("NUM");
        const double step = kind == "CIRC" ? 360.0 / n : get("STEP");
        for (int i = 0; i < n; ++i) add(start + rotated({get("D") / 2, 0}, get("START") + i * step));
    }
}

// CYCL CALL PAT: at each point, up to the safe height (the tool's height at the call, or the
// cycle's 2nd set-up clearance if higher) if below it, over to the point, the cycle.
void Interp::call_pattern(Tokens t) {
    const CycleDef& d = machining_cycle(t[0].column, "CYCL CALL PAT");
    if (pattern_.empty()) fail(code::unsupported_block, "CYCL CALL PAT without a PATTERN DEF", t[0].column);
    const double feed = call_feed(t, 3);
    const int c = axes(plane_).c;
    const double safe = std::max(pos_[c], d.q.at(203) + pattern_.front().z + d.q.at(204));
    const std::vector<PatternPoint> points = pattern_;
    for (const PatternPoint& p : points) {
        if (pos_[c] < safe) axis_move(safe, INFINITY);
        plane_move(p.at, feed);
        call_cycle(t[0].column, p.z);
    }
}

// CYCL DEF 220 POLAR PATTERN / 221 CARTESIAN PATTERN: the machining cycle defined before at
// each point, with the pattern's Q200, Q203, Q204; up to the 2nd set-up clearance first (if
// below it), between the points at the set-up clearance (Q301=0) or the 2nd (Q301=1), where
// the cycle ends each time. 221 runs its lines back and forth, from the start point.
void Interp::pattern_cycle(Tokens t, int number) {
    static const std::vector<int> k220{216, 217, 244, 245, 246, 247, 241, 200, 203, 204, 301},
        k221{225, 226, 237, 238, 242, 243, 224, 200, 203, 204, 301};
    const std::string name = "CYCL DEF " + std::to_string(number);
    const std::map<int, double> q = cycle_parameters(t);
    for (const auto& [n, v] : q)
        if (!std::isfinite(v)) fail(code::unsupported_word, name + ": Q" + std::to_string(n) + " takes a number", t[2].column);
    for (int n : number == 220 ? k220 : k221)
        if (!q.count(n)) fail(code::cycle_q_missing, name + ": Q" + std::to_string(n) + " missing", t[2].column);
    for (const auto& [n, v] : q) q_[n] = v;
    machining_cycle(t[0].column, name);
    CycleDef& d = *cycle_def_;
    if (q.count(365) && q.at(365) != 0)
        fail(code::unsupported_word, name + ": Q365=1 (from point to point on the circle) is not supported by toolcomp yet",
             t[0].column);
    if (q.at(301) != 0 && q.at(301) != 1) fail(code::cycle_bad_value, name + ": Q301 is 0 or 1", t[0].column);
    const PlaneAxes ax = axes(plane_);
    auto count = [&](int n) {
        if (q.at(n) < 1 || q.at(n) != std::floor(q.at(n)) || q.at(n) > static_cast<double>(kMaxPatternPoints))
            fail(code::cycle_bad_value, name + ": Q" + std::to_string(n) + " is a number of points, 1 or more", t[0].column);
        return static_cast<int>(q.at(n));
    };
    std::vector<Vec2> points;
    if (number == 220) {
        const int n = count(241);
        double step = q.at(247);
        if (step == 0) {
            const double sweep = q.at(246) - q.at(245);
            if (sweep == 0) fail(code::cycle_bad_value, name + ": the stopping angle Q246 equals the starting angle Q245", t[0].column);
            step = std::fabs(std::fabs(sweep) - 360) < 1e-9 ? sweep / n : n == 1 ? 0 : sweep / (n - 1);
        }
        const Vec2 centre(q.at(216), q.at(217));
        for (int i = 0; i < n; ++i) points.push_back(centre + rotated({q.at(244) / 2, 0}, q.at(245) + i * step));
    } else {
        const int nx = count(242), ny = count(243);
        if (static_cast<double>(nx) * ny > static_cast<double>(kMaxPatternPoints))
            fail(code::cycle_bad_value, name + ": more than 100000 points", t[0].column);
        points = meander({q.at(225), q.at(226)}, {q.at(237), q.at(238)}, nx, ny, q.at(224));
    }
    const CycleDef saved = d;
    for (int n : {200, 203, 204}) d.q[n] = q.at(n);
    const double surface = q.at(203);
    const double height = surface + (q.at(301) == 1 ? q.at(204) : q.at(200));
    if (pos_[ax.c] < surface + q.at(204)) axis_move(surface + q.at(204), INFINITY);
    for (const Vec2& p : points) {
        plane_move(p, INFINITY);
        call_cycle(t[0].column, 0, height);
    }
    *cycle_def_ = saved;
}

}  // namespace toolcomp::heidenhain
