#pragma once
// ControlProfile: how a particular control behaves, as plain data.
//
// Geometry and stages never ask "which control is this?"; they read a profile value.
// Profiles for the built-in dialects come from profile_for(); users may adjust fields.
#include <cstddef>
#include <string>
#include <vector>

#include "toolcomp/compensation/nose.hpp"
#include "toolcomp/compensation/radius_styles.hpp"
#include "toolcomp/program/dialect.hpp"

namespace toolcomp {

/// Which axes a tool length offset (G43 H) acts on.
enum class LengthAxes {
    /// the tool's whole offset vector (LinuxCNC: X..W from the tool table)
    all = 0,
    /// type A: the tool's length on Z whatever the plane (Fanuc default)
    z_only = 1,
    /// type B: the length on the axis normal to the active plane
    plane_normal = 2,
};

// Error texts of the radius stage: each control's own wording.
struct RadiusMessages {
    std::string plane = "Cutter radius compensation allowed only in XY, XZ planes";
    std::string already_on = "Cannot turn cutter radius comp on when on";
    std::string entry_too_short = "Length of cutter compensation entry move is not greater than the tool radius";
    std::string entry_arc_too_short = "Radius of cutter compensation entry arc is not greater than the tool radius";
    std::string entry_arc = "";  // set when an arc may not switch compensation on
    std::string arc_too_small = "Tool radius not less than arc radius with comp";
    std::string gouge_feed = "Straight feed in concave corner cannot be reached by the tool without gouging";
    std::string gouge_traverse = "Straight traverse in concave corner cannot be reached by the tool without gouging";
    std::string gouge_arc = "Arc move in concave corner cannot be reached by the tool without gouging";
    std::string arc_to_line = "Arc to straight motion makes a corner the compensated tool can't fit in without gouging";
    std::string arc_to_arc = "Arc to arc motion makes a corner the compensated tool can't fit in without gouging";
    // printf format with the two radii in program units
    std::string arc_mismatch = "BUG: cutter compensation has generated an invalid arc with mismatched radii r1 %f r2 %f\n";
    std::string exit_arc = "The move just after exiting cutter compensation mode must be straight, not an arc";
    std::string too_many_non_plane = "Too many blocks without motion in the compensation plane";
    std::string g10 = "";  // set when G10 is refused whatever it changes
    std::string side_change = "";  // set when RL <-> RR needs a cancel block between
    // Set when the control refuses to go round the contour start (end) because the start
    // point of the activation move (end point of the cancel move) lies behind the contour
    // within the tool radius of that contour point: no room to go round (Sinumerik KONT).
    std::string around_start = "";
    std::string around_end = "";
};

// What happens when too many blocks without motion in the plane follow each other while
// compensating (the control cannot see where the contour goes on).
/// What happens when more than max_non_plane_moves blocks without motion in the plane follow
/// each other while compensating.
enum class NonPlaneReaction {
    /// refuse the program (Sinumerik alarm 10762)
    error = 0,
    /// end the held move perpendicular to its programmed end and warn (9/Series)
    overcut = 1,
};

/// How a control applies cutter radius compensation.
struct RadiusRules {
    /// compensation allowed in G19 (LinuxCNC refuses it)
    bool yz_plane = false;
    // G41 while G42 is on (and back) without G40 between: LinuxCNC and Heidenhain refuse it;
    // Fanuc, Sinumerik and the 9/Series end the old move perpendicular at its end, start the
    // new one perpendicular at its start and join the two with a line.
    /// G41 <-> G42 without G40 between is allowed: the old move ends perpendicular at its
    /// end, the new starts perpendicular at its start, joined by a line (Fanuc, Sinumerik,
    /// 9/Series); False refuses it (LinuxCNC, Heidenhain)
    bool side_change = false;
    /// EntryStyle: how the activation block of compensation ends
    EntryStyle entry = EntryStyle::perpendicular_to_entry;
    /// an arc may be the activation block (LinuxCNC: yes)
    bool entry_arc = true;
    /// the entry move must be longer than the tool radius (LinuxCNC)
    bool entry_length_check = true;
    /// ExitStyle: how the path leaves the contour when compensation is cancelled
    ExitStyle exit = ExitStyle::perpendicular_to_last;
    /// the move after the cancel (G40) may not be an arc
    bool exit_must_be_straight = true;
    // I/K (or I/J) in the cancel block give the direction in which the contour is taken to
    // go on, for the last move's end (9/Series exit modified with I/K).
    /// I/K (I/J) in the cancel block give the direction in which the contour is taken to go
    /// on, for the last compensated move's end (9/Series); False: they need an arc to use
    /// them
    bool exit_direction_words = false;
    /// a work offset change under compensation (G54-G59.3, G92...) ends it for the moment:
    /// the last move is the exit, the first move in the new system an entry (9/Series);
    /// False: refused (LinuxCNC, Fanuc)
    bool offset_change_reenters = false;
    // Lathe tools: how the table's tip numbers are read (the imaginary tip's direction).
    /// TipConvention: how lathe tip numbers (CuttingEdge.orientation) are read
    TipConvention tip_convention = TipConvention::linuxcnc;
    /// OutsideCorner: what fills the gap at an outside corner
    OutsideCorner outside_corner = OutsideCorner::arc;
    /// turn angle, radians, beyond which intersection/extension corners change rule (see
    /// OutsideCorner)
    double corner_limit = 0;  // rad, see OutsideCorner
    // Sinumerik DISC (0..100) with the transition arc between two straight moves: the corner
    // becomes a fillet of radius r·(1 − DISC/100) tangent to the extended equidistants, so
    // 0 is the transition arc about the corner and 100 the sharp intersection. (Siemens does
    // not publish its law; this one is continuous in DISC and exact at both ends.) Joints
    // with an arc keep the transition arc.
    /// Sinumerik DISC, 0..100: the corner between two straight moves becomes a fillet of
    /// radius r*(1 - DISC/100); 0 is the transition arc, 100 the sharp intersection
    double disc = 0;
    // Joints whose turn differs from a straight continuation by at most this angle (rad)
    // are tangent: nothing is inserted and the next element starts where the last ended.
    /// joints turning at most this much (radians) are tangent: nothing is inserted
    double corner_tolerance = 0.05;
    // A pulled-back arc may sweep this much (rad) more than programmed before it gouges,
    // [0] in mm programs, [1] in inch programs (LinuxCNC's constants: 0.0254 and 0.001).
    /// how much more (radians) a pulled-back arc may sweep than programmed before it
    /// gouges, as (mm programs, inch programs)
    double arc_sweep_tolerance[2] = {0.0254, 0.001};
    // Consecutive blocks without plane motion the control looks past; -1 = no limit
    // (LinuxCNC holds them all back with the plane move before them).
    /// consecutive blocks without plane motion the control looks past; -1 = no limit
    int max_non_plane_moves = -1;
    // Blocks that move nothing at all (M8, S500, G4, F alone; not assignments, calls or
    // comments) count among them (Fanuc, 9/Series, Sinumerik "empty blocks"); false: only
    // moves without plane motion count.
    /// blocks that move nothing (M8, S500, G4, F alone; not assignments, calls or comments)
    /// count among the blocks without plane motion (Fanuc, 9/Series, Sinumerik); False:
    /// only moves without plane motion count (LinuxCNC, Heidenhain)
    bool count_blocks_without_motion = false;
    /// plane moves looked at when an element turns out unreachable (LinuxCNC: 1)
    int lookahead = 1;
    /// GougeReaction: what happens when the tool cannot reach part of the contour
    GougeReaction gouge = GougeReaction::error;
    // Overcut watch (no control has one): a compensated element whose tool centre comes
    // closer than r - overcut_tolerance (mm) to the programmed contour of the
    // `overcut_neighbours` programmed elements before and after it (counted from where its
    // end was settled, whatever the look-ahead) gets a warning "comp_overcut" (LinuxCNC cuts
    // such paths without an error). 0 switches it off.
    /// programmed elements before and after each compensated one whose contour its tool
    /// centre is checked against (warning 'comp_overcut'); 0 = no check
    int overcut_neighbours = 3;
    /// mm the tool centre may come closer to that contour than the radius without a warning
    double overcut_tolerance = 1e-6;
    /// NonPlaneReaction: what happens beyond max_non_plane_moves
    NonPlaneReaction non_plane_reaction = NonPlaneReaction::error;
    // Heidenhain APPR/DEP readings the manuals leave open (spec §8): R of CT/LCT is the
    // contour radius (tool arc R - r) or the tool-centre radius; LCT tangency in tool-centre
    // space or on the contour circle.
    /// Heidenhain APPR/DEP CT and LCT: R is the contour radius (tool arc R - r) when True,
    /// the tool-centre radius when False
    bool ct_radius_on_contour = true;
    /// Heidenhain APPR/DEP LCT: tangency in tool-centre space when True, on the contour
    /// circle when False
    bool lct_tangency_tool_space = true;
    /// extension blocks: a middle block shorter than this in both plane axes is dropped, mm
    /// (9/Series AMP minimum)
    double extension_min_length = 0;
    RadiusMessages messages;
};

/// The kind of machine of a ControlProfile: mill or lathe.
enum class MachineKind {
    /// milling machine
    mill = 0,
    /// lathe (in the Fanuc profile: X diameters, incremental U/W, T-word offsets, Fanuc tip
    /// numbers)
    lathe = 1,
};

// The deepest call nesting a profile may allow: each level holds a frame of the interpreter
// (a few hundred bytes, more with local parameters); 10000 levels are a few MB.
inline constexpr std::size_t kMaxCallDepthLimit = 10'000;

/// How a particular control behaves, as plain data: the profile of a dialect ('linuxcnc',
/// 'fanuc', ...) and machine ('mill' or 'lathe'), whose fields may be adjusted and passed as
/// run(..., profile=...).
struct ControlProfile {
    /// profile name (the dialect's name for built-in profiles)
    std::string name = "linuxcnc";
    /// MachineKind: mill or lathe (fixed at construction)
    MachineKind kind = MachineKind::mill;

