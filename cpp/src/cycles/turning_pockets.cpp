// Type II stock removal (Fanuc G71 / G72 with a P block moving along the cut too; Haas R1):
// a contour whose depth may go back and forth (pockets), its run along the cut never turning
// back. Planned in a frame where the cut runs along +U and the levels go deeper along +V,
// from the start point at the origin; the boundary of the stock is the approach line from
// the start point to the contour's first point, then the contour.
//
// A level cuts the stretch where the boundary lies deeper than it; where a hump of the
// contour splits a level in two, the pocket beyond is roughed after the one before it, each
// to its bottom (pocket by pocket). Each pass: down the wall (the approach line or the
// contour) to the level, the cut, up along the contour to the level before (no step is
// left, as the Haas manual describes type II), an escape straight back by the retract
// amount, a rapid back over the pass's start.
#include <algorithm>
#include <cmath>
#include <string>

#include "contour_math.hpp"
#include "turning_roughing.hpp"

namespace toolcomp::cycles {

namespace {
constexpr double kEps = kContourEps;

struct Piece {
    Vec2 from, end, center = Vec2::Zero();
    int dir = 0;  // 0: a line
    int line = 0;
    bool approach = false;  // the line from the start point to the contour
};

// A point on the boundary: s = piece index + fraction (ordered along the boundary).
struct Point {
    double s = 0;
    Vec2 p = Vec2::Zero();
};

struct Span {  // where a level lies short of the boundary: from the wall down to where it rises
    Point in, out;
};

// A pocket still to rough: its span at `level`, the level above it, and where its wall
// begins (the top of the hump before it).
struct Pending {
    Span span;
    long level = 0;
    Point top;
};

class Planner {
public:
    Planner(const Contour& contour, const Roughing& r) : contour_(contour), r_(r) {
        const Vec2 rough = r.allowance + r.rough_allowance;  // what the levels leave
        const Vec2 s = contour.start + rough;
        du_ = sign_of(contour.pieces.back().end.x() + rough.x() - r.start.x());
        dv_ = sign_of(contour.start.y() - r.start.y());
        if (dv_ == 0)
            throw CycleError{code::cycle_bad_value,
                             "PS0062 ILLEGAL COMMAND IN G71-G76: the contour starts level with the start point, so the "
                             "passes have no direction"};
        if (du_ == 0) not_monotonic(contour.pieces.back().line);
        approach_kind_ = r.rapid_infeed ? StepKind::rapid : StepKind::feed;
        // The contour may not begin behind the start point along the cut; the allowance may
        // put it there (the P block at A's Z, W > 0): the stock then begins above it.
        if ((contour.start.x() - r.start.x()) * du_ < -kEps) not_monotonic(contour.pieces.front().line);
        top_ = Vec2(std::min(0.0, local(s).x()), 0);
        add({top_, local(s), Vec2::Zero(), 0, contour.pieces.front().line, true});
        Vec2 from = local(s);
        for (const ContourPiece& p : contour.pieces) {
            const Vec2 end = local(p.end + rough);
            add({from, end, local(p.center + rough), p.dir * static_cast<int>(du_ * dv_), p.line});
            from = end;
        }
        double deepest = 0;
        for (const Piece& p : b_) deepest = std::max(deepest, p.end.y());
        if (deepest / r.depth > static_cast<double>(r.max_passes))
            throw CycleError{code::cycle_bad_value, "PS0062 ILLEGAL COMMAND IN G71-G76: more than " +
                                                        std::to_string(r.max_passes) + " passes"};
    }

    std::vector<Step> plan() {
        std::vector<Pending> pockets;
        rough({{{0, top_}, end_point()}, 0, {0, top_}}, pockets, true);
        while (!pockets.empty()) {
            const Pending p = pockets.back();
            pockets.pop_back();
            // Up to the level above the pocket, over to the top of the hump before it.
            const double clear = level_v(p.level) - r_.retract;
            move(StepKind::rapid, Vec2(cur_.x(), std::min(cur_.y(), clear)));
            move(StepKind::rapid, Vec2(p.top.p.x(), cur_.y()));
            rough(p, pockets, false);
        }
        finish(contour_);
        return std::move(out_);
    }

private:
    const Contour& contour_;
    const Roughing& r_;
    double du_ = 1, dv_ = 1;
    StepKind approach_kind_ = StepKind::rapid;
    std::vector<Piece> b_;
    std::vector<Step> out_;
    Vec2 cur_ = Vec2::Zero();
    Vec2 top_ = Vec2::Zero();  // where the stock's boundary begins: A, or above a contour behind it
    std::size_t passes_ = 0;

