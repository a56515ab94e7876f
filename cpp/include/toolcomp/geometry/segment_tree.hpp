#pragma once
// Nearest-segment queries against a fixed set of plane segments (a part contour): a bounding
// box hierarchy built once, then for any query segment the nearest distance below a limit,
// in about log(size) box tests and a few exact distances. What toolcomp.testing's
// assert_no_gouge asks for every piece of a compensated path.
#include <cstddef>
#include <span>
#include <vector>

#include "toolcomp/geometry/vec.hpp"

namespace toolcomp {

// The distance between segments a0a1 and b0b1 (0 where they cross or touch) and the point of
// a0a1 where it is taken.
struct SegmentGap {
    double distance;
    Vec2 at;
};
SegmentGap segment_gap(const Vec2& a0, const Vec2& a1, const Vec2& b0, const Vec2& b1);

// A circular arc from a0 to a1 about c, counter-clockwise for dir > 0 (a whole circle when
// `full`, or when a1 is a0): its radius is |a0 - c| (an arc whose end radius differs by a
// rounding amount is taken as circular).
struct PlaneArc {
    Vec2 a0, a1, c;
    int dir = 1;
    bool full = false;
};
// The gap between an arc and segment b0b1 and the point of the arc where it is taken.
SegmentGap arc_gap(const PlaneArc& arc, const Vec2& b0, const Vec2& b1);

class SegmentTree {
public:
    // The segments from[i]..to[i].
    SegmentTree(std::span<const Vec2> from, std::span<const Vec2> to);
    // The nearest of the segments to a0a1 if it is nearer than `limit`: its gap (the first
    // segment in the tree's order at that distance); else a distance of `limit` or more.
    SegmentGap nearest(const Vec2& a0, const Vec2& a1, double limit) const;
    // The same for an arc.
    SegmentGap nearest(const PlaneArc& arc, double limit) const;

private:
    struct Node {
        Vec2 lo, hi;         // box around its segments
        std::size_t a, b;    // its segments: order_[a..b)
        std::size_t left = 0, right = 0;  // children (0: a leaf)
    };
    std::size_t build(std::size_t a, std::size_t b);
    template <class Gap>
    SegmentGap search(const Vec2& lo, const Vec2& hi, SegmentGap best, const Gap& gap) const;
    std::vector<Vec2> from_, to_;
    std::vector<std::size_t> order_;
    std::vector<Node> nodes_;
};

}  // namespace toolcomp