    // ---- interpreter ------------------------------------------------------------------
    /// G20 (inch) active at program start
    bool startup_inch = false;
    // The working plane at program start: G17 (XY) on mills, G18 (ZX) on lathes (Fanuc T,
    // 9/Series and Sinumerik lathes power up in it), so that R arcs and G41/G42 of a lathe
    // program without G18 act in the plane the control uses.
    /// the working plane at program start: 17 (XY, mills), 18 (ZX, lathes) or 19
    Plane startup_plane = Plane::xy;
    // Feed per revolution at program start (Fanuc T series: G99 is the power-on state, F0.2
    // is 0.2 mm a turn); false: per minute.
    /// feed per revolution at program start (Fanuc lathes: G99 at power on)
    bool startup_feed_per_rev = false;
    // Blocks a program may execute (loops and repeats count every pass): beyond it the run
    // stops with an error instead of hanging. Subprogram calls nested deeper than
    // `call_depth_limit` (recursion without end) stop it the same way.
    /// blocks a program may execute (loops count)
    std::size_t block_limit = 100'000'000;
    /// nested subprogram calls a program may make (LinuxCNC 9, Fanuc 10, default 100; at
    /// most 10000)
    std::size_t call_depth_limit = 100;  // at most kMaxCallDepthLimit
    // Blocks executed in a row without a move: beyond it the run stops with "no_progress"
    // (a loop that never moves the tool; dialects/idle_watch.hpp). Loops that cut are bounded
    // by block_limit and max_segments only.
    /// blocks executed in a row without a move before the run stops with 'no_progress' (an
    /// endless loop that never moves the tool; default 10 000 000)
    std::size_t no_motion_limit = 10'000'000;
    // Comments read for (MSG, ...), (DEBUG, ...), (PRINT, ...): only the last one in
    // parentheses of a block, ';' comments never (LinuxCNC keeps one comment per block), or
    // every comment of the block (false).
    /// only the last comment in parentheses of a block is read for MSG/DEBUG/PRINT, ';'
    /// comments never (LinuxCNC); False: every comment
    bool last_comment_only = false;
    // A G94 or G95 word sets the feed rate to 0 (LinuxCNC, even when the mode does not
    // change): the next feed move needs an F word, which may stand in the same block. In
    // G93 the feed rate is then that of the last inverse-time move, not the F words.
    // Whether Fanuc controls do the same is not documented here: off for them.
    /// G94/G95 set the feed rate to 0, so the next feed move needs an F word (LinuxCNC)
    bool feed_mode_clears_feed = false;
    // A tool change (M6, M61) counts for G41/G42 without D and G43 without H (or H0) in its
    // own block (false), or only after the block (true: those take the tool that was in the
    // spindle before it, as LinuxCNC's rs274 and gcode module do, their tool data being
    // refreshed after a block).
    /// a tool change counts only after its block: G41/G42 without D and G43 without H
    /// beside M6/M61 take the tool in the spindle before it (rs274's way)
    bool tool_change_after_block = false;
    // How a block's motion code and axis words pair up. True (LinuxCNC): G0/G1/G2/G3 without
    // axis words is a move to where the tool is (a zero-length move; G2/G3 then need I/J/K
    // for a whole circle), any other motion code without axis words is refused ("All axes
    // missing with motion code"), I/J/K alone under a modal G2/G3 make an arc, and G43.1
    // beside a motion code takes its offset from the axis words the move goes to; G10, G28,
    // G30, G52 or G92 beside a motion code is refused with or without axis words. False: a
    // motion code without axis words only sets the mode.
    /// G0/G1/G2/G3 without axis words move to where the tool is, other motion codes need
    /// axis words, I/J/K alone under a modal G2/G3 make an arc (LinuxCNC); False: a motion
    /// code alone only sets the mode
    bool bare_motion_codes = false;
    // The least feed rate of an inverse-time (G93) move, in program units a minute: LinuxCNC
    // feeds a move shorter than 0.1/F (a zero-length one too) at 0.1.
    /// least feed rate of a G93 move, program units a minute (LinuxCNC 0.1)
    double inverse_time_min_rate = 0;
    // G96 needs its surface speed in the same block (LinuxCNC: "S word missing with G96");
    // false: the S word in force is the surface speed.
    /// G96 needs an S word in its block (LinuxCNC); False: the S in force is the surface speed
    bool g96_needs_s = false;

