// Variables of Sinumerik programs: R parameters (R0..R999, R[n]), local user data (DEF REAL/
// INT/BOOL, arrays of one or two dimensions), the tool system variables $TC_DPn[t,d] and
// $TC_CARRn[m], $P_TOOLNO / $P_TOOL, and the value-returning calls GETTCOR and LENTOAX.
#include <cmath>

#include "interp.hpp"
#include "toolcomp/program/codes.hpp"
#include "toolcomp/program/int_value.hpp"
#include "toolcomp/program/text.hpp"
#include "toolcomp/tools/sinumerik_gettcor.hpp"
#include "toolcomp/tools/sinumerik_lentoax.hpp"
#include "toolcomp/tools/sinumerik_settcor.hpp"
#include "toolcomp/tools/tool_table.hpp"

namespace toolcomp::sinumerik {

namespace {
// "$TC_DP12" -> 12 for prefix "$TC_DP"; 0 when the name is not prefix + number.
int numbered(const std::string& name, std::string_view prefix) {
    if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) return 0;
    int n = 0;
    for (std::size_t i = prefix.size(); i < name.size(); ++i) {
        if (!ascii_digit(name[i]) || n > 100000) return 0;
        n = n * 10 + (name[i] - '0');
    }
    return n;
}
int as_index(double v) { return int_value(v); }
}  // namespace

std::optional<std::size_t> Variable::at(std::span<const double> idx) const {
    const std::size_t rows = cols ? v.size() / cols : v.size();
    auto index = [](double x, std::size_t n) -> std::optional<std::size_t> {
        const int i = as_index(x);
        if (i < 0 || static_cast<std::size_t>(i) >= n) return std::nullopt;
        return static_cast<std::size_t>(i);
    };
    if (idx.empty()) return v.size() == 1 ? std::optional<std::size_t>(0) : std::nullopt;
    if (idx.size() == 1 && !cols) return index(idx[0], v.size());
    if (idx.size() == 2 && cols) {
        auto r = index(idx[0], rows), c = index(idx[1], cols);
        if (r && c) return *r * cols + *c;
    }
    return std::nullopt;
}

Variable* Interp::find_variable(const std::string& name) {
    auto& locals = stack_.back().locals;
    if (auto it = locals.find(name); it != locals.end()) return &it->second;
    if (auto it = globals_.find(name); it != globals_.end()) return &it->second;
    return nullptr;
}

