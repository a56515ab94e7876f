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

// The codes by name: G41_1 is G41.1 (held as 411), M6 is M6 (60). The interpreters compare
// codes by these names only.
enum GCode : int {
    G0 = 0, G1 = 10, G2 = 20, G3 = 30, G4 = 40, G5 = 50, G5_1 = 51, G5_2 = 52, G5_3 = 53, G7 = 70, G8 = 80,
    G10 = 100, G17 = 170, G17_1 = 171, G18 = 180, G18_1 = 181, G19 = 190, G19_1 = 191, G20 = 200, G21 = 210,
    G28 = 280, G28_1 = 281, G30 = 300, G30_1 = 301, G32 = 320, G33 = 330, G33_1 = 331, G38_2 = 382,
    G38_3 = 383, G38_4 = 384, G38_5 = 385, G40 = 400, G41 = 410, G41_1 = 411, G42 = 420, G42_1 = 421,
    G43 = 430, G43_1 = 431, G43_2 = 432, G44 = 440, G49 = 490, G50 = 500, G52 = 520, G52_1 = 521, G53 = 530,
    G54 = 540, G55 = 550, G56 = 560, G57 = 570, G58 = 580, G59 = 590, G59_1 = 591, G59_2 = 592, G59_3 = 593,
    G61 = 610, G61_1 = 611, G64 = 640, G65 = 650, G66 = 660, G66_1 = 661, G67 = 670, G70 = 700, G71 = 710,
    G71_1 = 711, G71_2 = 712, G72 = 720, G72_1 = 721, G72_2 = 722, G73 = 730, G73_1 = 731, G74 = 740,
    G75 = 750, G76 = 760, G80 = 800, G81 = 810, G82 = 820, G83 = 830, G84 = 840, G85 = 850, G86 = 860,
    G87 = 870, G88 = 880, G89 = 890, G90 = 900, G90_1 = 901, G91 = 910, G91_1 = 911, G92 = 920, G92_1 = 921,
    G92_2 = 922, G92_3 = 923, G93 = 930, G94 = 940, G95 = 950, G96 = 960, G96_1 = 961, G97 = 970, G98 = 980,
    G99 = 990,
};
enum MCode : int {
    M0 = 0, M1 = 10, M2 = 20, M3 = 30, M4 = 40, M5 = 50, M6 = 60, M7 = 70, M8 = 80, M9 = 90, M19 = 190,
    M30 = 300, M48 = 480, M49 = 490, M50 = 500, M51 = 510, M52 = 520, M53 = 530, M60 = 600, M61 = 610,
    M62 = 620, M63 = 630, M64 = 640, M65 = 650, M66 = 660, M67 = 670, M68 = 680, M70 = 700, M71 = 710,
    M72 = 720, M73 = 730, M98 = 980, M99 = 990, M800 = 8000, M801 = 8010,
};

// The number of a code as a program writes it (G65 -> 65.0, G43.1 -> 43.1), for reading words.
constexpr double written(int code10) { return code10 / 10.0; }

constexpr int kUnsupported = -2;  // a real code of the control that toolcomp does not run
constexpr int kUnknown = -1;      // not a code of this control

// Group of G (M) code `code10` on the control of `profile`, or kUnsupported / kUnknown.
int g_group(int code10, const ControlProfile& profile);
int m_group(int code10, const ControlProfile& profile);

// The canned cycles G73, G74, G81-G89.
constexpr bool is_cycle(int code10) { return code10 == G73 || code10 == G74 || (code10 >= G81 && code10 <= G89); }

// LinuxCNC's lathe profile cycles G70, G71, G71.1, G71.2, G72, G72.1, G72.2.
constexpr bool is_profile_cycle(int code10) {
    return code10 == G70 || code10 == G71 || code10 == G71_1 || code10 == G71_2 || code10 == G72 ||
           code10 == G72_1 || code10 == G72_2;
}

}  // namespace toolcomp::iso