    // ---- how words are read (ISO dialects) ---------------------------------------------
    // Integer words with LinuxCNC's slack (dialects/iso/whole_numbers.hpp): M, T, H, L up to
    // 0.0001 off an integer, G41/G42 D within 0.0001 (is_near_int), G2/G3 P within 0.001,
    // M61 Q and G10 P taken to the nearest integer; false: as written, exactly whole.
    /// integer words with LinuxCNC's slack (M T H L within 0.0001, D is_near_int, G2/G3 P
    /// 0.001, M61 Q and G10 P to the nearest); False: exactly whole, as written
    bool integer_word_slack = false;
    // G numbers read as LinuxCNC reads them (G1.00001 is G1; "Unknown g code used" for the
    // rest); false: to a tenth, exactly.
    /// G numbers read as LinuxCNC's read_g does; False: to a tenth, exactly
    bool linuxcnc_g_numbers = false;
    // Two G codes of one modal group in a block: the last counts (Fanuc); false: refused
    // ("Two g codes used from same modal group"), G80 beside a motion code excepted.
    /// two G codes of one modal group in a block: the last counts (Fanuc); False: refused
    bool last_g_code_wins = false;
    // The highest M code number (LinuxCNC 199: "M-code greater than 199").
    /// the highest M code number (LinuxCNC 199)
    int max_m_code = 99999;
    // The motion mode at program start, as ten times its G code: 800 (G80: axis words need a
    // motion code first, as LinuxCNC starts) or 0 (G00, Fanuc's power-on mode).
    /// the motion mode at start, ten times its G code: 800 (G80: axis words need a motion
    /// code, LinuxCNC) or 0 (G00, Fanuc)
    int startup_motion = 800;
    // Canned cycles return to the initial level (G98) at program start (Fanuc M series);
    // false: to the R point (G99), as LinuxCNC starts.
    /// canned cycles return to the initial level (G98) at start (Fanuc mill); False: G99 (LinuxCNC)
    bool startup_retract_initial = false;
    // G80 is G group 09 with the canned cycles (Fanuc): it cancels a cycle and the motion mode
    // of group 01 (G00-G03) before the cycle is again in effect, so G80 beside G00 is no
    // conflict and axis words after G80 move; false: G80 is a motion mode of its own, axis
    // words after it are refused (LinuxCNC).
    /// G80 is group 09 with the cycles: it cancels a cycle and the G00-G03 mode before it
    /// is back (Fanuc)
    bool cycles_own_group = false;
    // A G00-G03 beside a code whose axis words are its data (G28, G30, G10, G92, G50) only
    // sets the motion mode: the axis words are that code's (Fanuc, "G0 G28 U0 W0"); false:
    // refused ("Cannot use two g codes that both use axis values", LinuxCNC).
    /// G00-G03 beside G28/G30/G10/G92/G50 only sets the mode, the axis words are that
    /// code's (Fanuc)
    bool motion_beside_data_axes = false;
    // G84 in G18 / G19 is reported: LinuxCNC 2.9 feeds its tap to the plane's coordinates in
    // another axis order (a warning with the point it goes to; the path keeps the tap on the
    // hole's axis).
    /// warn at G84 in G18/G19: LinuxCNC 2.9 feeds that tap along the plane's axes out of order
    bool g84_axes_warning = false;
    // G53 moves at rapid traverse whatever the motion mode (Fanuc); false: it needs G0 or G1
    // ("Must use g0 or g1 with g53", LinuxCNC).
    /// G53 moves at rapid whatever the motion mode (Fanuc); False: it needs G0 or G1 (LinuxCNC)
    bool g53_rapid = false;
    // A D word without G41/G42 sets the modal D number for the next G41/G42 (Fanuc, with
    // modal_offset_numbers: G43 H1 D1 at a tool change); false: refused as unused.
    /// a D word without G41/G42 sets the D number of the next G41/G42 (Fanuc)
    bool d_word_alone = false;
    // The codes beyond the ISO vocabulary every ISO control shares (codes.cpp):
    // G52 sets an offset of all coordinate systems as LinuxCNC runs it (false: refused, not
    // run by toolcomp);
    /// G52 offsets all coordinate systems as LinuxCNC runs it; False: refused (not run)
    bool g52_offset = false;
    // G65 calls a macro program, G66/G67 are its modal calls (refused: not run by toolcomp)
    // (Fanuc Macro B); false: unknown codes;
    /// G65 calls a macro program, G66/G67 (refused) are its modal calls (Fanuc); False:
    /// unknown codes
    bool macro_calls = false;
    /// M98 P calls a subprogram, M99 returns (Fanuc); False: unknown codes
    bool m98_subprograms = false;
    /// M800/M801 switch the TTRC checks off/on (9/Series); False: unknown codes
    bool ttrc_check_codes = false;
    // The M codes the control itself fixes: a machine builder cannot give them another
    // meaning (control/machine.hpp). M0, M1, M2, M30 everywhere; M98, M99 on the ISO
    // controls; M17 on the Sinumerik; LinuxCNC's own M48-M53, M60-M73.
    /// the M codes the control itself fixes, which a machine cannot declare
    std::vector<int> fixed_m_codes{0, 1, 2, 30};
    // G4 X (and U on lathes) is the dwell in seconds, P in milliseconds (Fanuc); false: G4 P
    // in seconds, X and U axis words.
    /// G4 X (U on lathes) is the dwell in seconds, P in milliseconds (Fanuc)
    bool dwell_x_seconds = false;
    // G2/G3 P is the number of turns (LinuxCNC); false: the control's arcs take no P (Fanuc,
    // 9/Series), and a P there is refused rather than read as turns.
    /// G2/G3 P is the number of turns (LinuxCNC); False: a P on an arc is refused
    bool arc_turns_word = true;
    // A C beside X/Z (U/W) in a lathe's G1 is the chamfer of the Fanuc T series (refused: not
    // run by toolcomp), not a C axis move.
    /// C beside X/Z in a lathe's G1 is the Fanuc T chamfer (refused), not a C axis move
    bool c_word_is_chamfer = false;
    // A negative L word is refused as it is read ("Negative l word used", LinuxCNC).
    /// a negative L word is refused as it is read (LinuxCNC)
    bool negative_l_refused = false;
    // G4 P: only -1 counts as missing, any other value is a dwell, negative ones too
    // (LinuxCNC); false: a negative P is missing.
    /// G4: only P-1 is missing, negative P dwells (LinuxCNC); False: a negative P is missing
    bool dwell_negative_p = false;
    // G10 L2 / L20 as Fanuc reads them: L20 sets the additional systems G54.1 and L2 P0 the
    // external offset (both refused: not run by toolcomp), P from 1 to 6, no R; in G91 the
    // L2 values add to the offset. False: LinuxCNC's G10 (L2 absolute even in G91, P0 the
    // active system, P up to 9, R the rotation).
    /// G10 L2/L20 as Fanuc reads them (L20 and L2 P0 refused, P 1-6, no R, L2 adds in G91);
    /// False: LinuxCNC's G10
    bool fanuc_g10 = false;
    // G10 L1 P<tool> X Y Z A B C R I J Q sets a tool's offsets in the run's copy of the tool
    // table, L10 and L11 from where the tool is (LinuxCNC). false: refused (not run).
    /// G10 L1/L10/L11 set a tool's offsets in the run's copy of the tool table (LinuxCNC);
    /// False: refused
    bool g10_tool_table = false;
    // LinuxCNC 2.9's Fanuc-style numbered subprograms: a bare O<n> line begins one, M98 P<n>
    // [L<count>] as a line's first word calls it (<n>.ngc on the search path first, else the
    // first O<n> after the call), M99 as a line's first word returns; #1-#30 are shared;
    // M99 in the main program ends it as M2 does.
    /// Fanuc-style numbered subprograms as LinuxCNC 2.9 reads them: O<n> ... M99, M98 P L
    /// as a line's first word
    bool numbered_subprograms = false;
    // LinuxCNC's M70 (save), M71 (invalidate), M72 (restore) and M73 (save, restored when the
    // subroutine returns) of the modal state, one snapshot per call level; a restore runs the
    // differences as G-code (interp_modal_state.cpp). false: M70-M73 are unknown M codes.
    /// M70-M73 save, invalidate and restore the modal state, M73 until the subroutine
    /// returns (LinuxCNC)
    bool modal_state_codes = false;
    // LinuxCNC's spindle-synchronised motion: G33 (K per revolution), G33.1 rigid tapping
    // (in and back out, I the return's speed factor) and the G76 threading cycle (P I J K R Q
    // H E L), modal in the motion group (interp_spindle_sync.cpp). false: refused.
    /// G33, G33.1 and the G76 threading cycle as LinuxCNC runs them; False: refused
    bool spindle_sync_motion = false;
    // LinuxCNC's G5 / G5.1 splines and G5.2 / G5.3 NURBS, as its machine cuts them: biarcs,
    // 4 spans per control point (interp_splines.cpp). false: refused.
    /// G5, G5.1 splines and G5.2/G5.3 NURBS as LinuxCNC's machine cuts them (biarcs);
    /// False: refused
    bool splines = false;
    // LinuxCNC's lathe profile cycles G70 (finishing), G71 / G72 (roughing) and G71.1 / G71.2
    // / G72.1 / G72.2 on a profile in O<Q> sub, in the motion group, computed as LinuxCNC
    // 2.9.10 computes them (interp_profile_cycles.cpp). false: refused.
    /// LinuxCNC's lathe profile cycles G70, G71, G72 and G71.1/.2, G72.1/.2; False: refused
    bool profile_cycles = false;
    // LinuxCNC's M19 R Q P [$]: the spindle stops and turns to angle R (P: 0 the shorter way,
    // 1 clockwise, 2 counter-clockwise; Q: the seconds to wait), in M3-M5's group; no move.
    // false: refused.
    /// LinuxCNC's M19 R Q P: the spindle stops, oriented (no move); False: refused
    bool spindle_orient = false;
    // M6 stops the spindle: a program turns it on again after the change (LinuxCNC without
    // [EMCIO]TOOL_CHANGE_WITH_SPINDLE_ON; read back by #<_spindle_on> and M70).
    /// M6 stops the spindle (LinuxCNC without TOOL_CHANGE_WITH_SPINDLE_ON)
    bool tool_change_stops_spindle = false;
    // A restore sets F and S always, not only when they differ (LinuxCNC from 2.9.1 on; the
    // 2.9.0 interpreter, the default, compares them).
    /// M72/M73 restores set F and S even when unchanged (LinuxCNC 2.9.1 on); False: only
    /// when they differ
    bool restore_feed_speed_always = false;