double Interp::get(const std::string& name, std::span<const double> idx) {
    if (name == "R" && idx.size() == 1) {
        int i = as_index(idx[0]);
        if (i < 0 || i >= static_cast<int>(r_.size())) fail(code::alarm_17020, "17020 Illegal array index: R[" + std::to_string(i) + "]");
        return r_[static_cast<std::size_t>(i)];
    }
    if (int n = numbered(name, "R"); (n > 0 || name == "R0") && idx.empty()) {
        if (n >= static_cast<int>(r_.size())) fail(code::alarm_12550, "12550 Name " + name + " not defined");
        return r_[static_cast<std::size_t>(n)];
    }
    if (Variable* v = find_variable(name)) {
        if (v->r_index >= 0) {  // a VAR parameter standing for an R parameter
            if (!idx.empty()) fail(code::alarm_17020, "17020 Illegal array index of " + name);
            return r_[static_cast<std::size_t>(v->r_index)];
        }
        const auto [store, at] = element(*v, idx, name, 0);
        if (store->text) throw expr::TextValue{};  // evaluated with strings
        return store->v[at];
    }
    if (int n = numbered(name, "$TC_DP")) {
        if (idx.size() != 2) fail(code::alarm_17020, "17020 " + name + " needs the indices [t, d]");
        auto it = edges_.find({as_index(idx[0]), as_index(idx[1])});
        if (it == edges_.end()) fail(code::alarm_17180, "17180 Illegal D number: no cutting edge D" + std::to_string(as_index(idx[1])) +
                                                  " of T" + std::to_string(as_index(idx[0])));
        try {
            return it->second.DP(n);
        } catch (const Error& e) {
            fail(code::alarm_12550, "12550 Name " + name + " not defined");
        }
    }
    if (int n = numbered(name, "$TC_CARR")) {
        if (idx.size() != 1) fail(code::alarm_17020, "17020 " + name + " needs the index [m]");
        auto it = holders_.find(as_index(idx[0]));
        if (it == holders_.end()) return 0;
        const Toolholder& h = it->second;
        const Vec3* vecs[] = {&h.l1, &h.l2, &h.v1, &h.v2};
        if (n >= 1 && n <= 12) return (*vecs[(n - 1) / 3])[(n - 1) % 3];
        if (n == 13) return h.alpha1;
        if (n == 14) return h.alpha2;
        if (n >= 15 && n <= 17) return h.l3[n - 15];
        if (n >= 18 && n <= 20) return h.l4[n - 18];
        if (n == 24) return h.offset1;
        if (n == 25) return h.offset2;
        fail(code::alarm_12550, "12550 " + name + " cannot be read as a number");
    }
    if (const auto md = machine_datum(name, idx)) return *md;
    if (const auto c = frame_component(name, idx)) return *c;
    if (name == "$P_SUBPAR") {  // was parameter n of this PROC given in the call?
        const std::vector<bool>& given = stack_.back().subpar;
        const int n = idx.size() == 1 ? as_index(idx[0]) : 0;
        if (n < 1 || n > static_cast<int>(given.size()))
            fail(code::alarm_17020, "17020 Illegal array index of $P_SUBPAR: the subprogram has " +
                                        std::to_string(given.size()) + " parameters");
        return given[static_cast<std::size_t>(n - 1)];
    }
    if (name == "$P_TOOLNO" && idx.empty()) return tool_;
    if (name == "$P_TOOL" && idx.empty()) return d_;
    fail(code::alarm_12550, "12550 Name " + name + " not defined");
}

// Where a variable's element lives: the variable itself, or for a VAR parameter the caller's
// variable (one element of it, or a whole array the indices then address).
std::pair<Variable*, std::size_t> Interp::element(Variable& v, std::span<const double> idx, const std::string& name, int column) {
    Variable* store = v.ref ? v.ref : &v;
    std::optional<std::size_t> flat;
    if (v.ref && !v.whole) flat = idx.empty() ? std::optional<std::size_t>(v.ref_at) : std::nullopt;
    else flat = store->at(idx);
    if (!flat) fail(code::alarm_17020, "17020 Illegal array index of " + name, column);
    return {store, *flat};
}

// The axis a name stands for: an axis (X, Y, Z, A, B, C), $P_AXN1 / 2 / 3 (the abscissa,
// ordinate and applicate of the active plane), or an AXIS variable's axis.
std::optional<std::string> Interp::axis_named(const std::string& n) {
    if (n.size() == 1 && std::string_view("XYZABC").find(n[0]) != std::string_view::npos) return n;
    if (n.size() == 7 && n.rfind("$P_AXN", 0) == 0 && n[6] >= '1' && n[6] <= '3') {
        const PlaneAxes ax = axes(st_.plane);
        return std::string(1, "XYZ"[n[6] == '1' ? ax.a : n[6] == '2' ? ax.b : ax.c]);
    }
    if (Variable* v = find_variable(n); v && (v->ref ? v->ref->axis : v->axis)) return text(n, {});
    return std::nullopt;
}

// An AXIS value: what axis_named() names, or AXNAME("X").
std::string Interp::axis_value(const expr::Expr& e, int column) {
    std::optional<std::string> a;
    if (e.code.size() == 1 && e.code[0].op == expr::Op::variable && e.code[0].argc == 0)
        a = axis_named(e.names[e.code[0].name]);
    else if (e.code.size() == 2 && e.code[0].op == expr::Op::text && e.code[1].op == expr::Op::call &&
             e.code[1].fn == expr::Fn::axname)
        a = axis_named(to_upper_ascii(e.texts[e.code[0].name]));
    if (!a) fail(code::alarm_12330, "12330 An axis (X, Y, Z, A, B, C or an AXIS variable) expected", column);
    return *a;
}

