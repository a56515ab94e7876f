// Machine: a control plus what its builder configured (control/machine.hpp). Reading and
// writing machine files (TOML) is in the Python package (toolcomp/machine.py).
#include "bindings.hpp"

#include <algorithm>
#include <cmath>

#include <pybind11/stl.h>

#include "toolcomp/control/machine.hpp"

using namespace toolcomp;

namespace {
constexpr std::pair<const char*, MCodeAction> kActions[] = {
    {"nothing", MCodeAction::nothing},           {"coolant_on", MCodeAction::coolant_on},
    {"coolant_off", MCodeAction::coolant_off},   {"spindle_cw", MCodeAction::spindle_cw},
    {"spindle_ccw", MCodeAction::spindle_ccw},   {"spindle_stop", MCodeAction::spindle_stop},
    {"program_stop", MCodeAction::program_stop}, {"optional_stop", MCodeAction::optional_stop},
    {"program_end", MCodeAction::program_end},   {"tool_change", MCodeAction::tool_change},
    {"subprogram", MCodeAction::subprogram},     {"thread_chamfer_on", MCodeAction::thread_chamfer_on},
    {"thread_chamfer_off", MCodeAction::thread_chamfer_off},
};

MCodeAction action_from(const std::string& s) {
    for (const auto& [name, a] : kActions)
        if (s == name) return a;
    std::string all;
    for (const auto& [name, a] : kActions) all += std::string(all.empty() ? "" : ", ") + name;
    throw py::value_error("unknown M code action '" + s + "' (one of " + all + ")");
}
const char* action_name(MCodeAction a) {
    for (const auto& [name, b] : kActions)
        if (a == b) return name;
    return "nothing";
}

using Triple = std::array<double, 3>;
using OptTriple = std::array<std::optional<double>, 3>;

// An (x, y, z) field of Machine: read as it is, set only with finite numbers (by name).
auto triple_get(Triple Machine::*f) {
    return [f](const Machine& mc) { return mc.*f; };
}
auto triple_set(const char* name, Triple Machine::*f) {
    return [name, f](Machine& mc, const Triple& v) {
        for (double x : v)
            if (!std::isfinite(x)) throw py::value_error(std::string(name) + " must hold finite numbers");
        mc.*f = v;
    };
}
}  // namespace