    // ---- how a program runs and ends (ISO dialects) -------------------------------------
    // A program must end with M2/M30 or '%' (LinuxCNC: "File ended with no percent sign or
    // program end").
    /// a program must end with M2/M30 or '%' (LinuxCNC)
    bool program_end_required = false;
    // An error inside called subroutines is reported at the main program's line of the
    // outermost call (LinuxCNC unwinds the calls before it reports); false: where it is.
    /// an error in a called subroutine is reported at the line of the outermost call (LinuxCNC)
    bool errors_at_outermost_call = false;
    /// (ABORT, text) stops the program with the text (LinuxCNC 2.9)
    bool abort_comment = false;
    // The text of the error for calls nested deeper than call_depth_limit ("" : toolcomp's
    // own, naming the limit; LinuxCNC: "Too many subroutine levels").
    /// the error text for calls nested too deep ('' : toolcomp's own, naming the limit)
    std::string call_depth_message;
    // Arc tolerances, in program units ([0] for mm programs, [1] for inch programs), as
    // LinuxCNC 2.9 applies them: an arc given by its centre is refused when its start and
    // end radius differ by more than `arc_spiral_hard_factor`·`arc_spiral_abs`, or by more
    // than `arc_spiral_abs` and more than `arc_spiral_rel` of the larger radius; otherwise
    // the control runs a slight spiral. Radii below `arc_min_radius` are zero-radius arcs;
    // an R-format chord may exceed 2|R| by `arc_min_radius`.
    /// an arc by its centre is refused when its start and end radius differ by more than
    /// this and by more than arc_spiral_rel of the larger radius, as (mm programs in mm,
    /// inch programs in inch); LinuxCNC 2.9: (0.0283, 0.00283)
    double arc_spiral_abs[2] = {2 * 0.01 * 1.4142135623730951, 2 * 0.001 * 1.4142135623730951};
    /// see arc_spiral_abs: the relative part of the test (LinuxCNC 2.9: 0.001)
    double arc_spiral_rel = 0.001;
    /// an arc whose start and end radius differ by more than this times arc_spiral_abs is
    /// refused whatever its radius (LinuxCNC 2.9: 100)
    double arc_spiral_hard_factor = 100;
    /// arcs of a smaller radius are zero-radius arcs, and an R-format chord may exceed 2|R|
    /// by this, as (mm programs in mm, inch programs in inch); LinuxCNC 2.9: (0.00127,
    /// 0.00005)
    double arc_min_radius[2] = {0.00005 * 25.4, 0.00005};

