#include "codes.hpp"

namespace toolcomp::iso {

int g_group(int c, const ControlProfile& p) {
    // G-code system A with the lathe cycles: G32 threading, G90 / G92 / G94 the turning,
    // threading and facing cycles, modal in group 01.
    if (p.g_code_system_a && p.turning_cycles && (c == G32 || c == G90 || c == G92 || c == G94)) return g_motion;
    // G73 pattern repeating, G74 / G75 peck drilling / grooving, G76 threading (group 00).
    if (p.g_code_system_a && p.turning_cycles && (c == G73 || c == G74 || c == G75 || c == G76)) return g_nonmodal;
    if (p.g_code_system_a && c == G75) return kUnsupported;
    switch (c) {
        case G4: case G10: case G28: case G28_1: case G30: case G30_1: case G53:
        case G92: case G92_1: case G92_2: case G92_3:
            return g_nonmodal;
        case G52: return p.g52_offset ? g_nonmodal : kUnsupported;
        case G70: case G71: case G72: return p.turning_cycles ? g_nonmodal : p.profile_cycles ? g_motion : kUnsupported;
        case G71_1: case G71_2: case G72_1: case G72_2: return p.profile_cycles ? g_motion : kUnsupported;
        case G50: return p.g_code_system_a ? g_nonmodal : kUnknown;  // lathe: coordinates, spindle clamp
        case G38_2: case G38_3: case G38_4: case G38_5:  // probing: refused when run (see interp.cpp)
        case G80: return p.cycles_own_group ? g_cycle : g_motion;
        case G0: case G1: case G2: case G3: case G73: case G74: case G81: case G82: case G83:
        case G84: case G85: case G86: case G87: case G88: case G89:
            return g_motion;
        case G17: case G18: case G19: return g_plane;
        case G90: case G91: return g_distance;
        case G90_1: case G91_1: return g_arc_distance;
        case G93: case G94: case G95: return g_feed_mode;
        case G20: case G21: return g_units;
        case G40: case G41: case G42: case G41_1: case G42_1: return g_radius_comp;
        case G43: case G43_1: case G43_2: case G49: return g_length_comp;
        case G44: return p.length_subtract_word ? g_length_comp : kUnknown;
        case G65: return p.macro_calls ? g_nonmodal : kUnknown;
        case G66: case G66_1: case G67: return p.macro_calls ? kUnsupported : kUnknown;
        case G98: case G99: return g_retract;
        case G54: case G55: case G56: case G57: case G58: case G59: case G59_1: case G59_2: case G59_3:
            return g_coord_system;
        case G61: case G61_1: case G64: return g_path_control;
        case G96: case G97: return g_spindle_mode;
        case G7: case G8: return g_lathe_diameter;
        // Real LinuxCNC codes that toolcomp does not run yet: splines and NURBS, spindle-
        // synchronised motion, probing, threading, lathe cycles, rotated planes.
        case G33: case G33_1: case G76: return p.spindle_sync_motion ? g_motion : kUnsupported;
        case G5: case G5_1: case G5_2: return p.splines ? g_motion : kUnsupported;
        case G5_3: return p.splines ? g_nonmodal : kUnsupported;  // G5.3
        case G17_1: case G18_1: case G19_1:
        case G52_1: case G73_1: case G96_1:
            return kUnsupported;
        default:
            return kUnknown;
    }
}

int m_group(int c, const ControlProfile& p) {
    switch (c) {
        case M0: case M1: case M2: case M30: case M60: return m_stop;
        case M6: case M61: return m_tool_change;
        case M3: case M4: case M5: return m_spindle;
        case M7: case M8: case M9: return m_coolant;
        case M48: case M49: case M50: case M51: case M52: case M53: return m_override;
        case M62: case M63: case M64: case M65: case M66: case M67: case M68:
            return m_io;  // digital/analog I/O: no effect on the path (interp_machine.cpp)
        case M70: case M71: case M72: case M73:  // LinuxCNC: in M3-M5's group
            return p.modal_state_codes ? m_spindle : kUnsupported;
        case M19:  // LinuxCNC: M19 spindle orient, in M3-M5's group
            return p.spindle_orient ? m_spindle : kUnsupported;
        case M99: if (p.numbered_subprograms) return m_stop; [[fallthrough]];  // LinuxCNC: M99 in main = M2
        case M98: return p.m98_subprograms ? m_subprogram : kUnknown;
        case M800: case M801: return p.ttrc_check_codes ? m_checks : kUnknown;
        default:
            // M100-M199 are user programs on LinuxCNC: without them the code is unknown.
            return kUnknown;
    }
}

}  // namespace toolcomp::iso
