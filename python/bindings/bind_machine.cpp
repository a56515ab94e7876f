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
    py::class_<MachineCode>(m, "MachineCode", pydoc::MachineCode)
        .def(py::init([](const std::string& action, std::string name, std::string words, std::string program,
                         std::string argspec) {
                 return MachineCode{action_from(action), std::move(name), std::move(words), std::move(program),
                                    std::move(argspec)};
             }),
             py::arg("action"), py::arg("name") = "", py::arg("words") = "", py::arg("program") = "",
             py::arg("argspec") = "")
        .def_property(
            "action", [](const MachineCode& c) { return action_name(c.action); },
            [](MachineCode& c, const std::string& a) { c.action = action_from(a); }, pydoc::MachineCode_action)
        .def_readwrite("name", &MachineCode::name, pydoc::MachineCode_name)
        .def_readwrite("words", &MachineCode::words, pydoc::MachineCode_words)
        .def_readwrite("program", &MachineCode::program, pydoc::MachineCode_program)
        .def_readwrite("argspec", &MachineCode::argspec, pydoc::MachineCode_argspec)
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

    py::class_<Machine>(m, "Machine", pydoc::Machine)
        /// @pydoc Machine.__init__
        /// The plain machine of a control: its profile, no builder codes, machine zero
        /// at program zero.
        .def(py::init([](const std::string& control, const std::string& kind, std::optional<std::string> name) {
                 if (kind != "mill" && kind != "lathe")
                     throw py::value_error("kind is 'mill' or 'lathe', not '" + kind + "'");
                 Machine mc = plain_machine(dialect_from_name(control), kind == "lathe" ? MachineKind::lathe : MachineKind::mill);
                 if (name) mc.name = *name;
                 return mc;
             }),
             py::arg("control") = "linuxcnc", py::arg("kind") = "mill", py::arg("name") = py::none(),
             pydoc::Machine___init__)
        .def_readwrite("name", &Machine::name)
        .def_property_readonly("control", [](const Machine& mc) { return std::string(dialect_name(mc.control)); },
                               pydoc::Machine_control)
        .def_readonly("kind", &Machine::kind, pydoc::Machine_kind)
        .def_property(
            "profile", [](const Machine& mc) { return mc.profile; },
            [](Machine& mc, const ControlProfile& p) {
                if (p.kind != mc.kind) throw py::value_error("the profile is of another kind of machine");
                mc.profile = p;
            },
            pydoc::Machine_profile)
        .def_property(
            "m_codes", [](const Machine& mc) { return mc.m_codes; },
            [](Machine& mc, const std::map<int, MachineCode>& codes) {
                for (const auto& [n, c] : codes)
                    if (n < 0 || std::find(mc.profile.fixed_m_codes.begin(), mc.profile.fixed_m_codes.end(), n) !=
                                     mc.profile.fixed_m_codes.end())
                        throw py::value_error("M" + std::to_string(n) + " cannot be declared: the control fixes it");
                mc.m_codes = codes;
            },
            pydoc::Machine_m_codes)
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
            pydoc::Machine_g_codes)
        .def_readwrite("machine_data", &Machine::machine_data, pydoc::Machine_machine_data)
        .def_readwrite("cycles", &Machine::cycles, pydoc::Machine_cycles)
        .def_property("work_origin", triple_get(&Machine::work_origin),
                      triple_set("work_origin", &Machine::work_origin), pydoc::Machine_work_origin)
        .def_property("g28", triple_get(&Machine::g28),
                      triple_set("g28", &Machine::g28), pydoc::Machine_g28)
        /// @pydoc Machine.g30
        /// the G30 position in machine coordinates, (x, y, z) mm
        .def_property("g30", triple_get(&Machine::g30),
                      triple_set("g30", &Machine::g30), pydoc::Machine_g30)
        .def_property("start", triple_get(&Machine::start), triple_set("start", &Machine::start), pydoc::Machine_start)
        .def_property("m92", triple_get(&Machine::m92), triple_set("m92", &Machine::m92), pydoc::Machine_m92)
        .def_property(
            "tool_change", [](const Machine& mc) { return mc.tool_change; },
            [](Machine& mc, const OptTriple& v) {
                for (const auto& x : v)
                    if (x && !std::isfinite(*x)) throw py::value_error("tool_change must hold finite numbers or None");
                mc.tool_change = v;
            },
            pydoc::Machine_tool_change)
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
            pydoc::Machine_travel)
        .def_readwrite("spindles", &Machine::spindles, pydoc::Machine_spindles)
        .def_readwrite("travel_limit_warning", &Machine::travel_limit_warning, pydoc::Machine_travel_limit_warning)
        .def_property("rapid_rate", triple_get(&Machine::rapid_rate),
                      triple_set("rapid_rate", &Machine::rapid_rate), pydoc::Machine_rapid_rate)
        /// @pydoc Machine.max_feed
        /// the highest feed of each axis, mm/min (0: not given)
        .def_property("max_feed", triple_get(&Machine::max_feed),
                      triple_set("max_feed", &Machine::max_feed), pydoc::Machine_max_feed)
        .def_readwrite("tool_change_time", &Machine::tool_change_time, pydoc::Machine_tool_change_time)
        /// @pydoc Machine.check
        /// raise ValueError naming the field of a value the machine cannot have
        .def("check", [](const Machine& mc) { check_machine(mc); }, pydoc::Machine_check)
        .def("__repr__", [](const Machine& mc) {
            return "Machine(" + py::repr(py::str(mc.name)).cast<std::string>() + ", control='" +
                   std::string(dialect_name(mc.control)) + "', kind='" +
                   (mc.kind == MachineKind::lathe ? "lathe" : "mill") + "', m_codes=" + std::to_string(mc.m_codes.size()) + ")";
        });
}