std::optional<std::string> Interp::text(const std::string& name, std::span<const double> idx) {
    Variable* v = find_variable(name);
    if (!v && idx.empty()) return axis_named(name);  // axes as values among strings: IF _AX == X
    if (!v || v->r_index >= 0 || !(v->ref ? v->ref->text : v->text)) return std::nullopt;
    const auto [store, at] = element(*v, idx, name, 0);
    return store->s[at];
}

// A STRING variable (or element) set to `value`, at most its declared length.
void Interp::set_text(Variable& var, std::span<const double> idx, const std::string& name, std::string value, int column) {
    const auto [store, at] = element(var, idx, name, column);
    if (value.size() > store->length)
        fail(code::string_too_long, name + ": \"" + value + "\" is longer than its STRING[" + std::to_string(store->length) + "]", column);
    store->s[at] = std::move(value);
}

void Interp::set_variable(const std::string& name, std::span<const double> idx, double v, int column) {
    if (name == "R" && idx.size() == 1) {
        int i = as_index(idx[0]);
        if (i < 0 || i >= static_cast<int>(r_.size())) fail(code::alarm_17020, "17020 Illegal array index: R[" + std::to_string(i) + "]", column);
        r_[static_cast<std::size_t>(i)] = v;
        return;
    }
    if (int n = numbered(name, "R"); (n > 0 || name == "R0") && idx.empty()) {
        if (n >= static_cast<int>(r_.size())) fail(code::alarm_12550, "12550 Name " + name + " not defined", column);
        r_[static_cast<std::size_t>(n)] = v;
        return;
    }
    if (Variable* var = find_variable(name)) {
        if (var->r_index >= 0) {  // a VAR parameter standing for an R parameter
            if (!idx.empty()) fail(code::alarm_17020, "17020 Illegal array index of " + name, column);
            r_[static_cast<std::size_t>(var->r_index)] = v;
            return;
        }
        const auto [store, at] = element(*var, idx, name, column);
        if (store->text) fail(code::math_error, "14051 Arithmetic error in part program: a number for the STRING " + name, column);
        store->v[at] = store->integer ? std::round(v) : v;
        return;
    }
    if (set_frame_component(name, idx, v, column)) return;
    if (int n = numbered(name, "$TC_DP")) {
        if (idx.size() != 2) fail(code::alarm_17020, "17020 " + name + " needs the indices [t, d]", column);
        int t = as_index(idx[0]), d = as_index(idx[1]);
        if (t < 1 || t > 32000 || d < 1 || d > 32000)
            fail(code::alarm_17180, "17180 Illegal T or D number in " + name + "[" + std::to_string(t) + "," + std::to_string(d) + "]", column);
        try {
            edges_[{t, d}].DP(n) = v;
        } catch (const Error&) {
            fail(code::alarm_12550, "12550 Name " + name + " not defined", column);
        }
        return;
    }
    if (machine_data_name(name)) {
        const std::string key = machine_data_key(name, idx);
        if (name[1] == 'S') {  // setting data: written, read back from here on
            setting_data_[key] = v;
            return;
        }
        diags_.push_back({code::alarm_4075, Severity::warning,
                          "4075 Machine data " + key + " not changed due to missing permission level (the program goes on)",
                          {line_, column}});
        return;
    }
    if (int n = numbered(name, "$TC_CARR")) {
        if (idx.size() != 1) fail(code::alarm_17020, "17020 " + name + " needs the index [m]", column);
        try {
            holders_[as_index(idx[0])].set(n, v);
        } catch (const Error& e) {
            fail(e.code(), e.what(), column);
        }
        return;
    }
    fail(code::alarm_12550, "12550 Name " + name + " not defined", column);
}

bool Interp::machine_data_name(const std::string& name) {
    return name.size() > 4 && name[0] == '$' && (name[1] == 'M' || name[1] == 'S') &&
           (name[2] == 'N' || name[2] == 'C' || name[2] == 'A') && name[3] == '_';
}

