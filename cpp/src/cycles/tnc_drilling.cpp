// The TNC's drilling cycles (see tnc_drilling.hpp). The runs, as the TNC user manuals
// describe them (doc/heidenhain.md, "Fixed cycles", has the worked numbers and the choices
// where the manuals leave a detail open).
#include "tnc_drilling.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "toolcomp/program/codes.hpp"
#include "turning_roughing.hpp"  // CycleError

namespace toolcomp::cycles::tnc {

namespace {

constexpr double kRapid = std::numeric_limits<double>::infinity();
constexpr std::size_t kMaxPecks = 1'000'000;

[[noreturn]] void refuse(int cycle, const std::string& what) {
    throw CycleError{code::cycle_bad_value, "CYCL DEF " + std::to_string(cycle) + ": " + what};
}

double get(const QValues& q, int n, double otherwise) {
    const auto it = q.find(n);
    return it == q.end() ? otherwise : it->second;
}

// A retraction feed (Q208): 0 takes the plunging feed, MAX (+inf) is FMAX.
double retraction_feed(const QValues& q, double plunge, const Setting& s, double absent) {
    const double v = get(q, 208, absent);
    if (!std::isfinite(v)) return kRapid;
    return v == 0 ? plunge : v * s.feed_unit;
}

class Moves {
public:
    Moves(int cycle, std::size_t max_moves) : cycle_(cycle), max_(max_moves) {}
    void to(double z, double feed) {
        if (out.size() >= max_) throw MoveLimit{};
        if (out.size() > 4 * kMaxPecks) refuse(cycle_, "more than a million pecks");
        out.push_back({z, feed});
    }
    std::vector<AxialMove> out;

private:
    int cycle_;
    std::size_t max_;
};

// The plunges of 203 and 205: Q202 first, each next one smaller by Q212 but not below Q205,
// the last one what remains; the depths reached (below the start `top`, down to `bottom`).
std::vector<double> plunge_depths(int cycle, const QValues& q, double top, double bottom, std::size_t max_moves) {
    const double first = q.at(202), decrement = get(q, 212, 0), minimum = get(q, 205, 0);
    if (!(first > 0)) refuse(cycle, "the plunging depth Q202 must be above 0");
    if (decrement < 0 || minimum < 0) refuse(cycle, "the decrement Q212 and the minimum plunging depth Q205 must be 0 or more");
    std::vector<double> depths;
    double at = top;
    for (std::size_t k = 0; at > bottom; ++k) {
        if (k >= kMaxPecks) refuse(cycle, "more than a million pecks");
        if (k >= max_moves) throw MoveLimit{};
        double plunge = first - static_cast<double>(k) * decrement;
        if (minimum > 0) plunge = std::max(plunge, minimum);
        if (!(plunge > 0))
            refuse(cycle, "the decrement Q212 leaves no plunging depth before the depth is reached (Q205 is 0): "
                          "toolcomp refuses it");
        at = std::max(at - plunge, bottom);
        depths.push_back(at);
    }
    return depths;
}

std::vector<AxialMove> drilling_200(const QValues& q, const Setting& s) {
    const double clear = s.surface + q.at(200), bottom = s.surface + q.at(201);
    const double feed = q.at(206) * s.feed_unit;
    if (!(q.at(202) > 0)) refuse(200, "the plunging depth Q202 must be above 0");
    Moves m(200, s.max_moves);
    m.to(clear, kRapid);
    double at = s.surface;
    for (;;) {
        at = std::max(at - q.at(202), bottom);
        m.to(at, feed);
        if (at == bottom) break;
        m.to(clear, kRapid);           // chips out (dwell Q210)
        m.to(at + q.at(200), kRapid);  // back down, the set-up clearance above the last depth
    }
    return std::move(m.out);
}

std::vector<AxialMove> reaming_201(const QValues& q, const Setting& s) {
    const double feed = q.at(206) * s.feed_unit;
    return {{s.surface + q.at(200), kRapid}, {s.surface + q.at(201), feed},
            {s.surface + q.at(200), retraction_feed(q, feed, s, 0)}};
}

// 203: after a plunge, Q213 chip breaks (back by Q256) before the tool leaves the hole at
// Q208 to the set-up clearance and comes back at FMAX to Q200 above the depth reached.
std::vector<AxialMove> universal_drilling_203(const QValues& q, const Setting& s) {
    const double clear = s.surface + q.at(200), bottom = s.surface + q.at(201);
    const double feed = q.at(206) * s.feed_unit, back = retraction_feed(q, feed, s, 0);
    const double breaks = q.at(213), lift = get(q, 256, 0.2);
    if (breaks < 0 || breaks != std::floor(breaks)) refuse(203, "the number of chip breaks Q213 must be a whole number, 0 or more");
    if (lift < 0) refuse(203, "the chip breaking distance Q256 must be 0 or more");
    const std::vector<double> depths = plunge_depths(203, q, s.surface, bottom, s.max_moves);
    Moves m(203, s.max_moves);
    m.to(clear, kRapid);
    double done = 0;
    for (std::size_t i = 0; i < depths.size(); ++i) {
        m.to(depths[i], feed);
        if (i + 1 == depths.size()) break;
        if (done < breaks) {
            m.to(depths[i] + lift, back);  // chip break
            ++done;
        } else {
            m.to(clear, back);  // out of the hole (dwell Q210)
            m.to(depths[i] + q.at(200), kRapid);
            done = 0;
        }
    }
    m.to(clear, back);  // dwell Q211 at the bottom first
    return std::move(m.out);
}

// 205: after each plunge out of the hole at FMAX and back at FMAX to the advanced stop
// distance above the depth reached: Q258 the first time, Q259 the last, evenly between. With
// Q257 the chip is broken (back by Q256) every Q257 within a plunge. Q379: a pilot hole, the
// tool goes down to Q200 above it at Q253 and counts the depth from there.
std::vector<AxialMove> universal_pecking_205(const QValues& q, const Setting& s) {
    const double clear = s.surface + q.at(200), bottom = s.surface + q.at(201);
    const double feed = q.at(206) * s.feed_unit, back = retraction_feed(q, feed, s, kRapid);
    const double upper = q.at(258), lower = q.at(259), chip = q.at(257), lift = q.at(256);
    const double pilot = get(q, 379, 0);
    if (upper < 0 || lower < 0 || chip < 0 || lift < 0 || pilot < 0)
        refuse(205, "Q258, Q259, Q257, Q256 and Q379 must be 0 or more");
    if (get(q, 395, 0) != 0) refuse(205, "the depth reference Q395=1 (to the tool's cylindrical part) is not supported by toolcomp");
    const double top = s.surface - pilot;
    if (top <= bottom) refuse(205, "the deepened starting point Q379 is not above the depth");
    Moves m(205, s.max_moves);
    m.to(clear, kRapid);
    if (pilot > 0) {
        const auto f = q.find(253);
        if (f == q.end()) refuse(205, "Q379 needs the pre-positioning feed Q253");
        m.to(top + q.at(200), std::isfinite(f->second) ? f->second * s.feed_unit : kRapid);
    }
    const std::vector<double> depths = plunge_depths(205, q, top, bottom, s.max_moves);
    const std::size_t returns = depths.size() - 1;
    double at = top;
    for (std::size_t i = 0; i < depths.size(); ++i) {
        if (chip > 0)  // chip breaks inside the plunge, every Q257 of it
            for (double cut = at - chip; cut > depths[i] + 1e-9; cut -= chip) {
                if (m.out.size() > 4 * kMaxPecks) refuse(205, "more than a million chip breaks");
                m.to(cut, feed);
                m.to(cut + lift, feed);
            }
        m.to(depths[i], feed);
        at = depths[i];
        if (i + 1 == depths.size()) break;
        const double t = returns == 1 ? 0 : static_cast<double>(i) / static_cast<double>(returns - 1);
        m.to(clear, kRapid);
        m.to(at + upper + (lower - upper) * t, kRapid);
    }
    m.to(clear, back);  // dwell Q211 at the bottom first
    return std::move(m.out);
}

std::vector<AxialMove> tapping_207(const QValues& q, const Setting& s) {
    if (!(s.speed > 0)) refuse(207, "rigid tapping needs the spindle speed S");
    const double feed = std::fabs(q.at(239)) * s.speed * s.unit;  // a pitch a revolution, mm/min
    if (!(feed > 0)) refuse(207, "the thread pitch Q239 must not be 0");
    return {{s.surface + q.at(200), kRapid}, {s.surface + q.at(201), feed}, {s.surface + q.at(200), feed}};
}

}  // namespace

const std::vector<int>& required_q(int cycle) {
    static const std::vector<int> k200{200, 201, 206, 202, 203, 204}, k201{200, 201, 206, 203, 204},
        k203{200, 201, 206, 202, 203, 204, 212, 213, 205, 208},
        k205{200, 201, 206, 202, 203, 204, 212, 205, 258, 259, 257, 256}, k207{200, 201, 239, 203, 204},
        k208{200, 201, 206, 334, 203, 204, 335}, none{};
    switch (cycle) {
        case 200: return k200;
        case 201: return k201;
        case 203: return k203;
        case 205: return k205;
        case 207: return k207;
        case 208: return k208;
        default: return none;
    }
}

bool is_drilling(int cycle) { return cycle == 200 || cycle == 201 || cycle == 203 || cycle == 205 || cycle == 207; }

std::vector<AxialMove> drilling(int cycle, const QValues& q, const Setting& s) {
    std::vector<AxialMove> moves;
    switch (cycle) {
        case 200: moves = drilling_200(q, s); break;
        case 201: moves = reaming_201(q, s); break;
        case 203: moves = universal_drilling_203(q, s); break;
        case 205: moves = universal_pecking_205(q, s); break;
        case 207: moves = tapping_207(q, s); break;
        default: refuse(cycle, "not a drilling cycle");
    }
    moves.push_back({s.surface + std::max(q.at(200), q.at(204)), kRapid});
    return moves;
}

// Cycle 1: from the start Z0 (the set-up clearance above the surface) a plunge, back to Z0 at
// FMAX, down at FMAX to the advanced stop distance t above the depth reached (0.6 up to a
// depth of 30, else depth / 50 up to 7), the next plunge; at the bottom back to Z0.
std::vector<AxialMove> pecking_1(const QValues& lines, const Setting& s) {
    const double setup = std::fabs(lines.at(1)), depth = lines.at(2), peck = std::fabs(lines.at(3));
    const double feed = lines.at(5) * s.feed_unit;
    if (depth >= 0) refuse(1, "the depth must be negative (into the workpiece): toolcomp refuses it otherwise");
    if (!(peck > 0)) refuse(1, "the pecking depth must not be 0");
    if (!(feed > 0)) refuse(1, "the feed F must be above 0");
    const double surface = s.from - setup, bottom = surface + depth;
    const double mm = -depth * s.unit;
    const double t = (mm <= 30 ? 0.6 : std::min(mm / 50, 7.0)) / s.unit;
    Moves m(1, s.max_moves);
    double at = surface;
    for (;;) {
        at = std::max(at - peck, bottom);
        m.to(at, feed);
        if (at == bottom) break;
        m.to(s.from, kRapid);
        m.to(std::min(at + t, s.from), kRapid);
    }
    m.to(s.from, kRapid);  // dwell (1.4) first
    return std::move(m.out);
}

// Cycle 17: from the start Z0 down to the depth below the surface and back to Z0, a pitch a
// revolution.
std::vector<AxialMove> tapping_17(const QValues& lines, const Setting& s) {
    const double setup = std::fabs(lines.at(1)), depth = lines.at(2);
    if (depth >= 0) refuse(17, "the depth must be negative (into the workpiece): toolcomp refuses it otherwise");
    if (!(s.speed > 0)) refuse(17, "rigid tapping needs the spindle speed S");
    const double feed = std::fabs(lines.at(3)) * s.speed * s.unit;
    if (!(feed > 0)) refuse(17, "the thread pitch must not be 0");
    return {{s.from - setup + depth, feed}, {s.from, feed}};
}

// 208: the helix from the set-up clearance to the depth at Q334 a revolution (the tool centre
// on radius Q335/2 - R), a full circle at the bottom, back to the centre, out at FMAX.
BoreMilling bore_milling(const QValues& q, const Setting& s, double tool_radius) {
    BoreMilling b;
    const double diameter = q.at(335), pitch = q.at(334), rough = get(q, 342, 0), sense = get(q, 351, 1);
    if (!(pitch > 0)) refuse(208, "the infeed per helix Q334 must be above 0");
    if (sense != 1 && sense != -1) refuse(208, "Q351 is +1 (climb) or -1 (up-cut)");
    const double tool = 2 * tool_radius;
    if (diameter < tool - 1e-9) refuse(208, "the nominal diameter Q335 is smaller than the tool");
    if (rough == 0 && diameter > 2 * tool + 1e-9)
        refuse(208, "the nominal diameter Q335 is more than twice the tool diameter (with Q342 = 0 the TNC refuses it)");
    b.radius = std::max(0.0, diameter / 2 - tool_radius);
    if (b.radius < 1e-9) b.radius = 0;
    b.dir = static_cast<int>(sense);
    b.top = s.surface + q.at(200);
    b.bottom = s.surface + q.at(201);
    b.turns = (b.top - b.bottom) / pitch;
    if (b.turns > 1e6) refuse(208, "more than a million helix turns");
    b.feed = q.at(206) * s.feed_unit;
    if (!(b.feed > 0)) refuse(208, "the feed Q206 must be above 0");
    b.end = s.surface + std::max(q.at(200), q.at(204));
    return b;
}

}  // namespace toolcomp::cycles::tnc
