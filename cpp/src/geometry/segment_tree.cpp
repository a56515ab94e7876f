// Nearest-segment queries (see segment_tree.hpp): a box hierarchy split at the median of the
// longer side, searched nearest box first, boxes no nearer than the best so far skipped.
#include "toolcomp/geometry/segment_tree.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace toolcomp {

namespace {

constexpr std::size_t kLeaf = 4;  // segments a leaf holds at most

double cross(const Vec2& u, const Vec2& v) { return u.x() * v.y() - u.y() * v.x(); }

// Distance from p to segment ab and the nearest point of ab.
double point_segment(const Vec2& p, const Vec2& a, const Vec2& b, Vec2& nearest) {
    const Vec2 ab = b - a;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    nearest = a + t * ab;
    return (p - nearest).norm();
}

// The gap between boxes [alo, ahi] and [blo, bhi]: no point of one is nearer the other.
double box_gap(const Vec2& alo, const Vec2& ahi, const Vec2& blo, const Vec2& bhi) {
    const double dx = std::max({0.0, alo.x() - bhi.x(), blo.x() - ahi.x()});
    const double dy = std::max({0.0, alo.y() - bhi.y(), blo.y() - ahi.y()});
    return std::sqrt(dx * dx + dy * dy);
}

}  // namespace

SegmentGap segment_gap(const Vec2& a0, const Vec2& a1, const Vec2& b0, const Vec2& b1) {
    const Vec2 r = a1 - a0, s = b1 - b0;
    const double c0 = cross(r, b0 - a0), c1 = cross(r, b1 - a0);
    const double c2 = cross(s, a0 - b0), c3 = cross(s, a1 - b0);
    if (c0 * c1 < 0 && c2 * c3 < 0) return {0.0, a0 + (c2 / (c2 - c3)) * r};  // they cross
    // Else the nearest points include an end point of one of them.
    Vec2 x;
    SegmentGap best{point_segment(a0, b0, b1, x), a0};
    if (const double d = point_segment(a1, b0, b1, x); d < best.distance) best = {d, a1};
    if (const double d = point_segment(b0, a0, a1, x); d < best.distance) best = {d, x};
    if (const double d = point_segment(b1, a0, a1, x); d < best.distance) best = {d, x};
    return best;
}

namespace {

// Whether the direction v from the centre lies within the arc's sweep (cross products with
// its start and end radius vectors).
bool in_sweep(const PlaneArc& arc, const Vec2& u, const Vec2& w, const Vec2& v) {
    // A whole circle as the engine takes one (geometry/arc.cpp): an end within 1e-12 rad of
    // the start, on either side (a compensated circle's end misses its start by rounding).
    if (arc.full || (u.dot(w) > 0 && std::fabs(cross(u, w)) <= 1e-12 * u.norm() * w.norm())) return true;
    const double s = arc.dir > 0 ? 1.0 : -1.0;
    const bool major = s * cross(u, w) < 0;
    const double from_start = s * cross(u, v), to_end = s * cross(v, w);
    return major ? from_start >= 0 || to_end >= 0 : from_start >= 0 && to_end >= 0;
}

}  // namespace

SegmentGap arc_gap(const PlaneArc& arc, const Vec2& b0, const Vec2& b1) {
    const Vec2 u = arc.a0 - arc.c, w = arc.a1 - arc.c;
    const double r = u.norm();
    // The nearest point of the arc to q, and its distance.
    const auto to_arc = [&](const Vec2& q, Vec2& at) {
        const Vec2 v = q - arc.c;
        const double len = v.norm();
        if (len > 0 && in_sweep(arc, u, w, v)) {
            at = arc.c + (r / len) * v;
            return std::fabs(len - r);
        }
        const double d0 = (q - arc.a0).norm(), d1 = (q - arc.a1).norm();
        at = d0 <= d1 ? arc.a0 : arc.a1;
        return std::min(d0, d1);
    };
    Vec2 x, at;
    // The arc's ends against the segment.
    SegmentGap best{point_segment(arc.a0, b0, b1, x), arc.a0};
    if (const double d = point_segment(arc.a1, b0, b1, x); d < best.distance) best = {d, arc.a1};
    // The segment's ends, and its point nearest the centre, against the arc.
    if (const double d = to_arc(b0, at); d < best.distance) best = {d, at};
    if (const double d = to_arc(b1, at); d < best.distance) best = {d, at};
    Vec2 foot;
    point_segment(arc.c, b0, b1, foot);
    if (const double d = to_arc(foot, at); d < best.distance) best = {d, at};
    // Where the segment crosses the circle within the sweep: they touch.
    const Vec2 d = b1 - b0, f = b0 - arc.c;
    const double A = d.squaredNorm(), B = 2 * f.dot(d), C = f.squaredNorm() - r * r;
    const double disc = B * B - 4 * A * C;
    if (A > 0 && disc >= 0) {
        for (const double sign : {-1.0, 1.0}) {
            const double t = (-B + sign * std::sqrt(disc)) / (2 * A);
            const Vec2 p = b0 + t * d;
            if (t >= 0 && t <= 1 && in_sweep(arc, u, w, p - arc.c)) return {0.0, p};
        }
    }
    return best;
}

