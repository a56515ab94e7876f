// Klartext block execution: program frame, tools, straight lines, feeds, M functions and
// radius compensation requests. Arcs, polar moves, RND and CHF are in contour.cpp.
#include <algorithm>
#include "toolcomp/program/codes.hpp"
#include "toolcomp/program/text.hpp"
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "codes.hpp"
#include "interp.hpp"
#include "toolcomp/tools/format_heidenhain.hpp"
#include "toolcomp/program/input_limits.hpp"
#include "toolcomp/program/int_value.hpp"
#include "qparams.hpp"
#include "toolcomp/dialects/heidenhain/lexer.hpp"
#include "toolcomp/tools/tool_table.hpp"

namespace toolcomp::heidenhain {

Interp::Interp(const Program& prog, const ToolTable* tools, const ControlProfile& profile, MotionSink& sink,
               std::vector<Diagnostic>& diags, SearchPath search)
    : prog_(prog), search_(std::move(search)), tools_(tools), profile_(profile), sink_(sink), diags_(diags), unit_(prog.inch ? kMmPerInch : 1.0) {}

void Interp::fail(const char* code, const std::string& msg, int column) const {
    throw ProgramError(code, msg, {line_, column, file_ > 0 ? files_.names()[static_cast<std::size_t>(file_)] : std::string()});
}

const Token* Interp::find(Tokens t, std::string_view key) const {
    for (const Token& k : t)
        if (k.key == key) return &k;
    return nullptr;
}

std::optional<double> Interp::number(Tokens t, std::string_view key) const {
    const Token* k = find(t, key);
    if (!k) return std::nullopt;
    if (!k->has_value) fail(code::missing_value, std::string(key) + " needs a value", k->column);
    return k->value;
}

Vec3 Interp::with_plane(const Vec3& v, const Vec2& ab) const { return toolcomp::with_plane(v, ab, plane_); }

Vec3 Interp::end_point(Tokens t, std::size_t from) const {
    Vec3 e = pos_;
    static constexpr std::string_view names[3] = {"X", "Y", "Z"};
    static constexpr std::string_view inc[3] = {"IX", "IY", "IZ"};
    for (std::size_t i = from; i < t.size(); ++i) {
        for (int a = 0; a < 3; ++a) {
            if (t[i].is(names[a]) && t[i].has_value) e[a] = t[i].value;
            if (t[i].is(inc[a]) && t[i].has_value) e[a] = pos_[a] + t[i].value;
        }
    }
    return e;
}

// Refuses a word of `names` (from token `from` on) that this kind of block would not read:
// it would be dropped, and the path would not be the one the program asks for.
void Interp::refuse_words(Tokens t, std::initializer_list<std::string_view> names, const char* why,
                          std::size_t from) const {
    for (std::size_t i = from; i < t.size(); ++i)
        for (std::string_view n : names)
            if (t[i].key == n)
                fail(code::bad_word, std::string(n) + " is not read in " + (t[0].key == "APPR" || t[0].key == "DEP" ? t[0].key + " " + t[1].key : t[0].key.str()) +
                                     " blocks: " + why,
                     t[i].column);
}

// Words that can stand in any positioning block: radius compensation, feed, M functions.
void Interp::modal_words(Tokens t, std::size_t from) {
    for (std::size_t i = from; i < t.size(); ++i) {
        const Token& k = t[i];
        if (k.is("RL") || k.is("RR") || (k.is("R") && k.has_value && k.value == 0 && !t[0].is("CR"))) {
            const int side = k.is("RL") ? 1 : k.is("RR") ? -1 : 0;
            if (side != 0 && side_ != 0 && side != side_) fail(code::comp_side_change, profile_.radius.messages.side_change, k.column);
            if (side == 0 && side_ != 0) {
                settle_pending();
                if (pending_) {
                    sink_.push(*pending_);
                    pending_.reset();
                }
                sink_.control({ControlKind::radius_off, line_, Vec3::Zero(), file_});
                lookahead_ = 0;
            }
            side_ = side;
        } else if (k.is("R") && k.sign_only) {
            if (!t[0].is("L")) fail(code::paraxial_not_line, "R+/R- only in L blocks", k.column);
            if (side_ != 0) fail(code::paraxial_with_comp, "R+/R- cannot be combined with RL/RR", k.column);
            paraxial_ = static_cast<int>(k.value);  // applied by line()
        } else if (k.is("F") && k.has_value) {
            feed_ = k.value * (prog_.inch ? 2.54 : 1.0);  // mm/min, or 1/10 inch/min in INCH programs
        } else if (k.is("FMAX")) {
            rapid_ = true;
        } else if (k.is("FAUTO")) {
            fail(code::unsupported_word, "FAUTO is not supported by toolcomp", k.column);
        } else if (k.is("M") && k.has_value) {
            m_function(t, k);
        } else if (k.is("S") && k.has_value) {
            speed_ = k.value;
        }
    }
}

// An M function of a positioning block (L, C, APPR, DEP, ...): the ones that change the path
// are taken, the machine functions without a geometric effect pass, the rest are refused.
void Interp::m_function(Tokens t, const Token& k) {
    int m = int_value_truncated(k.value);
    // A builder code of the machine stands for the standard code of its action.
    if (const MachineCode* code = machine_ ? machine_->m_code(m) : nullptr) {
        m = standard_m_code(code->action);
        if (m < 0) return;
    }
    switch (m) {
        case M97: m97_ = true; break;
        case M98: open_corner_ = true; break;
        case M120: {
            const Token* la = find(t, "LA");
            lookahead_ = la && la->has_value ? int_value_truncated(la->value) : 0;
            if (lookahead_ > 99 || lookahead_ < 0) fail(code::bad_lookahead, "M120 LA allows 0 to 99 blocks", la->column);
            break;
        }
        case M107: m107_ = true; break;
        case M108: m107_ = false; break;
        case M128: m128_ = true; break;
        case M129: m128_ = false; break;
        case M2: case M30: ended_ = true; break;  // end of the program (after this block's move)
        case M140:  // retraction along the tool axis (line(): MB)
            if (!t[0].is("L")) fail(code::bad_word, "M140 acts in L blocks only (toolcomp)", k.column);
            break;
        case M99:  // the cycle runs at the end of the block (execute); M89 ends
            cycle_call_pending_ = true;
            modal_call_ = false;
            break;
        case M89:  // the modal cycle call: this block and every positioning block after it
            if (profile_.m89_modal_cycle_call) cycle_call_pending_ = modal_call_ = true;
            break;
        case M126: shortest_rotary_ = true; break;
        case M127: shortest_rotary_ = false; break;
        case M0: case M1: case M3: case M4: case M5: case M6: case M8: case M9: case M13: case M14:
        case M90:
            break;  // machine functions without a geometric effect on the path
        case M91: case M92:  // machine datums: the L block reads its coordinates from them
            if (!t[0].is("L"))
                fail(code::bad_word, "M" + std::to_string(m) + " acts in L blocks only (toolcomp)", k.column);
            break;
        default:
            fail(code::unsupported_m_code, "M" + std::to_string(m) + " is not supported by toolcomp", k.column);
    }
}

Motion Interp::motion_to(MotionKind kind, const Vec3& end) const {
    Motion m;
    m.kind = kind;
    m.plane = plane_;
    m.start = pos_;
    m.end = end;
    m.abc = abc_;
    m.line = line_;
    m.file = file_;
    m.tool = tool_;
    m.tool_offset = tlo_;
    m.work_offset = work_origin_;  // the moves are in the machine's axes less the preset
    m.unit = unit_;
    m.feed = kind == MotionKind::rapid ? std::nan("") : feed_;
    m.radius.side = static_cast<std::int8_t>(side_);
    // Peripheral milling with M128 and RL/RR: the tool is displaced by the deltas ΣDR only
    // (an undersize tool, ΣDR < 0, moves towards the contour: the other side).
    m.radius.radius = m128_ ? sum_dr_ : radius_;
    if (m.radius.radius < 0) {
        m.radius.radius = -m.radius.radius;
        m.radius.side = static_cast<std::int8_t>(-m.radius.side);
    }
    m.tool_axis = Vec3::Zero();
    m.tool_axis[axes(working_plane_.value_or(plane_)).c] = 1;
    if (m.is_arc() && !frame().conformal_in(m.plane))
        fail(code::scaling_refused, "An arc under axis-specific scaling (CYCL DEF 26) with different factors in its plane "
                                    "would be an ellipse: the TNC refuses it");
    m.radius.corner_at_intersection = m97_;
    m.radius.open_corner = open_corner_;
    m.radius.lookahead = static_cast<std::int8_t>(lookahead_);
    return m;
}

void Interp::tool_def(Tokens t) {
    if (t.size() < 3 || !t[2].has_value || !t[2].key.empty()) fail(code::tool_def, "TOOL DEF needs a tool number");
    ToolDef d;
    d.length = number(t, "L").value_or(0);
    d.radius = number(t, "R").value_or(0);
    d.r2 = number(t, "R2").value_or(0);
    if (d.r2 < 0 || (d.radius >= 0 && d.r2 > d.radius))
        fail(code::tool_def, "TOOL DEF: R2 must lie between 0 and R (the corner radius of the tool)", t[0].column);
    if (!(t[2].value >= 0 && t[2].value <= 32767))
        fail(code::tool_def, "TOOL DEF: tool number out of range 0..32767", t[2].column);
    defs_[int_value(t[2].value)] = d;
}

// TOOL CALL n|"name" X|Y|Z [S] [F] [DL] [DR] [DR2]: the tool axis sets the working plane;
// effective length L + DL(TOOL CALL) + DL(table), radius R + DR(TOOL CALL) + DR(table).
void Interp::tool_call(Tokens t) {
    std::size_t i = 2;
    int number_ = -1;
    const Tool* table_tool = nullptr;
    if (i < t.size() && t[i].key.empty() && t[i].has_value) {
        if (std::fabs(t[i].value - std::round(t[i].value)) > 1e-9)
            fail(code::unsupported_tool_index, "Tool indexes (TOOL CALL n.i) are not supported by toolcomp", t[i].column);
        if (!(t[i].value >= 0 && t[i].value <= 32767))
            fail(code::tool_call, "TOOL CALL: tool number out of range 0..32767", t[i].column);
        number_ = int_value(t[i].value);
        ++i;
    } else if (i < t.size() && !t[i].text.empty()) {
        if (tools_)
            for (const Tool& tool : tools_->tools())
                if (tool.name == t[i].text) table_tool = &tool;
        if (!table_tool) fail(code::tool_not_found, "Tool \"" + t[i].text + "\" not found in the tool table", t[i].column);
        number_ = table_tool->number;
        ++i;
    }
    for (; i < t.size(); ++i) {
        const std::string_view k = t[i].key;
        if ((k == "X" || k == "Y" || k == "Z") && !t[i].has_value)
            plane_ = k == "Z" ? Plane::xy : k == "Y" ? Plane::zx : Plane::yz;
        else if ((k == "X" || k == "Y" || k == "Z") && t[i].has_value)
            fail(code::bad_word, "TOOL CALL takes the tool axis without a value (" + std::string(k) + "), not a position",
                 t[i].column);
        else if (k == "F" && t[i].has_value)
            feed_ = t[i].value * (prog_.inch ? 2.54 : 1.0);
        else if (k == "S" && t[i].has_value)
            speed_ = t[i].value;
        else if (!((k == "DL" || k == "DR" || k == "DR2") && t[i].has_value))
            fail(code::bad_word, (k.empty() ? std::string("A number") : std::string(k)) + " is not read in TOOL CALL blocks",
                 t[i].column);
    }
    // Without a tool number the tool in the spindle stays (S, F, the axis or deltas change):
    // its data again, and the deltas of the TOOL CALL before unless this block gives new ones.
    axis_called_ = true;
    const bool same_tool = number_ < 0;
    if (same_tool) number_ = tool_;
    const double dl = number(t, "DL").value_or(same_tool ? call_dl_ : 0);
    const double dr = number(t, "DR").value_or(same_tool ? call_dr_ : 0);
    const double dr2 = number(t, "DR2").value_or(same_tool ? call_dr2_ : 0);
    call_dl_ = dl, call_dr_ = dr, call_dr2_ = dr2;
    double length = 0, radius = 0, dr_tab = 0, dr2_tab = 0;
    if (number_ > 0) {
        if (!table_tool && tools_) table_tool = tools_->find(number_);
        if (table_tool) {
            // TL = L in TOOL.T: the control does not use a locked tool (it takes the replacement
            // RT in its place, with checks toolcomp does not model): refused, never cut with
            // the locked tool's data.
            if (const auto tl = heidenhain_field(*tools_, number_, "TL"); tl && (*tl == "L" || *tl == "l")) {
                const auto rt = heidenhain_field(*tools_, number_, "RT");
                fail(code::tool_locked,
                     "Tool " + std::to_string(number_) + " is locked (TL = L in the tool table)" +
                         (rt && !rt->empty() ? "; its replacement tool " + *rt + " (RT) is not modelled by toolcomp"
                                             : " and has no replacement tool (RT)"),
                     t[0].column);
            }
            const CuttingEdge& e = table_tool->edge();
            length = (e.length.z() + e.length_wear.z()) / unit_;
            radius = (e.radius + e.radius_wear) / unit_;
            dr_tab = e.radius_wear / unit_;
            dr2_tab = e.corner_radius_wear / unit_;
        } else if (auto d = defs_.find(number_); d != defs_.end()) {
            length = d->second.length;
            radius = d->second.radius;
        } else {
            fail(code::tool_not_found, "Tool " + std::to_string(number_) + " is neither in the tool table nor defined");
        }
    }
    if (!same_tool) to_tool_change_position();
    if (number_ >= 0) tool_ = number_;
    radius_ = number_ == 0 ? 0 : radius + dr;
    sum_dr_ = number_ == 0 ? 0 : dr + dr_tab;
    sum_dr2_ = number_ == 0 ? 0 : dr2 + dr2_tab;
    const Vec3 before = tlo_;
    tlo_.setZero();
    tlo_[axes(plane_).c] = number_ == 0 ? 0 : length + dl;
    // On a machine the spindle stays where it stands: the tip's coordinate changes by the
    // difference of the lengths (without one the tip keeps its coordinate: doc/heidenhain.md).
    if (machine_) pos_ = frame().to_program(frame().point(pos_) + before - tlo_);
}

void Interp::line(Tokens t) {
    paraxial_ = 0;
    modal_words(t, 1);
    retract(t);
    Vec3 end = end_point(t, 1);
    machine_datum_end(t, end);
    if (paraxial_ != 0) {
        // R+ / R-: a move along one axis is lengthened / shortened by the tool radius.
        const Vec3 d = end - pos_;
        int moving = 0;
        for (int i = 0; i < 3; ++i) moving += std::fabs(d[i]) > 0;
        if (moving != 1) fail(code::paraxial_not_single_axis, "R+/R- needs a move along a single axis", t[0].column);
        refuse_scaled("R+/R-", t[0].column);
        end += paraxial_ * radius_ * d.normalized();
    }
    static constexpr std::string_view rotary[3] = {"A", "B", "C"};
    for (std::size_t i = 1; i < t.size(); ++i)
        for (int r = 0; r < 3; ++r)
            if (t[i].is(rotary[r]) && t[i].has_value)  // M126: the shorter way, the axis counting its turns
                abc_[r] = shortest_rotary_ ? abc_[r] + std::remainder(t[i].value - abc_[r], 360.0) : t[i].value;
    if (end == pos_) return;
    if (!rapid_ && feed_ <= 0) fail(code::no_feed, "No feed rate programmed");
    if (plane2(end) != plane2(pos_)) ++plane_moves_;
    last_rapid_ = rapid_;
    put(motion_to(rapid_ ? MotionKind::rapid : MotionKind::line, end));
    pos_ = end;
}

namespace {
// FN 18: (or FN18:) SYSREAD ...
bool is_sysread(std::string_view text) {
    std::size_t i = 2;
    while (i < text.size() && text[i] == ' ') ++i;
    return text.substr(i, 3) == "18:";
}
}  // namespace

bool Interp::execute(Tokens t) {
    const std::string_view k0 = t[0].key;
    const std::string_view k1 = t.size() > 1 ? std::string_view(t[1].key) : std::string_view();
    m97_ = false;
    open_corner_ = false;
    rapid_ = false;
    cycle_call_pending_ = false;
    if (k0 == "BEGIN" || k0 == "BLK") return true;
    if (k0 == "END" && k1 == "PGM") return false;
    if (k0 == "TOOL" && k1 == "DEF") tool_def(t);
    else if (k0 == "TOOL" && k1 == "CALL") tool_call(t);
    else if (k0 == "L") line(t);
    else if (k0 == "CC") circle_centre(t);
    else if (k0 == "C") arc_about_pole(t);
    else if (k0 == "CR") arc_radius(t);
    else if (k0 == "CT") arc_tangential(t);
    else if (k0 == "CTP") arc_tangential(t, /*polar=*/true);
    else if (k0 == "LP") polar_line(t);
    else if (k0 == "CP") polar_arc(t);
    else if (k0 == "RND") rounding(t);
    else if (k0 == "CHF") chamfer(t);
    else if (k0 == "M" || k0 == "F" || k0 == "S") {  // a block of machine functions only
        for (const Token& k : t)
            if (!(k.is("M") || k.is("F") || k.is("S") || k.is("FMAX")) || (!k.has_value && !k.is("FMAX")))
                fail(code::bad_word, (k.key.empty() ? std::string("A number") : k.key.str()) + " is not read in a block of M functions",
                     k.column);
        modal_words(t, 0);
    }
    else if (k0 == "STOP") {
        modal_words(t, 1);
        settle_pending();
        sink_.control({ControlKind::stop, line_, Vec3::Zero(), file_});
    } else if (k0 == "APPR") {
        approach(t);
    } else if (k0 == "DEP") {
        departure(t);
    } else if (k0 == "LN") {
        surface_line(t);
    } else if (k0 == "CYCL") {
        cycle(t);
    } else if (k0 == "PATTERN" && k1 == "DEF") {
        pattern_def(t);
    } else if (k0 == "PLANE") {
        plane_function(t);
    } else if (k0 == "FUNCTION") {
        function_block(t);
    } else
        fail(code::unknown_block, "Unknown block '" + std::string(k0) + "'", t[0].column);
    const bool positioning = k0 == "L" || k0 == "LP" || k0 == "C" || k0 == "CP" || k0 == "CR" || k0 == "CT" || k0 == "CTP";
    if (cycle_call_pending_ || (modal_call_ && positioning)) {  // M99 / M89: the cycle at the end of the block
        cycle_call_pending_ = false;
        call_cycle(t[0].column);
    }
    return true;
}

Interp::Tokens Interp::resolve(Tokens t, std::vector<Token>& scratch) const {
    if (std::none_of(t.begin(), t.end(), [](const Token& k) { return k.param > 0; })) return t;
    scratch.assign(t.begin(), t.end());
    for (Token& k : scratch)
        if (k.param > 0) {
            k.value = k.value * q_value(k.param - 1, k.column);
            k.param = 0;
        }
    return scratch;
}

// A Q parameter's value (0 until set). Q0-Q1999 exist (iTNC 530 / TNC 640; the TNC 426 has
// Q0-Q399); Q100-Q199 are set by the control itself (tool radius, tool axis, probe results,
// ...), which toolcomp does not model: reading one is refused rather than read as 0.
double Interp::q_value(int n, int column) const {
    check_q(n, column);
    if (n >= 100 && n <= 199) {
        if (const auto set = control_q_.find(n); set != control_q_.end()) return set->second;
        fail(code::q_system, "Q" + std::to_string(n) + " is set by the control (Q100 to Q199): not modelled by toolcomp" +
                                 (n >= 120 && n <= 122 ? " before CYCL DEF 19 or PLANE sets it" : ""),
             column);
    }
    auto it = q_.find(n);
    return it == q_.end() ? 0.0 : it->second;
}

void Interp::check_q(int n, int column) const {
    if (n < 0 || n > 1999) fail(code::q_out_of_range, "Q" + std::to_string(n) + " does not exist (Q0 to Q1999)", column);
}

// Runs the blocks with the program's own flow: labels (LBL n), subprogram calls (CALL LBL
// n, back at LBL 0), section repeats (CALL LBL n REP m), FN 9..12 jumps, program calls (CALL
// PGM); bounded by the profile's block limit.
void Interp::run() {
    // A main program read in pieces: each piece's blocks in turn; after its end (END PGM,
    // M2/M30) the pieces left are read for a syntax error, raised as when the file is read
    // whole.
    const Program* main = &prog_;
    bool more = run_blocks(*main, 0);  // false when the run ended (M2/M30)
    while (pieces_.next_piece && !main->syntax_error) {  // a syntax error ends the pieces
        const Program* next = pieces_.next_piece();
        if (!next) break;
        main = next;
        if (more) more = run_blocks(*main, 0);
    }
    settle_pending();
    if (approach_) throw ProgramError(code::approach_without_contour, "APPR needs a contour element after it", {approach_->line, 0});
    if (pending_) {
        sink_.push(*pending_);
        pending_.reset();
    }
    if (const auto& e = main->syntax_error) throw ParseError(e->code, e->message, e->pos);
    sink_.control({ControlKind::program_end, line_, Vec3::Zero(), file_});
    sink_.finish();
}

bool Interp::run_blocks(const Program& prog, int depth) {
    const int caller_file = file_;
    file_ = file_index(prog.name);
    struct Restore {
        int& f;
        int v;
        ~Restore() { f = v; }
    } restore{file_, caller_file};
    const auto& blocks = prog.blocks();
    // Labels by number (LBL 5) or by name (LBL "CONTOUR"), as the text LBL shows them.
    auto label_name = [](const Token& k) -> std::string {
        if (k.has_value && k.key.empty()) return std::to_string(int_value(k.value));
        if (!k.has_value && k.key.empty() && !k.text.empty()) return '"' + k.text + '"';
        return {};
    };
    // Found at the first jump: a program without one (a CAM program, read in pieces or not)
    // is not read an extra time.
    std::optional<std::map<std::string, std::size_t>> labels;
    auto label = [&](const std::string& name, const Token& at) {
        if (!labels) {
            labels.emplace();
            for (std::size_t i = 0; i < blocks.size(); ++i) {
                auto t = prog.tokens(blocks[i]);
                if (t.size() >= 2 && t[0].is("LBL") && !(t[1].has_value && t[1].value == 0) && !label_name(t[1]).empty())
                    (*labels)[label_name(t[1])] = i;
            }
        }
        auto it = labels->find(name);
        if (it == labels->end()) fail(code::label_not_found, "LBL " + name + " not found", at.column);
        return it->second;
    };
    int q_column = 0;  // the statement being run
    auto q = [this, &q_column](int n) { return q_value(n, q_column); };
    std::vector<std::size_t> returns;
    std::map<std::size_t, int> repeats;  // CALL LBL .. REP m blocks: passes left
    std::vector<Token> scratch;          // a block's tokens with Q parameters replaced
    for (std::size_t pc = 0; pc < blocks.size();) {
        auto raw = prog.tokens(blocks[pc]);
        line_ = blocks[pc].line;
        if (progress_ && (executed_ + 1) % progress_every_ == 0) progress_(executed_ + 1);
        if (++executed_ > profile_.block_limit) block_limit_exceeded(0);
        if (idle_.too_long(moves_, profile_.no_motion_limit)) [[unlikely]]
            fail(code::no_progress, no_progress_text(profile_.no_motion_limit));
        if (raw.empty() || (blocks[pc].block_delete && block_delete_)) {
            ++pc;
            continue;
        }
        if (raw[0].is("LN")) check_surface_line(raw);
        const Tokens t = resolve(raw, scratch);
        const std::string_view k0 = t[0].key;
        if (k0 == "LBL") {
            if (t.size() >= 2 && t[1].has_value && t[1].value == 0 && !returns.empty()) {
                pc = returns.back();  // end of a subprogram
                returns.pop_back();
            } else {
                ++pc;
            }
            continue;
        }
        if (k0 == "CALL" && t.size() >= 3 && t[1].is("LBL") && !label_name(t[2]).empty()) {
            const std::size_t target = label(label_name(t[2]), t[2]) + 1;
            if (const Token* rep = find(t, "REP")) {
                // REP m, or REP followed by the count as a separate number (REP 2/2)
                double m = rep->has_value ? rep->value : 0;
                if (!rep->has_value && rep + 1 < t.data() + t.size() && rep[1].key.empty() && rep[1].has_value)
                    m = rep[1].value;
                auto [it, fresh] = repeats.try_emplace(pc, int_value_truncated(m));
                if (it->second > 0) {
                    --it->second;
                    pc = target;  // run the section between LBL n and this block again
                } else {
                    repeats.erase(it);
                    ++pc;
                }
            } else {
                if (returns.size() > 64) fail(code::call_depth, "Subprogram calls nested too deeply", t[0].column);
                returns.push_back(pc + 1);
                pc = target;
            }
            continue;
        }
        if (k0 == "FN" && is_sysread(t[0].text)) {
            sysread(t[0]);
            ++pc;
            continue;
        }
        if (k0 == "FN" || k0 == "Q=") {
            QResult r;
            q_column = t[0].column;
            try {
                r = run_statement(t[0].text, q);
            } catch (const std::domain_error& e) {
                fail(code::q_math, std::string("Q parameter arithmetic: ") + e.what(), t[0].column);
            } catch (const std::invalid_argument& e) {
                fail(code::q_syntax, std::string("Q parameter statement: ") + e.what(), t[0].column);
            }
            if (r.error) fail(code::fn14_error, "FN 14: ERROR " + std::to_string(*r.error), t[0].column);
            if (r.assign) {
                check_q(*r.assign, t[0].column);
                q_[*r.assign] = r.value;
            }
            pc = r.jump ? label(*r.jump, t[0]) : pc + 1;
            continue;
        }
        if (k0 == "CALL" && t.size() >= 2 && t[1].is("PGM")) {
            call_program(t, depth);
            if (ended_) return false;  // M2/M30 in the called program
            ++pc;
            continue;
        }
        if (k0 == "CALL") fail(code::unsupported_block, "CALL without LBL or PGM is not supported by toolcomp", t[0].column);
        if (!execute(t)) return true;  // END PGM
        if (ended_) {
            if (depth > 0)
                diags_.push_back({code::call_pgm_end, Severity::warning,
                                  "M2/M30 in the called program " + prog.name +
                                      " ends the run (a called program must not contain M2 or M30)",
                                  {line_, 0}});
            return false;
        }
        ++pc;
    }
    // A called program parsed leniently stops before its first syntax error: reached here.
    if (depth > 0 && prog.syntax_error) {
        const Diagnostic& e = *prog.syntax_error;
        SourcePos at = e.pos;
        at.file = prog.name;  // the error's line is in the called file
        throw ParseError(e.code, e.message + " (in the called program " + prog.name + ")", at);
    }
    return true;
}

int Interp::file_index(const std::string& name) {
    const std::size_t known = files_.names().size();
    const int i = files_.index(name);
    if (files_.names().size() > known && pieces_.file_opened) pieces_.file_opened(name);
    return i;
}

namespace {
constexpr int kMaxProgramCallDepth = 100;  // CALL PGM nesting (endless recursion guard)

// The entry `name` of `dir` (a regular file, or a directory with `directory`), the name
// compared without regard to case when there is no exact match (TNC file names are
// case-insensitive). Only `dir` itself is listed.
std::optional<std::filesystem::path> entry_in(const std::filesystem::path& dir, const std::string& name,
                                              bool directory) {
    namespace fs = std::filesystem;
    std::error_code ec;
    // A file entry of any kind: look_in() tells a FIFO or a directory of the program's name.
    auto kind_ok = [&](const fs::path& p) { return directory ? fs::is_directory(p, ec) : fs::exists(fs::symlink_status(p, ec)); };
    if (const fs::path exact = dir / name; kind_ok(exact)) return exact;
    if (!fs::is_directory(dir, ec)) return std::nullopt;
    const std::string want = to_upper_ascii(name);
    std::optional<fs::path> found;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string n = it->path().filename().string();
        if (to_upper_ascii(n) == want && kind_ok(it->path()) && (!found || n < found->filename().string()))
            found = it->path();  // several spellings: the first in byte order, for a stable choice
    }
    return found;
}
}  // namespace