    Vec2 local(const Vec2& q) const { return {(q.x() - r_.start.x()) * du_, (q.y() - r_.start.y()) * dv_}; }
    Vec2 world(const Vec2& q) const { return {r_.start.x() + q.x() * du_, r_.start.y() + q.y() * dv_}; }
    double level_v(long k) const { return static_cast<double>(k) * r_.depth; }
    Point end_point() const { return {static_cast<double>(b_.size()), b_.back().end}; }

    // Adds a piece, an arc split where it turns in V so that every piece runs one way in V;
    // none may turn back along the cut.
    void add(const Piece& p) {
        if (p.end.x() - p.from.x() < -kEps) not_monotonic(p.line);
        if (p.dir == 0) {
            b_.push_back(p);
            return;
        }
        const double r = (p.from - p.center).norm();
        const double a0 = angle_of(p.from, p.center), sweep = swept(a0, angle_of(p.end, p.center), p.dir);
        if (sweep * r <= kEps) not_monotonic(p.line);  // a whole circle
        for (int k = 0; k < 4; k += 2)  // along the cut: angles 0 and 180 degrees
            if (const double t = swept(a0, k * kPi / 2, p.dir); t * r > kEps && (sweep - t) * r > kEps) not_monotonic(p.line);
        std::vector<double> cuts;
        for (int k = 1; k < 4; k += 2)  // in depth: 90 and 270 degrees
            if (const double t = swept(a0, k * kPi / 2, p.dir); t * r > kEps && (sweep - t) * r > kEps) cuts.push_back(t);
        std::sort(cuts.begin(), cuts.end());
        Vec2 from = p.from;
        for (double t : cuts) {
            const double a = a0 + p.dir * t;
            const Vec2 q = p.center + r * Vec2(std::cos(a), std::sin(a));
            b_.push_back({from, q, p.center, p.dir, p.line});
            from = q;
        }
        b_.push_back({from, p.end, p.center, p.dir, p.line});
    }

    // Where piece i meets the depth v (it runs one way in V and spans v).
    Point at_depth(std::size_t i, double v) const {
        const Piece& p = b_[i];
        const double f = p.from.y(), e = p.end.y();
        const double t = e == f ? 0.0 : std::clamp((v - f) / (e - f), 0.0, 1.0);
        Vec2 q = p.from + t * (p.end - p.from);
        if (p.dir != 0) {
            const double r = (p.from - p.center).norm(), dv = v - p.center.y();
            const double h = std::sqrt(std::max(0.0, r * r - dv * dv));
            const double lo = std::min(p.from.x(), p.end.x()), hi = std::max(p.from.x(), p.end.x());
            const double u1 = p.center.x() + h, u2 = p.center.x() - h;
            auto miss = [&](double u) { return std::max(lo - u, u - hi); };
            q = Vec2(std::clamp(miss(u1) <= miss(u2) ? u1 : u2, lo, hi), v);
        }
        return {static_cast<double>(i) + t, q};
    }

    // The spans of depth v between boundary points lo and hi.
    std::vector<Span> spans(double v, double lo, double hi) const {
        std::vector<Span> out;
        auto beyond = [&](const Vec2& q) { return q.y() > v + kEps; };
        bool inside = false;
        Point in;
        for (std::size_t i = 0; i < b_.size(); ++i) {
            const bool b0 = beyond(b_[i].from), b1 = beyond(b_[i].end);
            if (!b0 && b1) inside = true, in = at_depth(i, v);
            if (b0 && !b1 && inside) {
                out.push_back({in, at_depth(i, v)});
                inside = false;
            }
        }
        if (inside) out.push_back({in, end_point()});
        std::erase_if(out, [&](const Span& s) { return s.in.s < lo - kEps || s.out.s > hi + kEps; });
        return out;
    }

    void move(StepKind kind, const Vec2& to, const Piece* along = nullptr) {
        if ((to - cur_).norm() <= kEps) return;
        if (out_.size() >= r_.max_moves) throw MoveLimit{};
        Step s{kind, world(to)};
        if (along) s.line = along->line;
        if (kind == StepKind::arc) {
            s.center = world(along->center);
            s.dir = along->dir * static_cast<int>(du_ * dv_);
        }
        out_.push_back(s);
        cur_ = to;
    }