SegmentTree::SegmentTree(std::span<const Vec2> from, std::span<const Vec2> to)
    : from_(from.begin(), from.end()), to_(to.begin(), to.end()), order_(from.size()) {
    for (std::size_t i = 0; i < order_.size(); ++i) order_[i] = i;
    nodes_.reserve(2 * (order_.size() / kLeaf + 1));
    nodes_.push_back({});  // index 0: no child
    if (!order_.empty()) build(0, order_.size());
}

std::size_t SegmentTree::build(std::size_t a, std::size_t b) {
    Node n{Vec2::Constant(INFINITY), Vec2::Constant(-INFINITY), a, b};
    for (std::size_t i = a; i < b; ++i) {
        const std::size_t k = order_[i];
        n.lo = n.lo.cwiseMin(from_[k]).cwiseMin(to_[k]);
        n.hi = n.hi.cwiseMax(from_[k]).cwiseMax(to_[k]);
    }
    const std::size_t at = nodes_.size();
    nodes_.push_back(n);
    if (b - a <= kLeaf) return at;
    const int axis = n.hi.x() - n.lo.x() >= n.hi.y() - n.lo.y() ? 0 : 1;
    const std::size_t mid = a + (b - a) / 2;
    std::nth_element(order_.begin() + static_cast<std::ptrdiff_t>(a), order_.begin() + static_cast<std::ptrdiff_t>(mid),
                     order_.begin() + static_cast<std::ptrdiff_t>(b), [&](std::size_t i, std::size_t j) {
                         return from_[i][axis] + to_[i][axis] < from_[j][axis] + to_[j][axis];
                     });
    const std::size_t left = build(a, mid);
    const std::size_t right = build(mid, b);
    nodes_[at].left = left;
    nodes_[at].right = right;
    return at;
}

template <class Gap>
SegmentGap SegmentTree::search(const Vec2& lo, const Vec2& hi, SegmentGap best, const Gap& gap) const {
    if (nodes_.size() < 2) return best;
    std::size_t stack[128];
    std::size_t top = 0;
    stack[top++] = 1;
    while (top > 0) {
        const Node& n = nodes_[stack[--top]];
        if (box_gap(lo, hi, n.lo, n.hi) >= best.distance) continue;
        if (n.left == 0) {
            for (std::size_t i = n.a; i < n.b; ++i) {
                const std::size_t k = order_[i];
                const SegmentGap g = gap(from_[k], to_[k]);
                if (g.distance < best.distance) best = g;
            }
            continue;
        }
        // the nearer child on top: searched first, it tightens the bound for the other
        const double gl = box_gap(lo, hi, nodes_[n.left].lo, nodes_[n.left].hi);
        const double gr = box_gap(lo, hi, nodes_[n.right].lo, nodes_[n.right].hi);
        // A median split halves the segments each level: at most 64 levels, one stack entry
        // left behind on each.
        if (top + 2 > std::size(stack)) throw std::logic_error("SegmentTree: deeper than a median split allows");
        stack[top++] = gl <= gr ? n.right : n.left;
        stack[top++] = gl <= gr ? n.left : n.right;
    }
    return best;
}

SegmentGap SegmentTree::nearest(const Vec2& a0, const Vec2& a1, double limit) const {
    return search(a0.cwiseMin(a1), a0.cwiseMax(a1), {limit, a0},
                  [&](const Vec2& b0, const Vec2& b1) { return segment_gap(a0, a1, b0, b1); });
}

SegmentGap SegmentTree::nearest(const PlaneArc& arc, double limit) const {
    // the circle's box: around the arc, if loosely
    const double r = (arc.a0 - arc.c).norm();
    const Vec2 lo = arc.c.array() - r, hi = arc.c.array() + r;
    return search(lo, hi, {limit, arc.a0}, [&](const Vec2& b0, const Vec2& b1) { return arc_gap(arc, b0, b1); });
}

}  // namespace toolcomp
