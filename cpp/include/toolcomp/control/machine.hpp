#pragma once
// A machine: a control (its ControlProfile) plus what the machine builder configured on top
// of it. A real shop program carries the machine's boilerplate (chip conveyor, tailstock,
// doors, air blast, probe arms), machine-coordinate moves and tool change positions; the
// control runs them because the builder declared them, and a run does the same with a
// Machine. What no one declared stays an explicit error.
//
// Everything here is plain data, read from a TOML machine file by the Python package
// (toolcomp/machine.py, doc/machines.md) or set in code. Lengths are millimetres, in machine
// coordinates (the machine's own zero), feeds mm/min.
#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <string>

#include "toolcomp/control/rates.hpp"
#include "toolcomp/control/profile.hpp"
#include "toolcomp/program/dialect.hpp"

namespace toolcomp {

// What a builder M code does for the path. The control's own codes keep their meaning;
// a builder code acts like the standard code of its action (coolant_on like M8, ...).
enum class MCodeAction : std::uint8_t {
    nothing,        // no effect on the path: conveyors, doors, brakes, tailstock, air, relays
    coolant_on,     // as M8
    coolant_off,    // as M9
    spindle_cw,     // as M3
    spindle_ccw,    // as M4
    spindle_stop,   // as M5
    program_stop,   // as M0
    optional_stop,  // as M1
    program_end,    // as M30
    tool_change,    // as M6
    subprogram,     // runs `program` after its block: LinuxCNC o<program> call (a remap to an O-word
                    // sub, name.ngc on the search path), Fanuc M98 P<number> (a macro M code)
    thread_chamfer_on,   // the pull-out chamfer at the end of G76/G92 threads (Haas M23), on at start
    thread_chamfer_off,  // no pull-out chamfer (Haas M24)
};

// The standard code an action acts like (8 for coolant_on, ...); -1 for nothing.
constexpr int standard_m_code(MCodeAction a) {
    switch (a) {
        case MCodeAction::coolant_on: return 8;
        case MCodeAction::coolant_off: return 9;
        case MCodeAction::spindle_cw: return 3;
        case MCodeAction::spindle_ccw: return 4;
        case MCodeAction::spindle_stop: return 5;
        case MCodeAction::program_stop: return 0;
        case MCodeAction::optional_stop: return 1;
        case MCodeAction::program_end: return 30;
        case MCodeAction::tool_change: return 6;
        default: return -1;
    }
}

/// A builder M code: what it does for the path, and its name.
struct MachineCode {
    /// nothing, coolant_on, coolant_off, spindle_cw, spindle_ccw, spindle_stop,
    /// program_stop, optional_stop, program_end, tool_change or subprogram
    MCodeAction action = MCodeAction::nothing;
    /// what the builder calls it
    std::string name;   // what the builder calls it ("chip conveyor forward"), for messages
    /// the letters it reads in its block ("P" for Haas M59 P1133), taken out of the block
    std::string words;  // the letters it reads in its block ("P": Haas M59 P1133 sets relay 1133),
                        // taken out of the block: no other word of the block reads them
    /// subprogram: the program it runs (LinuxCNC a sub's name, Fanuc an O number)
    std::string program;
    // LinuxCNC's REMAP argspec of a subprogram code: the words the sub takes as its named
    // locals (#<p>), upper case required, lower case optional; '@' passes them as #1, #2, ...
    // in this order instead; '>' needs a feed above 0 (#<f>), '^' a spindle speed (#<s>).
    /// LinuxCNC subprogram: REMAP's argspec, the words the sub gets as #<p> locals (upper
    /// case required, lower case optional; '@' as #1, #2, ...; '>' a feed, '^' a spindle
    /// speed)
    std::string argspec;
};

// A position in machine coordinates; an axis not given is nullopt (it does not move, or
// keeps the control's default).
using MachinePoint = std::array<std::optional<double>, 3>;

// Travel of one axis in machine coordinates (mm); infinite bounds: not limited.
struct AxisTravel {
    double min = -std::numeric_limits<double>::infinity();
    double max = std::numeric_limits<double>::infinity();
    bool limited() const { return min > -std::numeric_limits<double>::infinity() || max < std::numeric_limits<double>::infinity(); }
};

/// A machine: a control (its ControlProfile) plus what its builder configured: M codes, work
/// origin, G28/G30 and tool change positions, axis travel, rates. Lengths in mm, machine
/// coordinates. Machine.read / Machine.preset / machine.write: see toolcomp.machine.
struct Machine {
    std::string name;
    /// the control's dialect: 'linuxcnc', 'fanuc', 'sinumerik', 'heidenhain' or 'rockwell'
    Dialect control = Dialect::linuxcnc;
    /// MachineKind: mill or lathe
    MachineKind kind = MachineKind::mill;
    /// the ControlProfile runs on this machine use (a copy: set it back after changing fields)
    ControlProfile profile;  // the control's profile with the machine file's overrides