    // Along the boundary from a to b: the approach line at its own kind, the contour at feed.
    void follow(const Point& a, const Point& b) {
        if (b.s <= a.s) return;
        const auto first = static_cast<std::size_t>(std::floor(a.s));
        const auto last = static_cast<std::size_t>(std::ceil(b.s)) - 1;
        for (std::size_t i = first; i <= last && i < b_.size(); ++i) {
            const Piece& p = b_[i];
            const Vec2 to = i == last ? b.p : p.end;
            move(p.approach ? approach_kind_ : p.dir == 0 ? StepKind::feed : StepKind::arc, to, &p);
        }
    }

    // From a point where a cut ends, up along the contour while it rises, to depth v at most.
    Point climb(const Point& from, double v) const {
        Point at = from;
        for (auto i = static_cast<std::size_t>(std::floor(from.s)); i < b_.size(); ++i) {
            const Piece& p = b_[i];
            if (p.end.y() - p.from.y() > kEps) break;  // it dives: a pocket begins
            if (p.end.y() <= v + kEps) return p.end.y() < v ? at_depth(i, v) : Point{static_cast<double>(i + 1), p.end};
            at = {static_cast<double>(i + 1), p.end};
        }
        return at;
    }

    // The top of the hump between two spans of a level: the boundary's least depth there
    // (the last such point, where the wall of the next pocket begins).
    Point hump_top(const Point& a, const Point& b) const {
        Point best = a;
        for (auto i = static_cast<std::size_t>(std::floor(a.s)); i < b_.size() && static_cast<double>(i + 1) < b.s; ++i)
            if (b_[i].end.y() <= best.p.y() + kEps) best = {static_cast<double>(i + 1), b_[i].end};
        if (b.p.y() <= best.p.y() + kEps) best = b;
        return best;
    }

    // The levels of one pocket, from its wall's top down; a split leaves the pockets beyond
    // the first to `pending`, in the order they are to be cut.
    void rough(Pending p, std::vector<Pending>& pending, bool root) {
        Point wall = p.top;
        double lo = p.span.in.s, hi = p.span.out.s;
        const StepKind down = root ? approach_kind_ : StepKind::feed;
        for (long k = p.level + 1;; ++k) {
            const double v = level_v(k);
            std::vector<Span> s = spans(v, lo, hi);
            if (s.empty()) return;
            for (std::size_t j = s.size(); j-- > 1;) pending.push_back({s[j], k - 1, hump_top(s[j - 1].out, s[j].in)});
            const Span& span = s.front();
            if (++passes_ > r_.max_passes)
                throw CycleError{code::cycle_bad_value, "PS0062 ILLEGAL COMMAND IN G71-G76: more than " +
                                                            std::to_string(r_.max_passes) + " passes"};
            move(down, wall.p);
            follow(wall, span.in);
            move(StepKind::feed, span.out.p);
            const Point top = climb(span.out, level_v(k - 1));
            follow(span.out, top);
            move(StepKind::rapid, top.p - Vec2(0, r_.retract));
            move(StepKind::rapid, Vec2(span.in.p.x(), cur_.y()));
            wall = span.in;
            lo = span.in.s, hi = span.out.s;
        }
    }

    // The pass along the whole contour shifted by the finishing allowance (what the levels
    // left), from and back to the start point, above the stock.
    void finish(const Contour& contour) {
        const Piece& approach = b_.front();
        const Vec2 s = local(contour.start + r_.allowance);
        if (!(cur_.x() == 0 && s.x() == 0)) {
            move(StepKind::rapid, Vec2(cur_.x(), std::min(cur_.y(), 0.0)));
            move(StepKind::rapid, Vec2::Zero());
        }
        move(approach_kind_, s, &approach);
        for (const ContourPiece& c : contour.pieces) {
            const Piece p{cur_, local(c.end + r_.allowance), local(c.center + r_.allowance),
                          c.dir * static_cast<int>(du_ * dv_), c.line};
            move(p.dir == 0 ? StepKind::feed : StepKind::arc, p.end, &p);
        }
        move(StepKind::rapid, Vec2(cur_.x(), std::min(cur_.y(), 0.0)));
        move(StepKind::rapid, Vec2::Zero());
    }
};
}  // namespace

std::vector<Step> rough_type2(const Contour& contour, const Roughing& r) {
    check_roughing(contour, r);
    return Planner(contour, r).plan();
}

}  // namespace toolcomp::cycles
