#pragma once
// Constant surface speed (G96 on every control that has it): the spindle speed that keeps the
// cutting speed at the tool's radius.
#include <limits>

#include "toolcomp/geometry/vec.hpp"

namespace toolcomp {

// rev/min for `surface_speed` mm/min at `radius` mm from the spindle axis; infinite at the axis.
inline double css_rpm(double surface_speed, double radius) {
    return radius > 0 ? surface_speed / (2 * kPi * radius) : std::numeric_limits<double>::infinity();
}

}  // namespace toolcomp
