#pragma once
// The choices a control makes in cutter radius compensation, by name: the profile's rules
// (control/profile.hpp) hold them, and a move may carry a program's own (RadiusRequest).

namespace toolcomp {

/// How a control finishes the activation block of radius compensation.
enum class EntryStyle {
    /// the activation block ends perpendicular to itself at its programmed end, then the
    /// corner rule joins it to the next element (LinuxCNC; Fanuc start-up type B; Sinumerik
    /// KONT)
    perpendicular_to_entry = 0,
    /// the activation block ends where the next element's equidistant starts, perpendicular
    /// to the next element (Fanuc start-up type A; Sinumerik NORM; Heidenhain RL/RR)
    perpendicular_to_next = 1,
    // Sinumerik KONT: as perpendicular_to_next, unless the start point lies behind the contour
    // (on the far side of the first element from the tool); then as perpendicular_to_entry, so
    // the tool goes round the contour start by the outside-corner rule (G450 circle, G451
    // intersection) instead of crossing the contour.
    /// Sinumerik KONT: as perpendicular_to_next, unless the start point lies behind the
    /// contour; then as perpendicular_to_entry, so the tool goes round the contour start by
    /// the outside-corner rule
    around_start_when_behind = 2,
};

/// How the compensated path leaves the contour when compensation is cancelled.
enum class ExitStyle {
    /// the last compensated move ends perpendicular to itself at its programmed end; the
    /// cancel move runs from there to its programmed end point (LinuxCNC; Fanuc type A)
    perpendicular_to_last = 0,
    /// the cancel move starts perpendicular to itself at its start, joined to the last move
    /// by the corner rule, and ends uncompensated (Fanuc type B)
    corner_with_exit = 1,
    // Sinumerik KONT: as perpendicular_to_last, unless the cancel move's end point lies behind
    // the contour (on the far side of the last contour point from the tool); then as
    // corner_with_exit, so the tool goes round the contour end by the outside-corner rule.
    /// Sinumerik KONT: as perpendicular_to_last, unless the cancel move's end point lies
    /// behind the contour; then as corner_with_exit, round the contour end by the
    /// outside-corner rule
    around_end_when_behind = 2,
};

// What fills the gap at an outside corner (spec §1.4.1).
/// What fills the gap at an outside corner of the compensated path.
enum class OutsideCorner {
    /// transition arc of the tool radius about the programmed corner
    arc = 0,
    /// meet at the intersection of the equidistants; turns sharper than corner_limit get
    /// the transition arc
    intersection = 1,
    /// intersection for turns up to corner_limit; sharper ones extend both elements by the
    /// radius and join the extensions with a line
    extension = 2,
};

// What the control does when the compensated tool cannot reach part of the contour (a
// step or groove narrower than the tool, an inside corner without an intersection).
/// What the control does when the compensated tool cannot reach part of the contour.
enum class GougeReaction {
    /// stop with the control's alarm (LinuxCNC, Fanuc, Heidenhain default)
    error = 0,
    /// leave out the unreachable elements and join the neighbours where their equidistants
    /// cross, within the look-ahead (Sinumerik CDON, Heidenhain M120)
    skip = 1,
    /// keep the path as computed (it gouges) and report a warning
    report = 2,
};

}  // namespace toolcomp