// $MN_ / $MC_ / $MA_ machine data and $SN_ / $SC_ / $SA_ setting data: the setting data the
// program wrote, the machine file's [machine_data], or the plain 840D's values of the few
// programs read most (inch scaling 25.4, metric system, 1000 increments a mm, the edge M6
// selects); any other is 12550 naming the machine file.
// An indexed datum's name as the machine file writes it: "$MA_AX_VELO_LIMIT[X]" (an axis
// index comes merged into the name from the lexer), "$MN_USER_DATA_INT[3]", "$MA_X[1,Z]".
std::string Interp::machine_data_key(const std::string& name, std::span<const double> idx) {
    if (idx.empty()) return name;
    std::string key = name.find('[') == std::string::npos ? name + "[" : name.substr(0, name.size() - 1) + ",";
    for (std::size_t i = 0; i < idx.size(); ++i) {
        if (idx[i] != std::floor(idx[i]) || std::fabs(idx[i]) > 1e9)
            fail(code::alarm_17020, "17020 Illegal array index of " + name + ": " + shortest_number(idx[i]));
        key += (i ? "," : "") + std::to_string(static_cast<long>(idx[i]));
    }
    return key + "]";
}

std::optional<double> Interp::machine_datum(const std::string& base, std::span<const double> idx) {
    if (!machine_data_name(base)) return std::nullopt;
    const std::string name = machine_data_key(base, idx);
    if (auto it = setting_data_.find(name); it != setting_data_.end()) return it->second;
    if (opts_.machine)
        if (auto it = opts_.machine->machine_data.find(name); it != opts_.machine->machine_data.end()) return it->second;
    if (name == "$MN_SCALING_VALUE_INCH") return kMmPerInch;
    if (name == "$MN_SCALING_SYSTEM_IS_METRIC") return 1;
    if (name == "$MN_INT_INCR_PER_MM") return 1000;
    if (name == "$MC_CUTTING_EDGE_DEFAULT") return profile_.cutting_edge_default;
    fail(code::alarm_12550, "12550 Name " + name + " not defined: give its value in the machine file's [machine_data]");
}

void Interp::define(std::span<const Token> t) {
    const std::string& type = t[0].text;
    if (type != "REAL" && type != "INT" && type != "BOOL" && type != "STRING" && type != "AXIS")
        fail(code::unsupported_word, "DEF " + type + " variables are not supported by toolcomp (REAL, INT, BOOL, STRING, AXIS are)", t[0].column);
    auto& locals = stack_.back().locals;
    for (std::size_t i = 1; i < t.size(); ++i) {
        const Token& v = t[i];
        if (v.key != "DEFVAR") continue;
        if (locals.count(v.text)) fail(code::alarm_12170, "12170 Name " + v.text + " defined several times", v.column);
        if (v.text == "R" || (v.text[0] == 'R' && v.text.find_first_not_of("0123456789", 1) == std::string::npos) ||
            v.text[0] == '$')
            fail(code::alarm_12170, "12170 Name " + v.text + " is reserved", v.column);
        Variable var;
        var.integer = type == "INT" || type == "BOOL";
        var.text = type == "STRING" || type == "AXIS";
        var.axis = type == "AXIS";
        var.length = type == "STRING" ? static_cast<std::size_t>(t[0].value) : var.axis ? 8 : 0;
        std::size_t n = v.has_value ? static_cast<std::size_t>(v.value) : 1;
        if (v.param > 0) {
            var.cols = static_cast<std::size_t>(v.param);
            n *= var.cols;
        }
        if (n > 100000) fail(code::alarm_12170, "12170 Array " + v.text + " too large", v.column);
        if (var.text) {
            var.v.assign(n, 0.0);  // the shape at() reads
            var.s.assign(n, std::string());
            if (v.expr >= 0) {
                const expr::Expr& init = stack_.back().prog->expression(v.expr);
                std::string x = var.axis ? axis_value(init, v.column) : eval_string(init, v.column);
                if (x.size() > var.length)
                    fail(code::string_too_long, v.text + ": \"" + x + "\" is longer than its STRING[" + std::to_string(var.length) + "]", v.column);
                for (std::string& e : var.s) e = x;
            }
            locals.emplace(v.text, std::move(var));
            continue;
        }
        var.v.assign(n, 0.0);
        if (v.expr >= 0) {
            double x = eval(v.expr, v.column);
            for (double& e : var.v) e = var.integer ? std::round(x) : x;
        }
        locals.emplace(v.text, std::move(var));
    }
}

