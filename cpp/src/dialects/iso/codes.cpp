#include "codes.hpp"

namespace toolcomp::iso {

int g_group(int c, const ControlProfile& p) {
    // G-code system A with the lathe cycles: G32 threading, G90 / G92 / G94 the turning,
    // threading and facing cycles, modal in group 01.
    if (p.g_code_system_a && p.turning_cycles && (c == 320 || c == 900 || c == 920 || c == 940)) return g_motion;
    // G73 pattern repeating, G74 / G75 peck drilling / grooving, G76 threading (group 00).
    if (p.g_code_system_a && p.turning_cycles && (c == 730 || c == 740 || c == 750 || c == 760)) return g_nonmodal;
    if (p.g_code_system_a && c == 750) return kUnsupported;
    switch (c) {
        case 40: case 100: case 280: case 281: case 300: case 301: case 530:
        case 920: case 921: case 922: case 923:
            return g_nonmodal;
        case 520: return p.g52_offset ? g_nonmodal : kUnsupported;
        case 700: case 710: case 720: return p.turning_cycles ? g_nonmodal : p.profile_cycles ? g_motion : kUnsupported;
        case 711: case 712: case 721: case 722: return p.profile_cycles ? g_motion : kUnsupported;
        case 500: return p.g_code_system_a ? g_nonmodal : kUnknown;  // lathe: coordinates, spindle clamp
        case 382: case 383: case 384: case 385:  // probing: refused when run (see interp.cpp)
        case 800: return p.cycles_own_group ? g_cycle : g_motion;
        case 0: case 10: case 20: case 30: case 730: case 740: case 810: case 820: case 830:
        case 840: case 850: case 860: case 870: case 880: case 890:
            return g_motion;
        case 170: case 180: case 190: return g_plane;
        case 900: case 910: return g_distance;
        case 901: case 911: return g_arc_distance;
        case 930: case 940: case 950: return g_feed_mode;
        case 200: case 210: return g_units;
        case 400: case 410: case 420: case 411: case 421: return g_radius_comp;
        case 430: case 431: case 432: case 490: return g_length_comp;
        case 440: return p.length_subtract_word ? g_length_comp : kUnknown;
        case 650: return p.macro_calls ? g_nonmodal : kUnknown;
        case 660: case 661: case 670: return p.macro_calls ? kUnsupported : kUnknown;
        case 980: case 990: return g_retract;
        case 540: case 550: case 560: case 570: case 580: case 590: case 591: case 592: case 593:
            return g_coord_system;
        case 610: case 611: case 640: return g_path_control;
        case 960: case 970: return g_spindle_mode;
        case 70: case 80: return g_lathe_diameter;
        // Real LinuxCNC codes that toolcomp does not run yet: splines and NURBS, spindle-
        // synchronised motion, probing, threading, lathe cycles, rotated planes.
        case 330: case 331: case 760: return p.spindle_sync_motion ? g_motion : kUnsupported;
        case 50: case 51: case 52: return p.splines ? g_motion : kUnsupported;
        case 53: return p.splines ? g_nonmodal : kUnsupported;  // G5.3
        case 171: case 181: case 191:
        case 521: case 731: case 961:
            return kUnsupported;
        default:
            return kUnknown;
    }
}

int m_group(int c, const ControlProfile& p) {
    switch (c) {
        case 0: case 10: case 20: case 300: case 600: return m_stop;
        case 60: case 610: return m_tool_change;
        case 30: case 40: case 50: return m_spindle;
        case 70: case 80: case 90: return m_coolant;
        case 480: case 490: case 500: case 510: case 520: case 530: return m_override;
        case 620: case 630: case 640: case 650: case 660: case 670: case 680:
            return m_io;  // digital/analog I/O: no effect on the path (interp_machine.cpp)
        case 700: case 710: case 720: case 730:  // LinuxCNC: in M3-M5's group
            return p.modal_state_codes ? m_spindle : kUnsupported;
        case 190:  // LinuxCNC: M19 spindle orient, in M3-M5's group
            return p.spindle_orient ? m_spindle : kUnsupported;
        case 990: if (p.numbered_subprograms) return m_stop; [[fallthrough]];  // LinuxCNC: M99 in main = M2
        case 980: return p.m98_subprograms ? m_subprogram : kUnknown;
        case 8000: case 8010: return p.ttrc_check_codes ? m_checks : kUnknown;
        default:
            // M100-M199 are user programs on LinuxCNC: without them the code is unknown.
            return kUnknown;
    }
}

}  // namespace toolcomp::iso
