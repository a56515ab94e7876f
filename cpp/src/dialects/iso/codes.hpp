#pragma once
// G and M codes of the ISO dialects: modal group of each supported code, and the codes that
// are valid on the control but not supported by toolcomp (an explicit error, never ignored).
//
// Codes are held as ten times their value (G59.3 -> 593), as LinuxCNC does.
#include "toolcomp/control/profile.hpp"

namespace toolcomp::iso {

enum GGroup : int {
    g_nonmodal = 0, g_motion = 1, g_plane = 2, g_distance = 3, g_arc_distance = 4,
    g_feed_mode = 5, g_units = 6, g_radius_comp = 7, g_length_comp = 8, g_cycle = 9, g_retract = 10,
    g_coord_system = 12, g_path_control = 13, g_spindle_mode = 14, g_lathe_diameter = 15,
    g_group_count = 16
};
enum MGroup : int {
    m_io = 5, m_stop = 4, m_tool_change = 6, m_checks = 10, m_spindle = 7, m_coolant = 8, m_override = 9,
    m_subprogram = 11,
    m_group_count = 12
};

constexpr int kUnsupported = -2;  // a real code of the control that toolcomp does not run
constexpr int kUnknown = -1;      // not a code of this control

// Group of G (M) code `code10` on the control of `profile`, or kUnsupported / kUnknown.
int g_group(int code10, const ControlProfile& profile);
int m_group(int code10, const ControlProfile& profile);

// LinuxCNC's lathe profile cycles G70, G71, G71.1, G71.2, G72, G72.1, G72.2.
constexpr bool is_profile_cycle(int code10) {
    return code10 == 700 || code10 == 710 || code10 == 711 || code10 == 712 || code10 == 720 || code10 == 721 ||
           code10 == 722;
}

}  // namespace toolcomp::iso