// The file of `CALL PGM name`: a TNC path (TNC:\DIR\PGM.H) loses its drive and is read
// relative to each search directory in turn; a name without a suffix is tried as given and
// with ".h". Names that would leave the search directories ("..", absolute paths after the
// drive is removed are taken as relative) are refused.
std::string Interp::find_program(const std::string& name, int column) const {
    namespace fs = std::filesystem;
    std::string rel = name;
    for (char& c : rel)
        if (c == '\\') c = '/';
    if (auto colon = rel.find(':'); colon != std::string::npos && rel.find('/') > colon) rel = rel.substr(colon + 1);
    std::vector<std::string> parts;
    for (std::size_t i = 0; i <= rel.size();) {
        std::size_t j = rel.find('/', i);
        if (j == std::string::npos) j = rel.size();
        const std::string part = rel.substr(i, j - i);
        if (part == "..")
            fail(code::call_pgm_bad_name, "CALL PGM " + name + ": '..' is not allowed in a program name", column);
        if (!part.empty() && part != ".") parts.push_back(part);
        i = j + 1;
    }
    if (parts.empty()) fail(code::call_pgm_bad_name, "CALL PGM needs a program name", column);
    std::vector<std::string> names{parts.back()};
    if (parts.back().find('.') == std::string::npos) names.push_back(parts.back() + ".h");
    for (const std::string& d : search_.dirs) {
        std::optional<fs::path> dir = fs::path(d);
        for (std::size_t k = 0; k + 1 < parts.size() && dir; ++k) dir = entry_in(*dir, parts[k], /*directory=*/true);
        if (!dir) continue;
        for (const std::string& n : names)
            if (auto f = entry_in(*dir, n, /*directory=*/false)) {
                // Within the search directory `d`, not just the subdirectory the name gave.
                const CalledEntry entry = look_in(search_, d, *f);
                if (entry.kind == CalledEntry::absent) continue;  // a link to nothing
                if (entry.kind == CalledEntry::refused) fail(entry.code.c_str(), "CALL PGM " + name + ": " + entry.message, column);
                return entry.path.string();
            }
    }
    std::string where;
    for (const std::string& d : search_.dirs) where += (where.empty() ? "" : ", ") + d;
    fail(code::call_pgm_not_found,
         "CALL PGM " + name + ": program not found" +
             (search_.dirs.empty() ? std::string(" (no search path given: RunOptions::search_path, search_path=)")
                                   : " in the search path (" + where + ")"),
         column);
}