    // Lathes (Fanuc style): X words are diameters from the start; U and W are incremental X
    // and Z; a T word is tool and offset number (T0313: tool 3, offset 13) and applies the
    // offset at once (geometry + wear X and Z, nose radius and tip for G41/G42; no D word).
    /// lathe: X words are diameters
    bool x_diameter = false;
    /// lathe: U and W are incremental X and Z
    bool incremental_uw = false;
    /// lathe: a T word is tool and offset number (T0313: tool 3, offset 13) and applies the
    /// offset at once (geometry + wear X and Z, nose radius and tip; no D word)
    bool t_offsets = false;
    // Fanuc lathe G-code system A: G90, G92 and G94 are the turning, threading and facing
    // cycles (refused: toolcomp does not run them), G91 does not exist (U and W are the
    // increments). false: G90/G91 distance modes, G92 coordinate setting, G94 feed per minute.
    /// Fanuc lathe G-code system A: G90, G92 and G94 are the turning, threading and facing
    /// cycles (refused), G91 does not exist (U and W are the increments)
    bool g_code_system_a = false;
    // The Fanuc T series' multiple repetitive cycles: G70 finishing along the P..Q contour,
    // G71 / G72 stock removal in turning / facing (types I and II), in their two-block form
    // (G71 U R; G71 P Q U W F) and their one-block form (G71 P Q U W D F, Haas and older
    // Fanuc). false: refused (LinuxCNC's G70-G72 read other words).
    /// the Fanuc T series' lathe cycles G70-G76, G90/G92/G94 and G32
    bool turning_cycles = false;
    // The escape of a G71/G72 pass when the cycle gives no R (Fanuc parameter 5133, Haas
    // setting 73), in mm; the machine's value belongs in its machine file.
    /// the escape of a G71/G72 pass when the cycle gives no R, mm (Fanuc parameter 5133,
    /// Haas setting 73)
    double turning_escape = 1.0;
    // G41/G42 in a G71/G72 contour: the roughing passes (levels and contour pass) leave the
    // nose radius more allowance,
    // from the tip towards the nose's centre in each axis (Haas: "cutter compensation is
    // approximated by adjusting the roughing allowance according to the radius and tip type").
    // false: the passes follow the contour as programmed (Fanuc: the compensation of the
    // finishing shape is cancelled while roughing).
    /// G41/G42 in a G71/G72 contour: the roughing passes leave the nose radius more
    /// allowance (Haas)
    bool roughing_nose_allowance = false;
    // Threads (G92, the one-block G76): the pull-out chamfer at the thread's end, in leads
    // (Haas setting 95; 0: none), and its angle from the Z axis in degrees (setting 96);
    // Haas M23/M24 (machine actions thread_chamfer_on/off) switch it. The one-block G76's
    // finishing allowance (setting 86) and least depth of a pass (setting 99), in mm.
    // G73: after each pass but the last the tool goes back to the start point shifted as the
    // next pass is (Haas: "a rapid departure move ... to the Start position plus the offset
    // for the second roughing pass"). false: back to the start point itself.
    /// G73: after each pass the tool goes back to the start shifted as the next pass (Haas)
    bool pattern_return_shifted = false;
    // Heidenhain M89: the modal cycle call (iTNC MP7440 bit 0 = 0), the cycle runs after its
    // block and every positioning block until M99, CYCL CALL or a new CYCL DEF. false: M89 is
    // a free M function without effect on the path.
    /// Heidenhain M89 calls the cycle after every positioning block until M99 / CYCL CALL /
    /// CYCL DEF (false: a free M function)
    bool m89_modal_cycle_call = true;
    // Sinumerik MD20270 $MC_CUTTING_EDGE_DEFAULT: the edge a tool change (M6) selects: n, 0
    // none (no offset until a D), -1 the D number programmed before the change.
    /// Sinumerik MD20270: the edge M6 selects (n; 0 none; -1 the D number programmed before M6)
    int cutting_edge_default = 1;
    /// the pull-out chamfer at the end of G92 and one-block G76 threads, in leads (Haas
    /// setting 95; 0: none)
    double thread_chamfer = 0;
    /// the thread chamfer's angle from the Z axis, degrees (Haas setting 96)
    double thread_chamfer_angle = 45;
    /// the one-block G76's finishing allowance, mm (Haas setting 86)
    double thread_finish_allowance = 0;
    /// the one-block G76's least depth of a pass, mm (Haas setting 99)
    double thread_min_cut = 0;
    // H and D are modal offset numbers (Fanuc): G43/G44 without H take the last H, G41/G42
    // without D the last D, both 0 at the start, and H0/D0 are no offset. false: without H or D
    // the tool in the spindle gives them, and H0 is that tool too (LinuxCNC).
    /// H and D are modal offset numbers (Fanuc): G43/G44 without H take the last H, G41/G42
    /// without D the last D, both 0 at the start (no offset); False: the tool in the
    /// spindle (LinuxCNC)
    bool modal_offset_numbers = false;
    // How a T word splits into tool, geometry offset and wear offset numbers. 0: T<tool><offset>
    // with two offset digits, the offset giving geometry and wear (Fanuc). 1..6: the 9/Series
    // installer formats: 1-3 geometry and wear from the last 1, 2 or 3 digits; 4-6 wear from
    // the last 1, 2 or 3 digits and geometry from the tool number.
    /// how a T word splits into tool, geometry and wear offset numbers: 0 T<tool><two
    /// offset digits> (Fanuc); 1-3 geometry and wear from the last 1, 2 or 3 digits; 4-6
    /// wear from the last 1, 2 or 3 digits and geometry from the tool number (9/Series)
    int t_format = 0;
    /// effective offset = geometry + wear_sign * wear
    double wear_sign = 1;  // effective = geometry + wear_sign * wear (Sinumerik SD42930)