// An assignment's target: the variable's name, its indices evaluated into `idx` (the code
// before the target's last instruction leaves them on the stack).
std::string Interp::assignment_target(const Token& t, std::vector<double>& idx) {
    const expr::Expr& target = stack_.back().prog->expression(t.param);
    expr::Expr idx_code = target;
    const expr::Instr var = idx_code.code.back();
    idx_code.code.pop_back();
    try {
        expr::evaluate_all(idx_code, *this, idx);
    } catch (const expr::MathError& err) {
        fail(code::math_error, std::string("14051 Arithmetic error in part program: ") + err.what(), t.column);
    }
    return target.names[var.name];
}

void Interp::assign(const Token& t) {
    std::vector<double> idx;
    const std::string name = assignment_target(t, idx);
    if (Variable* v = find_variable(name); v && v->r_index < 0 && (v->ref ? v->ref->text : v->text)) {
        if (v->ref ? v->ref->axis : v->axis) {
            if (t.expr < 0) fail(code::alarm_12330, "12330 " + name + " is an AXIS: assign it an axis (X, Y, Z, A, B, C)", t.column);
            return set_text(*v, idx, name, axis_value(stack_.back().prog->expression(t.expr), t.column), t.column);
        }
        return set_text(*v, idx, name,
                        t.expr >= 0 ? eval_string(stack_.back().prog->expression(t.expr), t.column)
                                    : t.text.substr(1, t.text.size() - 2),  // "text" as written
                        t.column);
    }
    if (!t.text.empty() && t.text.front() == '"') {
        if (find_variable(name) || numbered(name, "R") > 0 || name == "R")
            fail(code::math_error, "14051 Arithmetic error in part program: a string (" + t.text + ") where a number is expected", t.column);
        int n = numbered(name, "$TC_CARR");
        if (!n || idx.size() != 1) fail(code::unsupported_word, "String values are only supported for $TC_CARR21/22/23/34", t.column);
        try {
            holders_[as_index(idx[0])].set_text(n, t.text.substr(1, t.text.size() - 2));
        } catch (const Error& e) {
            fail(e.code(), e.what(), t.column);
        }
        return;
    }
    set_variable(name, idx, eval(t.expr, t.column), t.column);
}

std::vector<std::string> Interp::split_args(const std::string& text) {
    std::vector<std::string> out(1);
    int depth = 0;
    bool quote = false;
    for (char c : text) {
        if (c == '"') quote = !quote;
        if (!quote && (c == '(' || c == '[')) ++depth;
        if (!quote && (c == ')' || c == ']')) --depth;
        if (!quote && depth == 0 && c == ',') {
            out.emplace_back();
            continue;
        }
        out.back().push_back(c);
    }
    for (auto& s : out) {
        std::size_t b = s.find_first_not_of(" \t"), e = s.find_last_not_of(" \t");
        s = b == std::string::npos ? "" : s.substr(b, e - b + 1);
    }
    return out;
}

