// Parameters as the running program sees them: stored ones (params.hpp) and the system
// parameters computed from the interpreter's state (LinuxCNC 5161-5428, Fanuc #3000 and the
// position variables), named parameters, and the substitution of values into messages.
#include <algorithm>
#include <cctype>
#include <cmath>

#include "interp.hpp"
#include "whole_numbers.hpp"
#include "toolcomp/program/codes.hpp"
#include "toolcomp/program/text.hpp"
#include "toolcomp/tools/tool_table.hpp"

namespace toolcomp::iso {

bool Interp::system_param(int n, double& v) const {
    const bool fanuc = params_.fanuc();
    if (fanuc) {
        if (n >= 5001 && n <= 5003) {  // end point of the last block, workpiece coordinates
            v = pos_[n - 5001];
            return true;
        }
        if (n >= 5041 && n <= 5043) {  // current position, workpiece coordinates
            v = pos_[n - 5041];
            return true;
        }
        if (n == 4120) {  // T code
            v = tool_;
            return true;
        }
        return false;
    }
    auto axis9 = [](const Vec6& p, int j) { return j < 6 ? p[j] : 0.0; };  // U V W: none
    if (n >= 5061 && n <= 5070 && probed_) return v = probe_values_[static_cast<std::size_t>(n - 5061)], true;
    if (n == 5599) return v = debug_output_ ? 1.0 : 0.0, true;
    if (n >= 5161 && n <= 5169) return v = axis9(g28_, n - 5161), true;
    if (n >= 5181 && n <= 5189) return v = axis9(g30_, n - 5181), true;
    // G92.2 suspends the offsets and keeps these; G92.3 takes them back.
    if (n >= 5211 && n <= 5219) return v = axis9(g92_saved_, n - 5211), true;
    if (n == 5210) return v = g92_on_ ? 1.0 : 0.0, true;
    if (n == 5220) return v = st_.coord_system, true;
    if (n >= 5221 && n <= 5400 - 1 && n < 5221 + 9 * 20) {
        const int cs = (n - 5221) / 20, j = (n - 5221) % 20;
        if (j < 9) return v = axis9(g5x_[static_cast<std::size_t>(cs)], j), true;
        if (j == 9) return v = rotation_[static_cast<std::size_t>(cs)], true;
        return false;
    }
    if (n == 5400) return v = tool_, true;
    if (n >= 5401 && n <= 5413) {
        // The tool table's row of the tool in the spindle (whatever offset is applied; none
        // when there is no tool or no row), in program units.
        v = 0;
        const Tool* t = tools_ && tool_ > 0 ? tools_->find(tool_) : nullptr;
        if (!t) return true;
        const CuttingEdge& e = t->edge();
        const double sc = scale();
        if (n <= 5403) v = e.length[n - 5401] / sc;
        else if (n <= 5406) v = e.rotary[static_cast<std::size_t>(n - 5404)];
        else if (n <= 5409) v = e.uvw[static_cast<std::size_t>(n - 5407)] / sc;
        else if (n == 5410) v = 2 * e.radius / sc;
        else v = n == 5411 ? e.front_angle : n == 5412 ? e.back_angle : e.orientation;
        return true;
    }
    if (n >= 5420 && n <= 5428) return v = axis9(pos_, n - 5420), true;
    return false;
}

// A parameter number: LinuxCNC reads it as any integer word (within 0.0001, whole_numbers.hpp),
// Fanuc as written.
double Interp::parameter_number(double number, int column) const {
    if (std::isnan(number)) fail(code::bad_parameter_number, "Parameter number must be a whole number", column);
    if (!params_.fanuc()) {
        if (!linuxcnc_whole(number)) fail(code::non_integer_value, "Non integer value for integer", column);
        return std::round(number);
    }
    if (std::fabs(number - std::round(number)) > 1e-9)
        fail(code::bad_parameter_number, "Parameter number must be a whole number", column);
    return std::round(number);
}

double Interp::param(double number) {
    const bool fanuc = params_.fanuc();
    const double r = parameter_number(number, 0);
    if (fanuc) {
        if (r == 0) return ParameterStore::kVacant;
        if (r < 0 || r > 99999) fail(code::bad_parameter_number, "Variable number #" + printf_number("%f", r) + " out of range");
    } else if (r < 1 || r > 5601) {
        fail(code::parameter_out_of_range, "Parameter number out of range");
    }
    const int n = static_cast<int>(r);
    if (!fanuc && n >= 5420 && n <= 5428 && comp_on())
        fail(code::comp_position_read, "Cannot read current position with cutter radius compensation on");
    double v;
    if (system_param(n, v)) return v;
    if (!fanuc && n >= 5061 && n <= 5070)
        fail(code::probe_parameter_unset, "Probe result #" + std::to_string(n) + " read, but this run made no probe move");
    if (!fanuc && n == 5399) fail(code::unsupported_parameter, "#5399 (M66 input result) is not supported by toolcomp");
    if (params_.stored(n)) return params_.get(n);
    fail(code::unsupported_parameter, "System variable #" + std::to_string(n) + " is not supported by toolcomp");
}

void Interp::set_param(double number, double v, int column) {
    const bool fanuc = params_.fanuc();
    const int n = static_cast<int>(std::clamp(parameter_number(number, column), -1.0, 1e6));
    if (fanuc && n == 3000) {
        // #3000 = n (MESSAGE): the control stops with macro alarm 3000 + n.
        const double a = std::isnan(v) ? 0 : v;
        fail(code::macro_alarm, "Alarm " + std::to_string(3000 + static_cast<long>(a)) +
                                (alarm_text_.empty() ? std::string() : " " + alarm_text_),
             column);
    }
    if (fanuc && n == 0) fail(code::vacant_assignment, "#0 is always vacant and cannot be set", column);
    if (!fanuc && (n < 1 || n > 5601)) fail(code::parameter_out_of_range, "Parameter number out of range", column);
    if (!fanuc && ((n >= 5400 && n <= 5413) || (n >= 5420 && n <= 5428)))
        fail(code::read_only_parameter, "Parameter is readonly", column);
    if (!fanuc && n >= 5061 && n <= 5070) {  // the probe's results: a program may set them (LinuxCNC)
        if (!probed_) probe_values_.fill(0);
        probe_values_[static_cast<std::size_t>(n - 5061)] = v;
        probed_ = true;
        return;
    }
    if (!fanuc && n == 5599) {  // LinuxCNC: (DEBUG, ...) shown (1, the start) or not (0)
        debug_output_ = v != 0;
        return;
    }
    double dummy;
    if ((!fanuc && n >= 5061) || system_param(n, dummy) || !params_.stored(n))
        fail(code::read_only_parameter,
             "#" + std::to_string(n) + " is a system parameter: toolcomp does not let programs set it" +
                 (fanuc ? "" : " (set offsets with G10, G92, G28.1 / G30.1)"),
             column);
    params_.set(n, v);
}

void MachineSwitches::update(const BlockWords& bw) {
    if (int c = bw.m[m_coolant]; c >= 0) {
        if (c == M7) mist = true;
        else if (c == M8) flood = true;
        else mist = flood = false;  // M9
    }
    if (int ov = bw.m[m_override]; ov >= 0) {
        const bool on = !bw.has('P') || bw['P'].value != 0;
        switch (ov) {
            case M48: feed_override = speed_override = true; break;
            case M49: feed_override = speed_override = false; break;
            case M50: feed_override = on; break;
            case M51: speed_override = on; break;
            case M52: adaptive_feed = on; break;
            case M53: feed_hold = on; break;
            default: break;
        }
    }
}

namespace {
// LinuxCNC 2.9's read-only named parameters toolcomp knows (#<_x> etc. by the axis loop).
constexpr std::string_view kPredefined[] = {
    "_value", "_value_returned", "_call_level", "_metric", "_imperial", "_absolute", "_incremental",
    "_current_tool", "_selected_tool", "_feed", "_rpm", "_x", "_y", "_z", "_a", "_b", "_c", "_u", "_v", "_w",
    "_coord_system", "_motion_mode", "_plane", "_ccomp", "_line", "_task", "_remap_level", "_vmajor", "_vminor",
    "_spindle_on", "_spindle_cw", "_units_per_minute", "_units_per_rev", "_inverse_time", "_ijk_absolute_mode",
    "_lathe_diameter_mode", "_lathe_radius_mode", "_tool_offset", "_retract_r_plane", "_retract_old_z", "_mist",
    "_flood", "_feed_override", "_speed_override", "_adaptive_feed", "_feed_hold"};
}  // namespace

bool Interp::predefined(const std::string& name) {
    for (std::string_view n : kPredefined)
        if (name == n) return true;
    return false;
}

// The mode and machine-state parameters: G codes as 10 x their number (G59.1 is 591), the
// switches 1 or 0.
bool Interp::mode_param(const std::string& name, double& v) const {
    auto flag = [&](bool b) { return v = b ? 1.0 : 0.0, true; };
    if (name == "_coord_system") {
        const int c = st_.coord_system;
        return v = c <= 6 ? G53 + 10 * c : G59 + (c - 6), true;
    }
    if (name == "_motion_mode") return v = st_.motion, true;
    if (name == "_plane") return v = st_.plane == Plane::xy ? 170 : st_.plane == Plane::zx ? 180 : 190, true;
    if (name == "_ccomp") return v = radius_.side == 0 ? 400 : radius_.side > 0 ? 410 : 420, true;
    if (name == "_line") return v = line_, true;
    // The interpreter of the running control (milltask), not a preview: programs that leave
    // things out "in preview" run them here.
    if (name == "_task") return v = 1, true;
    if (name == "_remap_level") return v = 0, true;
    if (name == "_vmajor") return v = 2.9, true;  // LinuxCNC 2.9.0, as the control this profile follows
    if (name == "_vminor") return v = 0, true;
    if (name == "_spindle_on") return flag(spindles_[0].turning != 0);
    if (name == "_spindle_cw") return flag(spindles_[0].turning > 0);
    if (name == "_units_per_minute") return flag(st_.feed_mode == G94);
    if (name == "_units_per_rev") return flag(st_.feed_mode == G95);
    if (name == "_inverse_time") return flag(st_.feed_mode == G93);
    if (name == "_ijk_absolute_mode") return flag(st_.arc_absolute);
    if (name == "_lathe_diameter_mode") return flag(st_.diameter);
    if (name == "_lathe_radius_mode") return flag(!st_.diameter);
    if (name == "_tool_offset") return flag(st_.length_mode != G49);
    if (name == "_retract_r_plane") return flag(!st_.retract_initial);
    if (name == "_retract_old_z") return flag(st_.retract_initial);
    if (name == "_mist") return flag(machine_.mist);
    if (name == "_flood") return flag(machine_.flood);
    if (name == "_feed_override") return flag(machine_.feed_override);
    if (name == "_speed_override") return flag(machine_.speed_override);
    if (name == "_adaptive_feed") return flag(machine_.adaptive_feed);
    if (name == "_feed_hold") return flag(machine_.feed_hold);
    if (name == "_u" || name == "_v" || name == "_w") return v = 0, true;  // no such axes
    return false;
}

double Interp::get(const std::string& name, std::span<const double>) {
    // LinuxCNC's predefined named parameters (read only) first, then the program's.
    const bool inch = st_.inch;
    if (name == "_value") return value_;
    if (name == "_value_returned") return value_returned_ ? 1 : 0;
    if (name == "_call_level") return static_cast<double>(frames_.size() - 1);
    if (name == "_metric") return inch ? 0 : 1;
    if (name == "_imperial") return inch ? 1 : 0;
    if (name == "_absolute") return st_.incremental ? 0 : 1;
    if (name == "_incremental") return st_.incremental ? 1 : 0;
    if (name == "_current_tool") return tool_;
    if (name == "_selected_tool") return selected_;
    if (name == "_feed") return st_.feed_mode == G93 ? feed_ : feed_ / scale();
    if (name == "_rpm") return std::fabs(spindles_[0].speed);
    if (name.size() == 2 && name[0] == '_') {
        static constexpr char kAxes[] = "xyzabc";
        for (int j = 0; j < 6; ++j)
            if (name[1] == kAxes[j]) return pos_[j];
    }
    if (double v; mode_param(name, v)) return v;
    if (name == "_current_pocket" || name == "_selected_pocket")
        fail(code::unsupported_parameter, "#<" + name + "> (tool changer pockets) is not supported by toolcomp");
    if (const double* v = params_.named(name)) return *v;
    if (declared_before(name)) return 0;
    fail(code::named_parameter_undefined, "Named parameter #<" + name + "> not defined");
}

bool Interp::exists(const std::string& name) {
    return params_.named(name) || predefined(name) || declared_before(name);
}

namespace {
std::string lower_prefix(const std::string& s, std::size_t n) {
    std::string r;
    for (std::size_t i = 0; i < s.size() && i < n; ++i)
        r.push_back(ascii_lower(s[i]));
    return r;
}
}  // namespace

// Blanks before the keyword are skipped, as LinuxCNC does ("( MSG, x)" speaks).
void Interp::message_comment(const Comment& c) {
    const std::size_t from = c.text.find_first_not_of(" \t");
    if (from == std::string::npos) return;
    const std::string head = lower_prefix(c.text.substr(from), 6);
    if (head.rfind("msg,", 0) == 0)
        info(code::message, c.text.substr(c.text.find(',', from) + 1), c.column);
    else if ((head.rfind("debug,", 0) == 0 && (debug_output_ || params_.fanuc())) || head.rfind("print,", 0) == 0)
        info(code::message, substitute(c.text.substr(c.text.find(',', from) + 1)), c.column);
    else if (head.rfind("abort,", 0) == 0 && profile_.abort_comment)
        // LinuxCNC 2.9 stops the program with the text, parameters substituted, before the
        // block's motion.
        fail(code::abort, substitute(c.text.substr(c.text.find(',', from) + 1)), c.column);
}

std::string Interp::substitute(const std::string& text) {
    // (DEBUG, ...) and (PRINT, ...): #n and #<name> become their values.
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] != '#') {
            out.push_back(text[i]);
            continue;
        }
        std::size_t j = i + 1;
        if (j < text.size() && text[j] == '<') {
            const std::size_t close = text.find('>', j);
            if (close == std::string::npos) {
                out.push_back('#');
                continue;
            }
            std::string name;
            for (std::size_t k = j + 1; k < close; ++k)
                if (text[k] != ' ' && text[k] != '\t') name.push_back(ascii_lower(text[k]));
            const double* v = params_.named(name);
            // LinuxCNC's read-only #<_x>, #<_feed>, ... are values too
            out += v ? printf_number("%f", *v) : predefined(name) ? printf_number("%f", get(name, {})) : "######";
            i = close;
            continue;
        }
        std::size_t k = j;
        while (k < text.size() && ascii_digit(text[k])) ++k;
        if (k == j) {
            out.push_back('#');
            continue;
        }
        const int n = std::stoi(text.substr(j, std::min<std::size_t>(k - j, 7)));
        double v = 0;
        if (!system_param(n, v)) v = params_.stored(n) ? params_.get(n) : 0;
        out += printf_number("%f", v);
        i = k - 1;
    }
    return out;
}

InterpretOutput Interp::output() const { return {files_, params_.snapshot(), edited_tools_, dwell_seconds_}; }

}  // namespace toolcomp::iso