    // Sinumerik machine data of tool lengths (spec §3.2, §3.5): SD42940 TOOL_LENGTH_CONST
    // (0, ±17, ±18, ±19), SD42950 TOOL_LENGTH_TYPE (0 by tool type, 1 milling, 2 turning),
    // MD20360 TOOL_PARAMETER_DEF_MASK (bit 0 wear, bit 1 geometry in diameter; GETTCOR).
    /// Sinumerik SD42940 TOOL_LENGTH_CONST: 0, or 17/18/19 (and negative) to fix the length axes
    int tool_length_const = 0;
    /// Sinumerik SD42950 TOOL_LENGTH_TYPE: 0 by tool type, 1 always milling, 2 always turning
    int tool_length_type = 0;
    /// Sinumerik MD20360: bit 0 wear, bit 1 geometry in diameter on the transverse axis (GETTCOR)
    unsigned tool_parameter_def_mask = 0;

    // ---- tool length compensation ------------------------------------------------------
    /// LengthAxes: which axes a tool length offset (G43 H) acts on
    LengthAxes length_axes = LengthAxes::all;
    /// G44 (subtract the tool length offset) exists
    bool length_subtract_word = false;  // G44 (subtract the offset) exists; false: G44 is unknown

    // ---- cutter radius compensation (used by the radius stage) ---------------------------
    /// RadiusRules: the cutter radius compensation rules
    RadiusRules radius;
};

ControlProfile profile_for(Dialect d, MachineKind kind = MachineKind::mill);

// Throws std::invalid_argument naming the field when a setting cannot describe a control: a
// tolerance, angle or length that is not a finite number or is negative, DISC outside
// 0..100, a count or format out of its range. (A NaN tolerance would turn every comparison
// false: corners taken as tangent, a wrong path without a word.) run(), run_file() and
// PathStream check the profile they are given.
void check_profile(const ControlProfile& p);

}  // namespace toolcomp