// CALL PGM name: the TNC cancels radius compensation (and M120) at a program call, then runs
// the called program from its beginning to END PGM as a subprogram: Q parameters, the tool,
// feed, plane, pole and position carry over both ways. Its moves carry the line numbers of the
// called file and its index in Path::files.
void Interp::call_program(Tokens t, int depth) {
    const Token* name = t.size() > 2 ? &t[2] : nullptr;
    std::string text = name ? (!name->text.empty() ? name->text.str() : name->key.str()) : std::string();
    if (name && text.empty() && name->has_value) text = std::to_string(static_cast<long long>(name->value));
    if (text.empty()) fail(code::call_pgm_bad_name, "CALL PGM needs a program name", t[0].column);
    if (depth + 1 > kMaxProgramCallDepth)
        fail(code::call_pgm_depth,
             "CALL PGM " + text + ": programs nested more than " + std::to_string(kMaxProgramCallDepth) +
                 " deep (does a program call itself?)",
             t[0].column);
    const std::string file = find_program(text, t[0].column);
    if (approach_) throw ProgramError(code::approach_without_contour, "APPR needs a contour element after it", {approach_->line, 0});
    if (side_ != 0) {  // PGM CALL cancels radius compensation
        settle_pending();
        if (pending_) {
            sink_.push(*pending_);
            pending_.reset();
        }
        sink_.control({ControlKind::radius_off, line_, Vec3::Zero(), file_});
        side_ = 0;
    }
    lookahead_ = 0;
    auto& sub = called_[file];
    if (!sub) {
        CalledText f = read_called(search_, file, cr_ends_line(Dialect::heidenhain));
        if (!f.ok()) fail(f.code.c_str(), "CALL PGM " + text + ": " + f.message, t[0].column);
        sub = std::make_shared<const Program>(parse(f.text, file, /*strict=*/false));
    }
    if (sub->inch != prog_.inch)
        fail(code::call_pgm_units, "CALL PGM " + text + ": the called program is in " + (sub->inch ? "INCH" : "MM") +
                                   ", the calling program in " + (prog_.inch ? "INCH" : "MM") +
                                   " (not supported by toolcomp)",
             t[0].column);
    const int at = line_;
    const std::shared_ptr<const Program> keep = sub;  // held while it runs (it may call itself)
    run_blocks(*keep, depth + 1);
    if (!ended_) line_ = at;
}

void interpret(const Program& program, const ToolTable* tools, const ControlProfile& profile, MotionSink& sink,
               std::vector<Diagnostic>& diagnostics, const std::function<void(std::size_t)>& progress,
               std::size_t progress_every, const SearchPath& search,
               InterpretOutput* out, const Machine* machine, bool block_delete, const std::optional<Vec3>& start,
               const PieceHooks& pieces) {
    Interp interp(program, tools, profile, sink, diagnostics, search);
    interp.read_in_pieces(pieces);
    interp.set_machine(machine);
    if (start) interp.set_start(*start);
    interp.skip_marked_blocks(block_delete);
    if (progress) interp.on_progress(progress, progress_every);
    run_reporting(interp, out, [](const Interp& i) { return InterpretOutput{i.files(), {}, {}, i.dwell_seconds()}; });
}

}  // namespace toolcomp::heidenhain