void Interp::value_call(const Token& t) {
    auto args = split_args(t.text);
    auto string_arg = [&](std::size_t i) -> std::string {
        if (i >= args.size() || args[i].empty()) return "";
        const std::string& a = args[i];
        if (a.size() < 2 || a.front() != '"' || a.back() != '"')
            fail(code::unsupported_word, t.key + ": argument " + std::to_string(i + 1) + " must be a string in quotes", t.column);
        return a.substr(1, a.size() - 2);
    };
    auto array_arg = [&](std::size_t i, std::size_t size) -> Variable& {
        std::string n = i < args.size() ? args[i] : "";
        for (char& c : n) c = ascii_upper(c);
        Variable* v = n.empty() ? nullptr : find_variable(n);
        if (!v) fail(code::alarm_12550, "12550 Name " + (n.empty() ? std::string("(missing)") : n) + " not defined: " + t.key +
                                  " needs a REAL array of " + std::to_string(size) + " elements", t.column);
        if (v->v.size() < size)
            fail(code::alarm_17020, "17020 " + t.key + ": array " + n + " has fewer than " + std::to_string(size) + " elements", t.column);
        return *v;
    };
    int status = 0;
    if (t.key == "GETTCOR") {
        Variable& len = array_arg(0, 11);
        GettcorSettings s;
        s.plane = st_.plane;
        s.lengths = opts_.lengths;
        s.set_parameter_def_mask(opts_.tool_parameter_def_mask);
        const std::string comp = args.size() > 1 ? string_arg(1) : "";
        const std::string stat = string_arg(2);
        auto num = [&](std::size_t i, int dflt) {
            return i < args.size() && !args[i].empty() ? as_index(eval_text(args[i], t.column)) : dflt;
        };
        const int tt = num(3, -1), dd = num(4, -1), dl = num(5, -1);
        std::array<double, 11> out{};
        if (tt >= 0 || dd >= 0) {
            const int t2 = tt >= 0 ? tt : tool_, d2 = dd >= 0 ? dd : d_;
            if (!edges_.count({t2, d2}))
                if (auto e = table_edge(t2, d2)) edges_[{t2, d2}] = *e;
            status = gettcor(out, comp, edges_, t2, d2, s, stat, dl);
        } else if (const SinumerikEdge* e = edge()) {
            status = gettcor(out, comp, *e, s, stat, dl);
        } else {
            status = tool_ == 0 ? gettcor_bad_t : gettcor_bad_d;
        }
        if (status == 0)
            for (std::size_t i = 0; i < 11; ++i) len.v[i] = len.integer ? std::round(out[i]) : out[i];
    } else if (t.key == "LENTOAX") {
        Variable& axind = array_arg(0, 3);
        Variable& matrix = array_arg(1, 9);
        const std::string coord = args.size() > 2 && !args[2].empty() ? string_arg(2) : "W";
        const SinumerikEdge* e = edge();
        LentoaxResult r = lentoax(e ? e->type() : 120, st_.plane, opts_.lengths, coord);
        status = r.status;
        if (status == 0) {
            for (std::size_t i = 0; i < 3; ++i) axind.v[i] = r.axind[i];
            for (std::size_t i = 0; i < 9; ++i) matrix.v[i] = r.matrix(static_cast<long>(i / 3), static_cast<long>(i % 3));
        }
    } else if (t.key == "SETTCOR") {
        Variable& corval = array_arg(0, 3);
        const std::string comp = args.size() > 1 ? string_arg(1) : "";
        auto num = [&](std::size_t i, int dflt) {
            return i < args.size() && !args[i].empty() ? as_index(eval_text(args[i], t.column)) : dflt;
        };
        const int corcomp = num(2, 0), cormode = num(3, 0), geoax = num(4, 0);
        const int tt = num(5, tool_), dd = num(6, d_), dl = num(7, -1);
        if (dl > 1) {
            status = gettcor_bad_dl;
        } else {
            // A tool of the ToolTable joins the program's $TC_DP data when it is corrected.
            if (!edges_.count({tt, dd}))
                if (auto e = table_edge(tt, dd)) edges_[{tt, dd}] = *e;
            status = settcor(edges_, tt, dd, Vec3(corval.v[0], corval.v[1], corval.v[2]), comp, corcomp, cormode, geoax,
                             st_.plane, opts_.lengths);
        }
    } else {
        fail(code::unsupported_word, t.key + " is not supported by toolcomp yet", t.column);
    }
    if (t.param > 0) {
        Token target;
        target.param = t.param - 1;
        const expr::Expr& te = stack_.back().prog->expression(target.param);
        if (te.code.size() == 1) {
            set_variable(te.names[te.code[0].name], {}, status, t.column);
        } else {
            fail(code::unsupported_word, "The status of " + t.key + " must go to a plain variable", t.column);
        }
    }
}

}  // namespace toolcomp::sinumerik
