#include "toolcomp/control/profile.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "toolcomp/geometry/vec.hpp"

namespace toolcomp {

namespace {
// Cutter compensation as Fanuc's type C and the 9/Series TTRC both apply it: type A entry,
// intersections at inside and obtuse outside corners, extension blocks at outside corners
// sharper than 90 degrees, side changes without G40, any plane, no arc in the entry block; two
// blocks without plane motion looked past, more may overcut (warning).
void compensation_type_c(RadiusRules& r) {
    r.yz_plane = true;
    r.side_change = true;
    r.entry = EntryStyle::perpendicular_to_next;
    r.entry_arc = false;
    r.outside_corner = OutsideCorner::extension;
    r.corner_limit = kPi / 2;
    r.max_non_plane_moves = 2;
    r.count_blocks_without_motion = true;
    r.non_plane_reaction = NonPlaneReaction::overcut;
}


// The start of every control's profile: its name and kind; a lathe starts in ZX (G18).
ControlProfile base_profile(Dialect d, MachineKind kind) {
    ControlProfile p;
    p.name = std::string(dialect_name(d));
    p.kind = kind;
    if (kind == MachineKind::lathe) p.startup_plane = Plane::zx;
    return p;
}

ControlProfile linuxcnc_profile(MachineKind kind) {
    ControlProfile p = base_profile(Dialect::linuxcnc, kind);
    // LinuxCNC 2.9's readings (rs274ngc: read_integer_value, is_near_int, read_g,
    // convert_dwell, convert_setup), its program end and error reporting.
    p.call_depth_limit = 9;  // the 10th nested call is "Too many subroutine levels"
    p.call_depth_message = "Too many subroutine levels";
    p.last_comment_only = true;
    p.feed_mode_clears_feed = true;
    p.bare_motion_codes = true;
    p.inverse_time_min_rate = 0.1;
    p.g96_needs_s = true;
    p.integer_word_slack = true;
    p.linuxcnc_g_numbers = true;
    p.max_m_code = 199;
    p.negative_l_refused = true;
    p.dwell_negative_p = true;
    p.program_end_required = true;
    p.errors_at_outermost_call = true;
    p.abort_comment = true;
    p.g52_offset = true;
    p.g84_axes_warning = true;
    p.g10_tool_table = true;
    p.numbered_subprograms = true;
    p.modal_state_codes = true;
    p.spindle_sync_motion = true;
    p.splines = true;
    p.profile_cycles = true;
    p.spindle_orient = true;
    p.tool_change_stops_spindle = true;
    p.fixed_m_codes.insert(p.fixed_m_codes.end(), {98, 99, 48, 49, 50, 51, 52, 53, 60, 61, 62, 63, 64, 65, 66, 67,
                                                   68, 70, 71, 72, 73});
    return p;
}

// Fanuc 0i/30i (and the Fanuc-compatible Haas NGC): M and T series.
ControlProfile fanuc_profile(MachineKind kind) {
    ControlProfile p = base_profile(Dialect::fanuc, kind);
    p.call_depth_limit = 10;  // nested M98 and G65 together
    p.macro_calls = true;
    p.m98_subprograms = true;
    p.fixed_m_codes.insert(p.fixed_m_codes.end(), {98, 99});
    p.last_g_code_wins = true;
    p.startup_motion = 0;  // G00 at power on (parameter G01 = 0)
    p.cycles_own_group = true;
    p.startup_retract_initial = kind == MachineKind::mill;  // G98 (on the T series G98 is feed per minute)
    p.g53_rapid = true;
    p.motion_beside_data_axes = true;
    p.d_word_alone = true;
    p.fanuc_g10 = true;
    p.dwell_x_seconds = true;
    p.arc_turns_word = false;
    // "Tool length compensation type A": the H value acts on Z; G44 subtracts.
    p.length_axes = LengthAxes::z_only;
    p.length_subtract_word = true;
    p.modal_offset_numbers = true;
    // Cutter compensation C; alarm texts as printed by 0i/30i series controls.
    RadiusRules& r = p.radius;
    compensation_type_c(r);
    r.messages.entry_arc = "PS0034 NO CIRC ALLOWED IN ST-UP/EXT BLK";
    r.messages.exit_arc = "PS0034 NO CIRC ALLOWED IN ST-UP/EXT BLK";
    r.messages.entry_too_short = "PS0041 INTERFERENCE IN CRC";
    r.messages.entry_arc_too_short = "PS0041 INTERFERENCE IN CRC";
    r.messages.arc_too_small = "PS0038 INTERFERENCE IN CIRCULAR BLOCK";
    r.messages.gouge_feed = r.messages.gouge_traverse = "PS0041 INTERFERENCE IN CRC";
    r.messages.gouge_arc = r.messages.arc_to_line = r.messages.arc_to_arc = "PS0033 NO INTERSECTION AT CRC";
    if (kind == MachineKind::lathe) {
        // T series: diameter X, U/W incremental, T with offset numbers, tip numbers in
        // Fanuc/Haas numbering, the offset's X and Z both act, G99 at power on (parameter
        // FPM), G-code system A.
        p.x_diameter = true;
        p.incremental_uw = true;
        p.t_offsets = true;
        p.startup_feed_per_rev = true;
        p.c_word_is_chamfer = true;
        p.length_axes = LengthAxes::all;
        r.tip_convention = TipConvention::fanuc;
        p.g_code_system_a = true;
        p.turning_cycles = true;
    }
    return p;
}

// Allen-Bradley 9/Series lathe: the Fanuc lathe's profile, with what the 9/Series does
// otherwise (its manual excerpt: TTRC, the T-word formats, M800/M801) and what toolcomp
// does not take over from the Fanuc without the 9/Series manual saying so.
ControlProfile rockwell_profile() {
    ControlProfile p = fanuc_profile(MachineKind::lathe);
    p.name = std::string(dialect_name(Dialect::rockwell));
    // The 9/Series' own: T-word format 2 (T0016: geometry and wear 16); TTRC's exit direction
    // words and re-entry on an offset change (side and radius changes without G40).
    p.t_format = 2;
    p.ttrc_check_codes = true;  // M800 / M801
    RadiusRules& r = p.radius;
    r.exit_direction_words = true;
    r.offset_change_reenters = true;
    // Fanuc readings the 9/Series excerpt does not confirm: left at toolcomp's defaults
    // (each refused or read the plain way, never guessed).
    const ControlProfile plain;
    p.call_depth_limit = plain.call_depth_limit;
    p.last_g_code_wins = plain.last_g_code_wins;
    p.startup_motion = plain.startup_motion;
    p.cycles_own_group = plain.cycles_own_group;
    p.startup_retract_initial = plain.startup_retract_initial;
    p.g53_rapid = plain.g53_rapid;
    p.motion_beside_data_axes = plain.motion_beside_data_axes;
    p.d_word_alone = plain.d_word_alone;
    p.fanuc_g10 = plain.fanuc_g10;
    p.dwell_x_seconds = plain.dwell_x_seconds;
    p.length_subtract_word = plain.length_subtract_word;
    p.modal_offset_numbers = plain.modal_offset_numbers;
    p.startup_feed_per_rev = plain.startup_feed_per_rev;
    p.c_word_is_chamfer = plain.c_word_is_chamfer;
    p.g_code_system_a = plain.g_code_system_a;
    p.turning_cycles = plain.turning_cycles;
    p.macro_calls = plain.macro_calls;
    p.m98_subprograms = plain.m98_subprograms;
    // The texts of the control's messages are not in the manual excerpt: these name the
    // condition.
    r.messages.entry_arc = "Block format error: TTRC entry in a circular block";
    r.messages.exit_arc = "Block format error: TTRC exit in a circular block";
    r.messages.gouge_feed = r.messages.gouge_traverse = r.messages.gouge_arc =
        "Backwards motion: the compensated move runs against the programmed move";
    r.messages.arc_to_line = r.messages.arc_to_arc = "Interference: the compensation vectors cross";
    r.messages.arc_too_small = "Circular departure too small: the tool radius does not fit the arc";
    r.messages.entry_too_short = r.messages.entry_arc_too_short =
        "Interference: the entry move is shorter than the tool radius";
    r.messages.g10 = "G10 is not allowed while TTRC is active";
    return p;
}

ControlProfile sinumerik_profile(MachineKind kind) {
    ControlProfile p = base_profile(Dialect::sinumerik, kind);
    p.fixed_m_codes.push_back(17);  // end of subprogram
    // 840D TRC with the power-on G groups: CUT2D, NORM (straight to the perpendicular
    // point at the contour start, perpendicular off the last contour point on G40),
    // G450 transition circles (G451 intersections are the `intersection` corner style
    // with `corner_limit`, beyond which the 840D inserts a circle), direct G41 <-> G42
    // change, any plane, selection and deselection only in straight blocks, bottleneck
    // detection (CDON) over CUTCOM_MAXNUM_CHECK_BLOCKS = 3 skipping what the tool
    // cannot reach, CUTCOM_MAXNUM_DUMMY_BLOCKS = 3 blocks without plane motion, and
    // L1 on the axis normal to the plane for milling tools (SD42940 = 0). Messages
    // carry the alarm numbers of spec 3.8; where the texts are not published they
    // name the condition.
    p.length_axes = LengthAxes::plane_normal;
    RadiusRules& r = p.radius;
    r.yz_plane = true;
    r.side_change = true;
    r.entry = EntryStyle::perpendicular_to_next;
    r.entry_arc = false;
    r.entry_length_check = false;
    r.exit = ExitStyle::perpendicular_to_last;
    r.outside_corner = OutsideCorner::arc;
    r.corner_limit = 100 * kPi / 180;
    r.gouge = GougeReaction::skip;
    r.lookahead = 3;
    r.max_non_plane_moves = 3;
    r.count_blocks_without_motion = true;
    r.non_plane_reaction = NonPlaneReaction::error;
    r.messages.entry_arc = "10753 TRC selection only possible in a linear block";
    r.messages.exit_arc = "10754 TRC deselection only possible in a linear block";
    r.messages.gouge_feed = r.messages.gouge_traverse = r.messages.gouge_arc = r.messages.arc_to_line =
        r.messages.arc_to_arc = r.messages.arc_too_small =
            "10751 Danger of collision: no intersection within the look-ahead of the bottleneck detection";
    r.messages.around_start = "10755 Selection via KONT not possible at the current start point";
    r.messages.around_end = "10756 Deselection via KONT not possible at the programmed end point";
    r.messages.too_many_non_plane = "10762 Too many empty blocks between two traversing blocks with active TRC";
    return p;
}

ControlProfile heidenhain_profile(MachineKind kind) {
    ControlProfile p = base_profile(Dialect::heidenhain, kind);
    // TNC 426: RL/RR act at the end of the first block (perpendicular at the programmed
    // point), R0 leaves the same way, RL <-> RR needs an R0 block between, no start in a
    // circle block, transition arcs at outside corners, TOOL RADIUS TOO LARGE where the
    // tool does not fit. Texts other than TOOL RADIUS TOO LARGE are not in the manuals
    // read: these name the condition.
    RadiusRules& r = p.radius;
    r.yz_plane = true;
    r.entry = EntryStyle::perpendicular_to_next;
    r.entry_arc = false;
    r.entry_length_check = false;
    r.exit_must_be_straight = false;  // DEP CT / LCT leave on an arc; R0 in a circle block is refused by the front end
    r.messages.entry_arc = "Radius compensation cannot start in a circle block";
    r.messages.exit_arc = "Radius compensation cannot end in a circle block";
    r.messages.side_change = "RL and RR must be separated by an R0 block";
    r.messages.gouge_feed = r.messages.gouge_traverse = r.messages.gouge_arc = r.messages.arc_to_line =
        r.messages.arc_to_arc = r.messages.arc_too_small = "TOOL RADIUS TOO LARGE";
    return p;
}
}  // namespace

ControlProfile profile_for(Dialect d, MachineKind kind) {
    switch (d) {
        case Dialect::linuxcnc: return linuxcnc_profile(kind);
        case Dialect::fanuc: return fanuc_profile(kind);
        case Dialect::rockwell: return rockwell_profile();  // a lathe control
        case Dialect::sinumerik: return sinumerik_profile(kind);
        case Dialect::heidenhain: return heidenhain_profile(kind);
    }
    return base_profile(d, kind);
}

void check_profile(const ControlProfile& p) {
    auto bad = [](const char* field, const std::string& rule, double v) {
        std::ostringstream os;
        os << "ControlProfile." << field << " must be " << rule << " (got " << v << ")";
        throw std::invalid_argument(os.str());
    };
    auto at_least = [&](const char* field, double v, double lo) {
        if (!std::isfinite(v) || v < lo) bad(field, lo == 0 ? "a finite number >= 0" : "a finite number >= " + std::to_string(lo), v);
    };
    auto within = [&](const char* field, double v, double lo, double hi, const char* rule) {
        if (!(v >= lo && v <= hi)) bad(field, rule, v);
    };
    const RadiusRules& r = p.radius;
    within("radius.corner_limit", r.corner_limit, 0, kPi, "an angle from 0 to pi (radians)");
    within("radius.corner_tolerance", r.corner_tolerance, 0, kPi / 2, "an angle from 0 to pi/2 (radians)");
    within("radius.disc", r.disc, 0, 100, "from 0 to 100");
    for (double v : r.arc_sweep_tolerance) at_least("radius.arc_sweep_tolerance", v, 0);
    at_least("radius.overcut_tolerance", r.overcut_tolerance, 0);
    at_least("radius.extension_min_length", r.extension_min_length, 0);
    if (r.max_non_plane_moves < -1) bad("radius.max_non_plane_moves", "-1 (no limit) or a count >= 0", r.max_non_plane_moves);
    if (r.overcut_neighbours < 0) bad("radius.overcut_neighbours", "a count >= 0 (0: the watch off)", r.overcut_neighbours);
    if (r.lookahead < 0) bad("radius.lookahead", "a count >= 0", r.lookahead);
    for (double v : p.arc_spiral_abs) at_least("arc_spiral_abs", v, 0);
    at_least("arc_spiral_rel", p.arc_spiral_rel, 0);
    at_least("arc_spiral_hard_factor", p.arc_spiral_hard_factor, 0);
    for (double v : p.arc_min_radius) at_least("arc_min_radius", v, 0);
    at_least("inverse_time_min_rate", p.inverse_time_min_rate, 0);
    if (p.wear_sign != 1 && p.wear_sign != -1) bad("wear_sign", "1 (the wear added) or -1 (subtracted)", p.wear_sign);
    if (r.overcut_neighbours > 1000) bad("radius.overcut_neighbours", "at most 1000", r.overcut_neighbours);
    if (r.lookahead > 1000) bad("radius.lookahead", "at most 1000", r.lookahead);
    if (p.call_depth_limit > kMaxCallDepthLimit)
        bad("call_depth_limit", "at most " + std::to_string(kMaxCallDepthLimit), static_cast<double>(p.call_depth_limit));
    if (p.cutting_edge_default < -1 || p.cutting_edge_default > 32000)
        bad("cutting_edge_default", "-1 (the D before the change), 0 (none) or an edge 1-32000", p.cutting_edge_default);
    at_least("turning_escape", p.turning_escape, 0);
    at_least("thread_chamfer", p.thread_chamfer, 0);
    at_least("thread_finish_allowance", p.thread_finish_allowance, 0);
    at_least("thread_min_cut", p.thread_min_cut, 0);
    if (!(p.thread_chamfer_angle > 0 && p.thread_chamfer_angle < 90))
        bad("thread_chamfer_angle", "above 0 and below 90 degrees", p.thread_chamfer_angle);
    if (p.startup_motion != 0 && p.startup_motion != 10 && p.startup_motion != 800)
        bad("startup_motion", "0 (G00), 10 (G01) or 800 (G80)", p.startup_motion);
    if (p.no_motion_limit < 1) bad("no_motion_limit", "a count >= 1", 0);
    if (p.block_limit < 1) bad("block_limit", "a count >= 1", 0);
    if (p.t_format < 0 || p.t_format > 6) bad("t_format", "0 (Fanuc) or a 9/Series format 1-6", p.t_format);
    if (p.tool_length_type < 0 || p.tool_length_type > 2) bad("tool_length_type", "0, 1 or 2", p.tool_length_type);
    const int c = p.tool_length_const < 0 ? -p.tool_length_const : p.tool_length_const;
    if (c != 0 && c != 17 && c != 18 && c != 19) bad("tool_length_const", "0, +-17, +-18 or +-19", p.tool_length_const);
}

}  // namespace toolcomp
