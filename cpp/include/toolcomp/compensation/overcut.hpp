#pragma once
// Local overcut watch of the radius stage: every compensated element (tool-centre path)
// against the programmed contour of its neighbours, the `neighbours` programmed elements
// before and after it. Where the tool centre comes closer to that contour than the radius
// (less the tolerance), the path cuts into the part: one warning per compensated element,
// with its smallest distance. Cheap: each element meets at most 2·neighbours + 2 others.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "toolcomp/geometry/element.hpp"
#include "toolcomp/program/diagnostic.hpp"

namespace toolcomp {

// An element with what the distance tests ask of it worked out once: an arc's start and end
// radius vectors and radii, its sweep, whether it is a whole circle or more than a half.
struct Swept {
    Element2 e;
    Vec2 u = Vec2::Zero(), w = Vec2::Zero();
    double r0 = 0, r1 = 0, spiral = 0;  // spiral: |r1 - r0|
    double sweep = 0;                   // worked out for spirals only (else 0)
    double len = 0;                     // a line's length
    bool full = false, major = false;
    Vec2 lo = Vec2::Zero(), hi = Vec2::Zero();  // a box around it (an arc's: exact for circular arcs)
    explicit Swept(const Element2& e);
};

// The gap between two elements' boxes, squared: no point of one comes closer to the other.
inline double box_gap2(const Swept& a, const Swept& b) {
    // Nested max (max_element's comparisons in its order): an initializer list is a loop.
    const double dx = std::max(std::max(0.0, a.lo.x() - b.hi.x()), b.lo.x() - a.hi.x());
    const double dy = std::max(std::max(0.0, a.lo.y() - b.hi.y()), b.lo.y() - a.hi.y());
    return dx * dx + dy * dy;
}

// Smallest distance between two elements (line segments or arcs, as they are swept). An arc
// whose end radius differs from its start radius (a spiral) is taken within that difference.
double element_distance(const Swept& a, const Swept& b);
inline double element_distance(const Element2& a, const Element2& b) { return element_distance(Swept(a), Swept(b)); }
// A cheap lower bound of that distance (<= 0 when nothing is known), without angles: the
// other element beyond a line's supporting line, a segment outside or inside an arc's
// circle, two arcs' circles apart or one within the other (an arc lies within the ring of
// its start and end radii), an arc about an end of a segment turning away from it. Most
// pairs the watch meets are settled by it. It stops at the first partial bound >= `enough`.
double distance_lower_bound(const Swept& a, const Swept& b, double enough = INFINITY);

class OvercutWatch {
public:
    // `tolerance` in program units; `neighbours` 0 switches the watch off.
    void configure(int neighbours, double tolerance) {
        neighbours_ = neighbours;
        tolerance_ = tolerance;
    }
    // A programmed plane element under compensation (in contour order).
    void programmed(const Element2& e, int line);
    // The joint before the last programmed element was taken as tangent although it turns:
    // the control's tangent rule moves the tool up to `slack` closer to both its elements.
    void tangent_slack(double slack);
    // A tool-centre element of radius r, of source line `line` of file `file` (Motion::file),
    // in path order (elements of no length are left out). `settled`: the programmed elements
    // there were when its end was settled (by the next one; a stage that looks further ahead
    // hands it over later): the programmed elements before and after it are counted from
    // there, so a longer look-ahead does not shift the window. Non-decreasing.
    void compensated(const Element2& e, int line, int file, double r, std::size_t settled);
    // Warnings for the elements whose neighbours have all been seen; `all`: compensation
    // ends, report every pending one and forget the contour. `mm` = mm per program unit.
    void report(std::vector<Diagnostic>& out, double mm, bool all);
    void scale(double f);

private:
    struct Prog {
        Swept e;
        int line;
        double slack;
    };
    struct Comp {
        Swept e;
        int line;
        int file;
        double r;
        std::size_t seen;  // programmed elements counted when it arrived
        double worst;      // smallest distance - (r - allowance) so far
        double dist;       // the distance there
        int near_line;     // and the programmed element's line
    };
    void check(Comp& c, const Prog& p) const;  // a box test first, then check_close()
    void check_close(Comp& c, const Prog& p, double closest) const;

    int neighbours_ = 0;
    double tolerance_ = 0;
    // A few elements each (no allocation once they have grown). prog_: the contour watched,
    // from neighbours + 2 before the last `settled` on (at most kLag more: a look-ahead is
    // below 128 blocks), those before wait to be dropped; comp_: from comp_head_ on, the
    // elements not yet reported.
    std::vector<Prog> prog_;
    std::vector<Comp> comp_;
    std::size_t comp_head_ = 0;
    std::size_t count_ = 0;    // programmed elements of the contour
    std::size_t settled_ = 0;  // the last compensated element's `settled`
    static constexpr std::size_t kLag = 128;
};

}  // namespace toolcomp