    // Builder M codes by number. A code the control fixes itself (profile.fixed_m_codes:
    // program stop and end, subprogram call and return) cannot be declared (check_machine).
    /// builder M codes: {number: MachineCode} (a copy: set it back after changing it)
    std::map<int, MachineCode> m_codes;
    // LinuxCNC's remapped G codes (REMAP=G88.6 ... ngc=...): by the code x 10 (886), each a
    // subprogram with its argspec, run as the block's motion. Only codes LinuxCNC lacks.
    /// LinuxCNC's remapped G codes: {88.6: MachineCode('subprogram', program=...,
    /// argspec=...)} (a copy)
    std::map<int, MachineCode> g_codes;
    // Heidenhain builder cycles (DMG's CYCL DEF 392 ATC, ...) by number: action nothing, the
    // definition's Q parameters are the program's, nothing moves.
    /// Heidenhain builder cycles: {392: MachineCode('nothing', 'ATC')}: accepted, their Q
    /// parameters set, no motion (a copy)
    std::map<int, MachineCode> cycles;
    // Sinumerik machine and setting data a program reads ($MN_..., $MC_..., $MA_..., $SN_...,
    // $SC_..., $SA_...: the name as the program writes it, upper case, without an index).
    /// Sinumerik machine and setting data programs read: {'$MN_SCALING_VALUE_INCH': 25.4} (a copy)
    std::map<std::string, double> machine_data;

    // Where program zero (G54, the first work offset) lies in machine coordinates: G53 moves
    // and the travel limits are measured from it. A LinuxCNC .var file or G10 still set it.
    /// where program zero (G54) lies in machine coordinates, (x, y, z) mm
    std::array<double, 3> work_origin{0, 0, 0};
    // The G28 and G30 positions in machine coordinates (LinuxCNC #5161-#5163, #5181-#5183).
    /// the G28 position in machine coordinates, (x, y, z) mm
    std::array<double, 3> g28{0, 0, 0}, g30{0, 0, 0};
    // Where the axes stand when a program starts, in machine coordinates (the reference
    // point the machine is at after homing: its zero, unless the builder put it elsewhere).
    /// where the axes stand when a program starts, machine coordinates, (x, y, z) mm
    /// (default: the machine's zero)
    std::array<double, 3> start{0, 0, 0};
    // Heidenhain: the additional machine datum the builder defines, in machine coordinates: a
    // positioning block with M92 is measured from it (with M91 from the machine's zero).
    /// Heidenhain: the additional machine datum (M92) in machine coordinates, (x, y, z) mm
    std::array<double, 3> m92{0, 0, 0};
    // Where a tool change (M6) sends the axes it names, at rapid, before the change (Haas
    // mill: Z to machine zero); no axis: the tool changes where it stands.
    /// where M6 sends each axis first, machine coordinates (x, y, z), None: that axis stays
    MachinePoint tool_change{};

    // Axis travel (X, Y, Z): a move beyond it is "travel_limit" at its block, an error that
    // stops the run (the control's soft limit) unless travel_limit_warning.
    /// axis travel ((xmin, xmax), (ymin, ymax), (zmin, zmax)) in machine coordinates, mm;
    /// +-inf: no limit
    std::array<AxisTravel, 3> travel{};
    /// a move beyond the travel is a warning (True) or an error that stops the run (False)
    bool travel_limit_warning = false;

    // Rapid traverse and the highest feed of each axis (mm/min; 0: not given). Read and
    // checked, for cycle time.
    /// rapid traverse of each axis, mm/min (0: not given)
    std::array<double, 3> rapid_rate{0, 0, 0}, max_feed{0, 0, 0};
    /// seconds a tool change takes, chip to chip (0: not given), for Result.cycle_time
    double tool_change_time = 0;
    MachineRates rates() const { return {rapid_rate, max_feed, tool_change_time}; }

    // Spindles, 1 to 8 (LinuxCNC's [TRAJ]SPINDLES): a program selects one with $0 .. $n-1.
    /// spindles, 1 to 8 (LinuxCNC [TRAJ]SPINDLES): $0 .. $n-1
    int spindles = 1;
    static constexpr int kMaxSpindles = 8;

    const MachineCode* m_code(int number) const {
        auto it = m_codes.find(number);
        return it == m_codes.end() ? nullptr : &it->second;
    }
    const MachineCode* g_code(int code10) const {
        auto it = g_codes.find(code10);
        return it == g_codes.end() ? nullptr : &it->second;
    }
    const MachineCode* cycle(int number) const {
        auto it = cycles.find(number);
        return it == cycles.end() ? nullptr : &it->second;
    }
    bool has_travel_limits() const { return travel[0].limited() || travel[1].limited() || travel[2].limited(); }
};

// The plain machine of a control: its profile, no builder codes, machine zero at program zero.
Machine plain_machine(Dialect control, MachineKind kind = MachineKind::mill);

// Throws std::invalid_argument naming the field for a machine that cannot be: a declared code
// the control fixes, negative or huge code numbers, travel whose min exceeds its max, values
// that are not finite numbers, negative rates; and check_profile() on its profile.
void check_machine(const Machine& m);

}  // namespace toolcomp
