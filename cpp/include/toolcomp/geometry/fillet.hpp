#pragma once
// Rounding a corner between two elements of a contour (Heidenhain RND, Sinumerik RND=):
// the rounding arc of radius rho between e1 (ending at the corner) and e2 (starting there):
// its centre lies at distance rho on the inner side s of the corner from both elements (the
// intersection of their equidistants: offset lines, or concentric circles of radius
// R - s·d·rho), the tangent points are the feet of that centre on the elements, and the
// elements are cut back to them. Of the candidate centres the one that cuts the least off
// the two elements is used; none within both elements: nullopt (radius too large).
#include <optional>

#include "toolcomp/geometry/element.hpp"

namespace toolcomp {

struct Fillet {
    Vec2 t1, t2, centre;  // the tangent points on e1 and e2, the arc's centre
    int dir;              // +1 counter-clockwise (a left turn), -1 clockwise
};

std::optional<Fillet> fillet(const Element2& e1, const Element2& e2, double rho);

}  // namespace toolcomp
