#pragma once
// The choices a control makes in cutter radius compensation, by name: the profile's rules
// (control/profile.hpp) hold them, and a move may carry a program's own (RadiusRequest).

namespace toolcomp {

// How a control finishes the activation block of radius compensation (spec §1.6).
enum class EntryStyle {
    // The activation block ends perpendicular to itself at its programmed end, then the
    // ordinary corner rule joins it to the next element (LinuxCNC; Fanuc start-up type B;
    // Sinumerik KONT).
    perpendicular_to_entry = 0,
    // The activation block ends where the next element's equidistant starts, perpendicular
    // to the next element (Fanuc start-up type A; Sinumerik NORM; Heidenhain RL/RR).
    perpendicular_to_next = 1,
    // Sinumerik KONT: as perpendicular_to_next, unless the start point lies behind the contour
    // (on the far side of the first element from the tool); then as perpendicular_to_entry, so
    // the tool goes round the contour start by the outside-corner rule (G450 circle, G451
    // intersection) instead of crossing the contour.
    around_start_when_behind = 2,
};

// How the compensated path leaves the contour when compensation is cancelled (spec §1.6).
enum class ExitStyle {
    // The last compensated move ends perpendicular to itself at its programmed end; the
    // cancel move runs from there to its programmed end point (LinuxCNC; Fanuc type A).
    perpendicular_to_last = 0,
    // The cancel move starts perpendicular to itself at its start, joined to the last move by
    // the corner rule, and ends uncompensated (Fanuc type B).
    corner_with_exit = 1,
    // Sinumerik KONT: as perpendicular_to_last, unless the cancel move's end point lies behind
    // the contour (on the far side of the last contour point from the tool); then as
    // corner_with_exit, so the tool goes round the contour end by the outside-corner rule.
    around_end_when_behind = 2,
};

// What fills the gap at an outside corner (spec §1.4.1).
enum class OutsideCorner {
    arc = 0,           // transition arc of the tool radius about the programmed corner
    intersection = 1,  // meet at the intersection of the equidistants; sharper turns than
                       // `corner_limit` get the transition arc
    extension = 2,     // intersection for turns up to `corner_limit`; sharper ones extend both
                       // elements by r and join the extensions with a line
};

// What the control does when the compensated tool cannot reach part of the contour (a
// step or groove narrower than the tool, an inside corner without an intersection).
enum class GougeReaction {
    error = 0,   // stop with the control's alarm (LinuxCNC, Fanuc, Heidenhain default)
    skip = 1,    // leave out the unreachable elements and join the neighbours where their
                 // equidistants cross, within the look-ahead (Sinumerik CDON, Heidenhain M120)
    report = 2,  // keep the path as computed (it gouges) and report a warning
};

}  // namespace toolcomp