void bind_machine(py::module_& m) {
    py::class_<MachineCode>(m, "MachineCode", "A builder M code: what it does for the path, and its name.")
        .def(py::init([](const std::string& action, std::string name, std::string words, std::string program,
                         std::string argspec) {
                 return MachineCode{action_from(action), std::move(name), std::move(words), std::move(program),
                                    std::move(argspec)};
             }),
             py::arg("action"), py::arg("name") = "", py::arg("words") = "", py::arg("program") = "",
             py::arg("argspec") = "")
        .def_property(
            "action", [](const MachineCode& c) { return action_name(c.action); },
            [](MachineCode& c, const std::string& a) { c.action = action_from(a); },
            "nothing, coolant_on, coolant_off, spindle_cw, spindle_ccw, spindle_stop, program_stop, optional_stop, "
            "program_end, tool_change or subprogram")
        .def_readwrite("name", &MachineCode::name, "what the builder calls it")
        .def_readwrite("words", &MachineCode::words,
                       "the letters it reads in its block (\"P\" for Haas M59 P1133), taken out of the block")
        .def_readwrite("program", &MachineCode::program,
                       "subprogram: the program it runs (LinuxCNC a sub's name, Fanuc an O number)")
        .def_readwrite("argspec", &MachineCode::argspec,
                       "LinuxCNC subprogram: REMAP's argspec, the words the sub gets as #<p> locals (upper case "
                       "required, lower case optional; '@' as #1, #2, ...; '>' a feed, '^' a spindle speed)")
        .def("__eq__", [](const MachineCode& a, const MachineCode& b) {
            return a.action == b.action && a.name == b.name && a.words == b.words && a.program == b.program &&
                   a.argspec == b.argspec;
        })
        .def("__repr__", [](const MachineCode& c) {
            return "MachineCode('" + std::string(action_name(c.action)) + "', " +
                   py::repr(py::str(c.name)).cast<std::string>() +
                   (c.words.empty() ? std::string() : ", words='" + c.words + "'") +
                   (c.program.empty() ? std::string() : ", program='" + c.program + "'") +
                   (c.argspec.empty() ? std::string() : ", argspec='" + c.argspec + "'") + ")";
        });

    py::class_<Machine>(m, "Machine",
                        "A machine: a control (its ControlProfile) plus what its builder configured: M codes, "
                        "work origin, G28/G30 and tool change positions, axis travel, rates. Lengths in mm, "
                        "machine coordinates. Machine.read / Machine.preset / machine.write: see toolcomp.machine.")
        .def(py::init([](const std::string& control, const std::string& kind, std::optional<std::string> name) {
                 if (kind != "mill" && kind != "lathe")
                     throw py::value_error("kind is 'mill' or 'lathe', not '" + kind + "'");
                 Machine mc = plain_machine(dialect_from_name(control), kind == "lathe" ? MachineKind::lathe : MachineKind::mill);
                 if (name) mc.name = *name;
                 return mc;
             }),
             py::arg("control") = "linuxcnc", py::arg("kind") = "mill", py::arg("name") = py::none(),
             "The plain machine of a control: its profile, no builder codes, machine zero at program zero.")
        .def_readwrite("name", &Machine::name)
        .def_property_readonly("control", [](const Machine& mc) { return std::string(dialect_name(mc.control)); },
                               "the control's dialect: 'linuxcnc', 'fanuc', 'sinumerik', 'heidenhain' or 'rockwell'")
        .def_readonly("kind", &Machine::kind, "MachineKind: mill or lathe")
        .def_property(
            "profile", [](const Machine& mc) { return mc.profile; },
            [](Machine& mc, const ControlProfile& p) {
                if (p.kind != mc.kind) throw py::value_error("the profile is of another kind of machine");
                mc.profile = p;
            },
            "the ControlProfile runs on this machine use (a copy: set it back after changing fields)")
        .def_property(
            "m_codes", [](const Machine& mc) { return mc.m_codes; },
            [](Machine& mc, const std::map<int, MachineCode>& codes) {
                for (const auto& [n, c] : codes)
                    if (n < 0 || std::find(mc.profile.fixed_m_codes.begin(), mc.profile.fixed_m_codes.end(), n) !=
                                     mc.profile.fixed_m_codes.end())
                        throw py::value_error("M" + std::to_string(n) + " cannot be declared: the control fixes it");
                mc.m_codes = codes;
            },
            "builder M codes: {number: MachineCode} (a copy: set it back after changing it)")
        .def_property(
            "g_codes",
            [](const Machine& mc) {
                std::map<double, MachineCode> out;
                for (const auto& [c, code] : mc.g_codes) out[c / 10.0] = code;
                return out;
            },
            [](Machine& mc, const std::map<double, MachineCode>& codes) {
                std::map<int, MachineCode> by10;
                for (const auto& [g, code] : codes) {
                    const double v = g * 10;
                    if (!(v >= 0 && v <= 9999) || std::fabs(v - std::round(v)) > 1e-6)
                        throw py::value_error("a G code number is 0-999.9 with one decimal");
                    by10[static_cast<int>(std::lround(v))] = code;
                }
                mc.g_codes = std::move(by10);
            },
            "LinuxCNC's remapped G codes: {88.6: MachineCode('subprogram', program=..., argspec=...)} (a copy)")
        .def_readwrite("machine_data", &Machine::machine_data,
                       "Sinumerik machine and setting data programs read: {'$MN_SCALING_VALUE_INCH': 25.4} (a copy)")
        .def_readwrite("cycles", &Machine::cycles,
                       "Heidenhain builder cycles: {392: MachineCode('nothing', 'ATC')}: accepted, their Q parameters "
                       "set, no motion (a copy)")
        .def_property("work_origin", triple_get(&Machine::work_origin),
                      triple_set("work_origin", &Machine::work_origin), "where program zero (G54) lies in machine coordinates, (x, y, z) mm")
        .def_property("g28", triple_get(&Machine::g28),
                      triple_set("g28", &Machine::g28), "the G28 position in machine coordinates, (x, y, z) mm")
        .def_property("g30", triple_get(&Machine::g30),
                      triple_set("g30", &Machine::g30), "the G30 position in machine coordinates, (x, y, z) mm")
        .def_property("start", triple_get(&Machine::start), triple_set("start", &Machine::start),
                      "where the axes stand when a program starts, machine coordinates, (x, y, z) mm (default: "
                      "the machine's zero)")
        .def_property("m92", triple_get(&Machine::m92), triple_set("m92", &Machine::m92),
                      "Heidenhain: the additional machine datum (M92) in machine coordinates, (x, y, z) mm")
        .def_property(
            "tool_change", [](const Machine& mc) { return mc.tool_change; },
            [](Machine& mc, const OptTriple& v) {
                for (const auto& x : v)
                    if (x && !std::isfinite(*x)) throw py::value_error("tool_change must hold finite numbers or None");
                mc.tool_change = v;
            },
            "where M6 sends each axis first, machine coordinates (x, y, z), None: that axis stays")
        .def_property(
            "travel",
            [](const Machine& mc) {
                std::array<std::pair<double, double>, 3> t;
                for (int i = 0; i < 3; ++i) t[i] = {mc.travel[i].min, mc.travel[i].max};
                return t;
            },
            [](Machine& mc, const std::array<std::pair<double, double>, 3>& t) {
                for (int i = 0; i < 3; ++i) {
                    if (std::isnan(t[i].first) || std::isnan(t[i].second) || t[i].first > t[i].second)
                        throw py::value_error("travel: each axis is (min, max) with min <= max");
                    mc.travel[i] = {t[i].first, t[i].second};
                }
            },
            "axis travel ((xmin, xmax), (ymin, ymax), (zmin, zmax)) in machine coordinates, mm; +-inf: no limit")
        .def_readwrite("spindles", &Machine::spindles, "spindles, 1 to 8 (LinuxCNC [TRAJ]SPINDLES): $0 .. $n-1")
        .def_readwrite("travel_limit_warning", &Machine::travel_limit_warning,
                       "a move beyond the travel is a warning (True) or an error that stops the run (False)")
        .def_property("rapid_rate", triple_get(&Machine::rapid_rate),
                      triple_set("rapid_rate", &Machine::rapid_rate), "rapid traverse of each axis, mm/min (0: not given)")
        .def_property("max_feed", triple_get(&Machine::max_feed),
                      triple_set("max_feed", &Machine::max_feed), "the highest feed of each axis, mm/min (0: not given)")
        .def_readwrite("tool_change_time", &Machine::tool_change_time,
                       "seconds a tool change takes, chip to chip (0: not given), for Result.cycle_time")
        .def("check", [](const Machine& mc) { check_machine(mc); },
             "raise ValueError naming the field of a value the machine cannot have")
        .def("__repr__", [](const Machine& mc) {
            return "Machine(" + py::repr(py::str(mc.name)).cast<std::string>() + ", control='" +
                   std::string(dialect_name(mc.control)) + "', kind='" +
                   (mc.kind == MachineKind::lathe ? "lathe" : "mill") + "', m_codes=" + std::to_string(mc.m_codes.size()) + ")";
        });
}
