// One block, in LinuxCNC's order of execution (the RS274/NGC "order of execution" table,
// rs274ngc's execute_block and convert_*): the checks, feed mode, F, S, T, M6/M61, spindle,
// coolant, overrides, dwell, plane, units, diameter mode, radius comp, length comp,
// coordinate system, path control, distance modes, retract mode, G10/G28/G30/G92 and the
// lathe cycles, motion, program stop/end. Each step is one call below; the order of the
// calls is the control's.
#include "interp.hpp"
#include "toolcomp/program/codes.hpp"

namespace toolcomp::iso {

namespace {

bool uses_axes_group0(int g0) {
    return g0 == G10 || g0 == G28 || g0 == G30 || g0 == G92 || g0 == G52 || g0 == G50 || g0 == G70 || g0 == G71 ||
           g0 == G72 || g0 == G73 || g0 == G74 || g0 == G75 || g0 == G76;
}

// A plain move (no G code but its motion, no M code) has none of the codes the modal steps
// check and set.
bool has_modal_codes(const BlockWords& bw) { return bw.modal_codes() || bw.m_codes(); }

}  // namespace

// Codes whose block's axis words are data, not a move: G10, G28, G30, G92 and the tool
// length offsets given as axis values (G43.1, G43.2).
bool Interp::axes_are_data(const BlockWords& bw) {
    const int lc = bw.g[g_length_comp];
    return uses_axes_group0(bw.g[g_nonmodal]) || lc == G43_1 || lc == G43_2;
}

bool Interp::execute(const BlockWords& bw) {
    const int motion_to_be = execute_head(bw);
    return motion_to_be == kBlockEnded || execute_tail(bw, motion_to_be);
}

// Steps 1-9: the checks, then feed and speed, the tool, the M codes (LinuxCNC's order up
// to its user and remapped M codes). Returns the block's motion, or kBlockEnded when an M72
// restore ended the block.
int Interp::execute_head(const BlockWords& bw) {
    block_tool_ = tool_;
    if (bw.thread_chamfer >= 0) thread_chamfer_on_ = bw.thread_chamfer == 1;
    if (bw.has_polar()) polar_checks(bw);
    if (profile_.g_code_system_a && bw.g_groups != 0) system_a_codes(bw);
    end_cycle_by_g80(bw);
    const int motion_to_be = check_motion_words(bw);
    check_words(bw, motion_to_be);
    spindle_choice(bw, motion_to_be);
    check_axis_letters(bw);
    refuse_under_radius_comp(bw);
    if (bw.m[m_io] >= 0) io_code(bw);
    set_feed(bw);                       // 2-3
    spindle_words(bw);                  // 4
    if (bw.has('T')) select_tool(bw);   // 5
    if (!has_modal_codes(bw)) return motion_to_be;
    tool_change_codes(bw);              // 6
    if (spindle_codes(bw)) return kBlockEnded;  // 7
    machine_.update(bw);  // 8-9: coolant and overrides (read by #<_flood>, #<_feed_override>, ...)
    return motion_to_be;
}

// Steps 10-21: dwell, the modes, G10/G28/G92 and the lathe cycles, the motion, the stop.
// False after M2/M30.
bool Interp::execute_tail(const BlockWords& bw, int motion_to_be) {
    if (bw.g[g_nonmodal] == G4) dwell_code(bw);  // 10
    if (has_modal_codes(bw)) set_modes(bw);      // 11-18
    if (bw.has('D') && profile_.d_word_alone && !profile_.t_offsets) {
        const int rc = bw.g[g_radius_comp];
        if (rc != G41 && rc != G41_1 && rc != G42 && rc != G42_1) modal_d_number(bw);
    }
    axis_data_codes(bw);  // 19
    if (!motion(bw, motion_to_be)) return true;  // 20 (false: a remapped motion's sub runs first)
    return stop_codes(bw);  // 21
}

// ---- the checks ------------------------------------------------------------------------

// G80 of group 09 (ControlProfile::cycles_own_group): the cycle ends, the group 01 mode
// before it is back.
void Interp::end_cycle_by_g80(const BlockWords& bw) {
    if (bw.g[g_cycle] == G80 && (is_cycle(st_.motion) || st_.motion == G80)) {
        st_.motion = plain_motion_;
        cycle_il_set_ = false;
    }
}

// The motion code with its axis words, G80, G4, G53, G52/G92. Returns the block's motion.
int Interp::check_motion_words(const BlockWords& bw) const {
    const int g0 = bw.g[g_nonmodal], motion_code = bw.g[g_motion], col0 = bw.g_column[g_nonmodal];
    const bool axes = bw.has_axis(), data_axes = axes_are_data(bw), bare = profile_.bare_motion_codes;
    if (motion_code >= 0 && motion_code != G80) {
        if (bare ? uses_axes_group0(g0) : data_axes && axes && !profile_.motion_beside_data_axes)
            fail(code::two_axis_codes, "Cannot use two g codes that both use axis values", col0);
        if (bare && !axes && motion_code != G0 && motion_code != G1 && motion_code != G2 && motion_code != G3 &&
            motion_code != G5_2 && !bw.machine_g && !is_profile_cycle(motion_code))
            // G5.2 P alone: the first control point's weight; a remap: its argspec; G7x: here
            fail(code::axes_missing, "All axes missing with motion code", bw.g_column[g_motion]);
    }
    if (motion_code == G80 && axes) fail(code::axis_with_g80, "Cannot use axis values with g80", bw.axis_column());
    const int motion_to_be = motion_of(bw);
    if (motion_to_be == G80 && axes && !data_axes)
        fail(code::axis_without_motion, "Cannot use axis values without a g code that uses them", bw.axis_column());
    if ((motion_code == G2 || motion_code == G3) && g0 == G4)
        fail(code::g4_with_arc, "G4 not allowed with G2 or G3 because they both use P", col0);
    if (g0 == G53) {
        if (!(motion_to_be == G0 || motion_to_be == G1)) fail(code::g53_motion, "Must use g0 or g1 with g53", col0);
        const bool incremental = bw.g[g_distance] >= 0 ? bw.g[g_distance] == G91 : st_.incremental;
        if (incremental) fail(code::g53_incremental, "Cannot use g53 incremental", col0);
    }
    if ((g0 == G92 || g0 == G52) && !axes) fail(code::g92_no_axes, "All axes missing with g52 or g92", col0);
    return motion_to_be;
}

// G96 without S; U, V, W: refused, or (ControlProfile::incremental_uw) the incremental X, Z.
void Interp::check_axis_letters(const BlockWords& bw) const {
    if (bw.g[g_spindle_mode] == G96 && !bw.has('S') && profile_.g96_needs_s)
        fail(code::g96_s_missing, "S word missing with G96", bw.g_column[g_spindle_mode]);
    if (!(bw.has('U') || bw.has('V') || bw.has('W'))) return;
    const char l = bw.has('U') ? 'U' : bw.has('V') ? 'V' : 'W';
    if (!profile_.incremental_uw || l == 'V')
        fail(code::unsupported_axis, std::string(1, l) + " axis words are not supported by toolcomp", bw[l].column);
    if ((bw.has('U') && bw.has('X')) || (bw.has('W') && bw.has('Z')))
        fail(code::absolute_and_incremental, "X and U (or Z and W) in one block", bw[l].column);
}

// What LinuxCNC refuses while the tool radius is compensated, as it works through a block:
// the M codes (I/O, tool change, overrides, in its order) and the plane before
// G40/G41/G42, the rest after them (so G40 G43 is allowed, G41 G43 is not, G40 G18 is not).
// G53 is refused with the move (motion_line).
void Interp::refuse_under_radius_comp(const BlockWords& bw) {
    const int comp_code = bw.g[g_radius_comp];
    const bool comp_before = comp_on(), comp_after = comp_code >= 0 ? comp_code != G40 : comp_before;
    const bool modal = has_modal_codes(bw);
    if (comp_before && modal) refuse_m_codes_under_comp(bw);
    if (comp_after && modal) refuse_modes_under_comp(bw, comp_before);
    if (comp_after && bw.g[g_motion] >= G38_2 && bw.g[g_motion] <= G38_5)
        fail(code::comp_probe, "Cannot probe with cutter radius comp on", bw.g_column[g_motion]);
}

void Interp::refuse_m_codes_under_comp(const BlockWords& bw) const {
    if (const int io = bw.m[m_io]; io >= 0) {
        const char* what = io == M62 ? "Cannot set motion output with cutter radius compensation on"
                         : io == M63 ? "Cannot set motion digital output with cutter radius compensation on"
                         : io <= M65 ? "Cannot set auxiliary digital output with cutter radius compensation on"
                         : io == M66 ? "Cannot wait for digital input with cutter radius compensation on"
                         : io == M67 ? "Cannot set motion analog output with cutter radius compensation on"
                                     : "Cannot set auxiliary analog output with cutter radius compensation on";
        fail(code::comp_io, what, bw.m_column[m_io]);
    }
    if (bw.m[m_tool_change] == M6)
        fail(code::comp_tool_change, "Cannot change tools with cutter radius compensation on", bw.m_column[m_tool_change]);
    // LinuxCNC 2.9 takes M61 here and loses the move held for the next corner (its position
    // is read back after a tool change): a wrong path, refused instead.
    if (bw.m[m_tool_change] == M61)
        fail(code::comp_m61,
             "Cannot set the tool number (M61) with cutter radius compensation on: LinuxCNC would lose the "
             "compensated move it holds",
             bw.m_column[m_tool_change]);
    if (const int ov = bw.m[m_override]; ov >= 0) {
        const bool enable = ov == M48 || (ov >= M50 && (!bw.has('P') || bw['P'].value != 0));
        fail(code::comp_overrides,
             enable ? "Cannot enable overrides with cutter radius compensation on"
                    : "Cannot disable overrides with cutter radius compensation on",
             bw.m_column[m_override]);
    }
    if (bw.g[g_plane] >= 0 && bw.g[g_plane] != (st_.plane == Plane::xy ? G17 : st_.plane == Plane::zx ? G18 : G19))
        fail(code::comp_plane_change, "Cannot change planes with cutter radius compensation on", bw.g_column[g_plane]);
}

void Interp::refuse_modes_under_comp(const BlockWords& bw, bool comp_before) {
    const int g0 = bw.g[g_nonmodal], col0 = bw.g_column[g_nonmodal];
    if (bw.g[g_length_comp] >= 0)
        fail(code::comp_tool_offset, "Cannot change tool offset with cutter radius compensation on",
             bw.g_column[g_length_comp]);
    const bool axis_offsets = g0 == G92 || g0 == G92_1 || g0 == G92_2 || g0 == G92_3 || g0 == G52;
    if ((axis_offsets || bw.g[g_coord_system] >= 0) && profile_.radius.offset_change_reenters) {
        // 9/Series: compensation ends here for the moment (the last move its exit) and the
        // first move in the new system is an entry.
        if (comp_before) {
            out().control({ControlKind::radius_off, line_, Vec3::Zero(), file_});
            comp_moved_ = false;
        }
    } else if (bw.g[g_coord_system] >= 0) {
        fail(code::comp_coord_system, "Cannot change coordinate systems with cutter radius compensation on",
             bw.g_column[g_coord_system]);
    }
    if (bw.g[g_path_control] >= 0)
        fail(code::comp_control_mode, "Cannot change control mode with cutter radius compensation on",
             bw.g_column[g_path_control]);
    if (bw.g[g_retract] >= 0)
        fail(code::comp_retract_mode, "Cannot change retract mode with cutter radius compensation on",
             bw.g_column[g_retract]);
    if (g0 == G10) {
        if (!profile_.radius.messages.g10.empty()) fail(code::comp_g10, profile_.radius.messages.g10, col0);
        // LinuxCNC refuses G10 L2/L20 of the active system (tool table edits pass)
        const int l = bw.has('L') ? int_value(bw['L'].value) : -1;
        const int p = bw.has('P') ? int_value_truncated(bw['P'].value) : -1;
        if ((l == 2 || l == 20) && (p == 0 || p == st_.coord_system))
            fail(code::comp_g10, "Cannot change the active coordinate system with cutter radius compensation on", col0);
    }
    if (g0 == G28 || g0 == G30) fail(code::comp_home, "Cannot use g28 or g30 with cutter radius comp", col0);
    if (axis_offsets && !profile_.radius.offset_change_reenters)
        fail(code::comp_axis_offsets, "Cannot change axis offsets with cutter radius comp", col0);
}

// ---- steps 2-9 ---------------------------------------------------------------------------

// Feed mode and F. LinuxCNC's feed rate in G93 is that of the last inverse-time move
// (motion_line, motion_arc): an F word there times its own block only.
void Interp::set_feed(const BlockWords& bw) {
    if (has_modal_codes(bw)) {
        if (bw.g[g_feed_mode] >= 0) {
            st_.feed_mode = bw.g[g_feed_mode];
            // (G93 too, unseen: inverse time needs an F in every feed block)
            if (profile_.feed_mode_clears_feed && st_.feed_mode != G93) feed_ = 0;  // an F here is read after it
        }
        if (profile_.t_offsets && bw.g[g_retract] >= 0)  // Fanuc lathes: G98 per minute, G99 per revolution
            st_.feed_mode = bw.g[g_retract] == G98 ? G94 : G95;
    }
    if (bw.has('F') && !(st_.feed_mode == G93 && profile_.feed_mode_clears_feed))
        feed_ = bw['F'].value * (st_.feed_mode == G93 ? 1.0 : scale());
}

// M6 (to the machine's tool change position first), M61; the 9/Series M800 / M801.
void Interp::tool_change_codes(const BlockWords& bw) {
    if (bw.m[m_tool_change] == M6 && opts_.machine) to_tool_change_position(bw.m_column[m_tool_change]);
    if (bw.m[m_tool_change] >= 0) change_tool(bw, bw.m[m_tool_change]);
    if (const int ch = bw.m[m_checks]; ch >= 0) {
        checks_ = ch == M801;
        radius_.checks = checks_;
    }
}

// M3, M4, M5, M19 and LinuxCNC's M70-M73: state of the machine, not of the path (the
// spindle direction matters to the boring cycles). True when an M72 restore ended the block.
bool Interp::spindle_codes(const BlockWords& bw) {
    const int sp = bw.m[m_spindle];
    if (sp >= M70) return modal_state(bw);
    if (sp >= 0) spindle_turn(bw, sp);
    return false;
}

// ---- steps 10-21 -------------------------------------------------------------------------

// G4. LinuxCNC keeps -1 for a missing P and reads any other value, negative ones too.
void Interp::dwell_code(const BlockWords& bw) {
    if (!bw.has('P') || (profile_.dwell_negative_p ? bw['P'].value == -1 : bw['P'].value < 0))
        fail(code::dwell_missing, "Dwell time missing with g4", bw.g_column[g_nonmodal]);
    dwell(bw['P'].value);
}

// 11-18: plane, units (an F in the same block was read in the old units, as LinuxCNC does),
// diameter mode, radius comp (requested here, applied by the compensation stage), length
// comp, coordinate system, path control, distance modes, retract mode.
void Interp::set_modes(const BlockWords& bw) {
    if (bw.g[g_units] >= 0) set_units(bw.g[g_units] == G20);
    if (bw.g[g_plane] >= 0) st_.plane = bw.g[g_plane] == G17 ? Plane::xy : bw.g[g_plane] == G18 ? Plane::zx : Plane::yz;
    if (bw.g[g_lathe_diameter] >= 0) {
        const bool d = bw.g[g_lathe_diameter] == G7;
        diameter_switched_ = d != st_.diameter;  // (LinuxCNC's G76 reads it)
        st_.diameter = d;
    }
    if (bw.g[g_radius_comp] >= 0) radius_comp(bw, bw.g[g_radius_comp]);
    if (bw.g[g_length_comp] >= 0) length_comp(bw, bw.g[g_length_comp]);
    if (const int c = bw.g[g_coord_system]; c >= 0) set_coord_system(c < G59 ? (c - G53) / 10 : 6 + (c - G59));
    if (bw.g[g_path_control] >= 0) set_path_control(bw);
    if (bw.g[g_distance] >= 0) st_.incremental = bw.g[g_distance] == G91;
    if (bw.g[g_arc_distance] >= 0) st_.arc_absolute = bw.g[g_arc_distance] == G90_1;
    if (bw.g[g_retract] >= 0 && !profile_.t_offsets) st_.retract_initial = bw.g[g_retract] == G98;
}

// G61, G61.1, G64 P Q: P and Q kept as given (LinuxCNC's M70 saves them).
void Interp::set_path_control(const BlockWords& bw) {
    st_.path_control = bw.g[g_path_control];
    if (st_.path_control != G64) return;
    const WordSlot p = bw['P'], q = bw['Q'];
    tolerance_ = p.set && p.value >= 0 ? p.value : 0;
    naivecam_ = q.set && q.value >= 0 ? q.value : p.set && p.value >= 0 ? p.value : 0;
    if (!warned_blending_) {  // once a run
        info(code::blending_not_modelled,
             "G64 blending is a tolerance of the executed path: toolcomp returns the programmed path",
             bw.g_column[g_path_control]);
        warned_blending_ = true;
    }
}

// 19: the codes of group 0 that read the axis words as data (G10, G28, G30, G92, G52), the
// Fanuc lathe's G50 and its cycles G70-G76, and G5.3.
void Interp::axis_data_codes(const BlockWords& bw) {
    const int g0 = bw.g[g_nonmodal];
    switch (g0) {
        case G10: g10(bw); break;
        case G28: case G28_1: case G30: case G30_1: home(bw, g0); break;
        case G92: case G92_1: case G92_2: case G92_3: case G52: g92(bw, g0); break;
        case G50: g50(bw); break;
        case G70: finishing_cycle(bw); break;
        case G71: case G72: roughing_cycle(bw, g0); break;
        case G76: threading_cycle(bw); break;
        case G5_3: nurbs_end(bw); break;
        case G73: pattern_cycle(bw); break;
        case G74: case G75: peck_cycle(bw, g0); break;
        default: break;
    }
}

// 20: the motion mode, then the move. False when a remapped motion code's subprogram runs
// before the block's stop.
bool Interp::motion(const BlockWords& bw, int motion_to_be) {
    const int motion_code = bw.g[g_motion];
    prev_motion_ = st_.motion;
    if (motion_code >= 0 && !is_cycle(motion_code)) cycle_il_set_ = false;
    if (motion_code >= 0) st_.motion = motion_code;
    if (motion_code == G0 || motion_code == G1 || motion_code == G2 || motion_code == G3) plain_motion_ = motion_code;
    // A motion code with its axis words (or, bare, without them: a zero-length move or a
    // whole circle), or axis words that are not data under a modal motion.
    const bool data_axes = axes_are_data(bw);
    const bool moves = profile_.bare_motion_codes
                           ? motion_to_be >= 0 && motion_to_be != G80 && (motion_code >= 0 || !data_axes)
                           : motion_to_be >= 0 && bw.has_axis() && !data_axes;
    if (profile_.profile_cycles && is_profile_cycle(motion_to_be)) {
        profile_cycle(bw, motion_to_be);  // with or without axis words
    } else if (moves) {
        return move(bw, motion_to_be);
    } else if ((motion_code == G2 || motion_code == G3) && (bw.has('I') || bw.has('J') || bw.has('K') || bw.has('R'))) {
        motion_arc(bw, motion_code);  // full circle given by its centre only
    }
    return true;
}

bool Interp::move(const BlockWords& bw, int motion_to_be) {
    switch (motion_to_be) {
        case G0: case G1: motion_line(bw, motion_to_be, bw.g[g_nonmodal] == G53); break;
        case G2: case G3: motion_arc(bw, motion_to_be); break;
        case G32: thread_line(bw); break;
        case G33: sync_line(bw); break;
        case G33_1: rigid_tap(bw); break;
        case G76: lcnc_threading(bw); break;
        case G38_2: case G38_3: case G38_4: case G38_5: probe(bw, motion_to_be); break;
        case G5: case G5_1: spline(bw, motion_to_be); break;
        case G5_2: nurbs_point(bw); break;
        case G90: case G92: case G94: single_cycle(bw, motion_to_be); break;
        default:
            if (!bw.machine_g) cycle(bw, motion_to_be);
            else return remapped_motion(bw);
            break;
    }
    return true;
}

// 21: M0, M1, M60 stop; M2, M30 (and M99 in the main program, as LinuxCNC standalone) end
// the program and its compensation. False after the end.
bool Interp::stop_codes(const BlockWords& bw) {
    const int stop = bw.m[m_stop];
    if (stop == M0 || stop == M1 || stop == M60) sink_.control({ControlKind::stop, line_, Vec3::Zero(), file_});
    if (stop == M99 && frames_.size() > 1)  // LinuxCNC: M99 not first in a subprogram's line
        fail(code::m99_in_sub, "Bug:  Reached convert_stop() from M99 as subprogram return", bw.m_column[m_stop]);
    if (stop == M2 || stop == M30 || stop == M99) {
        sink_.control({ControlKind::program_end, line_, Vec3::Zero(), file_});
        radius_ = {};  // M2/M30 end compensation (and reset the other modes)
        return false;
    }
    return true;
}

}  // namespace toolcomp::iso
