#pragma once
// ControlProfile: how a particular control behaves, as plain data.
//
// Geometry and stages never ask "which control is this?"; they read a profile value.
// Profiles for the built-in dialects come from profile_for(); users may adjust fields.
#include <string>

#include "toolcomp/program/dialect.hpp"

namespace toolcomp {

// Which axes a tool length offset (G43 H) acts on.
enum class LengthAxes {
    all = 0,           // the tool's whole offset vector (LinuxCNC: X..W from the tool table)
    z_only = 1,        // type A: the tool's length on Z whatever the plane (Fanuc default)
    plane_normal = 2,  // type B: the length on the axis normal to the active plane
};

struct ControlProfile {
    std::string name = "linuxcnc";

    // ---- interpreter ------------------------------------------------------------------
    bool startup_inch = false;  // G20 active at program start
    // Arc tolerances, in program units ([0] for mm programs, [1] for inch programs), as
    // LinuxCNC 2.9 applies them: an arc given by its centre is refused when its start and
    // end radius differ by more than `arc_spiral_hard_factor`·`arc_spiral_abs`, or by more
    // than `arc_spiral_abs` and more than `arc_spiral_rel` of the larger radius; otherwise
    // the control runs a slight spiral. Radii below `arc_min_radius` are zero-radius arcs;
    // an R-format chord may exceed 2|R| by `arc_min_radius`.
    double arc_spiral_abs[2] = {2 * 0.01 * 1.4142135623730951, 2 * 0.001 * 1.4142135623730951};
    double arc_spiral_rel = 0.001;
    double arc_spiral_hard_factor = 100;
    double arc_min_radius[2] = {0.00005 * 25.4, 0.00005};

    // ---- tool length compensation ------------------------------------------------------
    LengthAxes length_axes = LengthAxes::all;
    bool length_subtract_word = false;  // G44 (subtract the offset) exists

    // ---- cutter radius compensation (used by the radius stage) ---------------------------
    // Joints whose turn differs from a straight continuation by at most this angle (rad)
    // are tangent: nothing is inserted and the next element starts where the last ended.
    double corner_tolerance = 0.05;
    // A pulled-back arc may sweep this much (rad) more than programmed before it gouges.
    double arc_sweep_tolerance = 0.001;
};

ControlProfile profile_for(Dialect d);

}  // namespace toolcomp
