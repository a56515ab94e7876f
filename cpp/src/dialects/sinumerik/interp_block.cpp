// One Sinumerik block: its statements are evaluated left to right (assignments take effect
// at once, so "R1=5 X=R1" moves to 5), the words are collected, then executed in the
// control's order: feed, speed, tool selection and change, edge, plane, units, dimensions,
// compensation modes, frames, motion, program stop and end, subprogram call.
#include <algorithm>
#include <cmath>
#include <optional>

#include "interp.hpp"
#include "toolcomp/program/codes.hpp"
#include "toolcomp/program/int_value.hpp"
#include "toolcomp/dialects/sinumerik/lexer.hpp"
#include "toolcomp/program/text.hpp"

namespace toolcomp::sinumerik {

namespace {
// Words that are keywords, and real 840D words toolcomp does not run (an explicit error
// rather than a silently different path). Every name has two letters or more.
constexpr std::string_view kKeywords[] = {
    "NORM", "KONT", "CDON", "CDOF", "CDOF2", "CUT2D", "DIAMON", "DIAMOF", "DIAM90", "TRANS", "ATRANS", "ROT",
    "AROT", "SCALE", "ASCALE", "MIRROR", "AMIRROR", "SUPA", "TCOABS", "RET", "STOPRE", "TRAFOOF",
    "CIP", "CT",
    // No effect on the programmed path: feed profiles, jerk and feed-forward, path reference,
    // the compressor off; the compressor on smooths within a tolerance (a note, as G64).
    "FNORM", "FLIN", "FCUB", "BRISK", "SOFT", "BRISKA", "SOFTA", "FFWON", "FFWOF", "UPATH", "SPATH", "COMPOF",
    "COMPON", "COMPCURV", "COMPCAD"};
constexpr std::string_view kUnsupported[] = {
    "KONTC", "KONTT", "CUT2DF", "CUT3DC", "CUT3DF", "CUT3DFS", "CUT3DFF", "CUT3DCC", "CUT3DCCD", "TRAORI", "TRACYL",
    "TRANSMIT", "TCOFR", "TCOFRZ", "TCOFRY", "TCOFRX", "ASPLINE", "BSPLINE", "CSPLINE", "POLY", "OFFN_AX", "ORIC", "ORID",
    "G110", "G111", "G112", "ORIWKS", "ORIMKS",
    // contour definitions on the path (rounding, chamfers, angles): not read yet
    "RNDM", "ANG",
    "ORIAXES", "ORIVECT", "ORIEULER", "ORIRPY", "TRACON", "CTRANS", "CROT", "CSCALE", "CMIRROR"};

template <std::size_t N>
constexpr bool all_longer_than_one(const std::string_view (&names)[N]) {
    for (std::string_view n : names)
        if (n.size() < 2) return false;
    return true;
}
static_assert(all_longer_than_one(kKeywords) && all_longer_than_one(kUnsupported));

// A keyword with a digit reaches the interpreter whole only if the lexer keeps it whole.
constexpr bool digit_keywords_lexed_whole() {
    for (std::string_view k : kKeywords)
        if (std::ranges::any_of(k, ascii_digit) && std::ranges::find(kDigitKeywords, k) == kDigitKeywords.end())
            return false;
    return true;
}
static_assert(digit_keywords_lexed_whole(), "a keyword with a digit is missing from kDigitKeywords (lexer.hpp)");

// k is one of `names`; the address words of a block (X, G, F ...) are passed by with one test.
template <std::size_t N>
bool listed(const std::string_view (&names)[N], std::string_view k) {
    if (k.size() < 2) return false;
    for (std::string_view x : names)
        if (x == k) return true;
    return false;
}
bool is_keyword(std::string_view k) { return listed(kKeywords, k); }
bool is_unsupported(std::string_view k) { return listed(kUnsupported, k); }
}  // namespace

// Calls that set up the control without a path of their own: CYCLE832 (high speed settings:
// a tolerance of the executed path), WORKPIECE (the blank for the display), CYCLE800 with no
// swivel (A, B, C 0, or no parameters: the plane stays as it is).
void Interp::no_path_call(const Token& x) {
    if (x.is("CYCLE832")) {
        if (!blending_noted_)
            info(code::blending_not_modelled,
                 "CYCLE832 smooths the executed path within its tolerance: toolcomp returns the programmed path", x.column);
        blending_noted_ = true;
        return;
    }
    if (x.is("WORKPIECE")) return info(code::no_path_effect, "WORKPIECE(...) sets the blank for the display: no motion", x.column);
    if (x.is("GROUP_BEGIN") || x.is("GROUP_END"))
        return info(code::no_path_effect, x.key + "(...) groups blocks in the editor: no motion", x.column);
    if (x.is("SETMS")) return info(code::no_path_effect, "SETMS(...) names the master spindle: no motion", x.column);
    if (x.is("EXTERN")) return;  // declares a subprogram's parameters for the compiler: nothing runs
    // CYCLE800(FR, TC, ST, MODE, X0, Y0, Z0, A, B, C, X1, Y1, Z1, DIR, ...)
    const std::vector<std::string> args = split_args(x.text);  // x.text: the arguments, without the parentheses
    for (std::size_t i : {7, 8, 9}) {
        if (i >= args.size() || args[i].empty()) continue;
        const double angle = eval_text(args[i], x.column);
        if (angle != 0)
            fail(code::unsupported_word, "CYCLE800 with a swivel (" + std::string(1, "ABC"[i - 7]) + " = " +
                                             shortest_number(angle) + "): tilted planes are not supported by toolcomp yet",
                 x.column);
    }
    info(code::no_path_effect, "CYCLE800 without a swivel: the plane stays unrotated (the retraction of the machine's swivel data is not modelled)", x.column);
}

// AX[X]=10, AX[_AX]=10 (an AXIS variable): the address word X10.
Token Interp::axis_address(const Token& t) {
    Token a = t;
    const std::optional<std::string> axis = axis_named(t.text);
    if (!axis)
        fail(code::unsupported_word, "AX[" + t.text + "]: toolcomp moves the axes X, Y, Z, A, B, C (an axis name or an AXIS variable)", t.column);
    if (axis->empty()) fail(code::alarm_12330, "12330 AX[" + t.text + "]: the AXIS holds no axis", t.column);
    a.key = *axis;
    a.text.clear();
    return a;
}

// A word that is no address (a name of two letters or more, or "="): an assignment, a call of
// a value, MSG, a drilling cycle or hole pattern, MCALL, CALL, a call that makes no path, or a
// statement toolcomp refuses. True when it took the word (else it is a keyword or names a
// subprogram: block() reads it as such).
bool Interp::statement_or_call(const Token& x, BlockCalls& calls, bool& words) {
    const ShortText& k = x.key;
    if (x.is("=")) {
        assign(x);
        return true;
    }
    if (x.is("FRAME=")) {
        frame_assign(x);
        return true;
    }
    if (is_value_call(x.key)) {
        value_call(x);
        return true;
    }
    if (x.is("MSG")) {  // MSG("text" << R1): the text as the control shows it
        std::string m = x.text;
        if (m.find_first_not_of(" \t") == std::string::npos) {
            m.clear();
        } else {
            try {
                m = eval_string(expr::parse_all(m, expr::sinumerik_syntax()), x.column);
            } catch (const expr::SyntaxError&) {  // a form toolcomp does not read: the text as written
                if (m.size() >= 2 && m.front() == '"' && m.back() == '"') m = m.substr(1, m.size() - 2);
            }
        }
        info(code::message, m, x.column);
        return true;
    }
    if (x.is("MCALL")) {
        calls.mcall = true;
        words = true;
        return true;
    }
    if (k == "HOLES1" || k == "HOLES2" || k == "CYCLE801") {
        if (calls.pattern || calls.drill) fail(code::alarm_12010, "12010 Two subprogram calls in one block", x.column);
        calls.pattern.emplace(k, x.text != k ? x.text.str() : std::string());
        words = true;
        return true;
    }
    if (drilling_cycle_name(k)) {
        if (calls.drill) fail(code::alarm_12010, "12010 Two subprogram calls in one block", x.column);
        calls.drill.emplace(k, cycle_arguments(k, x.text != k ? x.text.str() : std::string(), x.column));
        words = true;
        return true;
    }
    if (calls.mcall && (is_unsupported(k) || !is_keyword(k)) && !x.has_value && x.expr < 0 && k.size() > 1)
        fail(code::unsupported_word, "MCALL " + k + ": toolcomp calls the drilling cycles CYCLE81-CYCLE89 and CYCLE840 modally", x.column);
    if (x.is("CALL")) {  // CALL / PCALL / EXTCALL "path": the program the lexer named
        if (!calls.name.empty()) fail(code::alarm_12010, "12010 Two subprogram calls in one block", x.column);
        words = true;
        calls.name = x.text;
        calls.column = x.column;
        return true;
    }
    if (x.is("CYCLE832") || x.is("WORKPIECE") || x.is("CYCLE800") || x.is("GROUP_BEGIN") || x.is("GROUP_END") ||
        x.is("SETMS") || x.is("EXTERN")) {
        no_path_call(x);
        return true;
    }
    if (x.is("SYNACT"))
        fail(code::unsupported_word, "Synchronized actions (" + x.text.substr(0, x.text.find(' ')) +
                                         " ... DO ...) are not supported by toolcomp", x.column);
    if (x.is("SETAL")) {
        const long n = std::lround(eval_text(x.text, x.column));
        fail(code::setal, "Alarm " + std::to_string(n) + " set by the program (SETAL)", x.column);
    }
    return false;
}

void Interp::block(std::span<const Token> t) {
    Context& c = stack_.back();
    if (t[0].is("DEF")) {
        if (c.executable_seen)
            fail(code::alarm_14500, "14500 Illegal DEF or PROC instruction in the program (DEF after the first executable block)",
                 t[0].column);
        define(t);
        return;
    }
    if (t[0].is("PROC")) {
        if (c.pc != 1 && c.executable_seen)
            fail(code::alarm_14500, "14500 Illegal DEF or PROC instruction in the program", t[0].column);
        if (t[0].param == 1 && stack_.size() > 1) c.saved = Context::Saved{st_, frame_, pframe_};  // PROC ... SAVE
        return;
    }
    c.executable_seen = true;
    BlockData b;
    std::string taken;  // letters the machine's builder codes of the block read
    bool words = false;
    BlockCalls calls;
    Token axis_word;  // AX[axis]=value as the address of that axis
    for (const Token& raw : t) {
        const Token& x = raw.is("AX") ? (axis_word = axis_address(raw)) : raw;
        const ShortText& k = x.key;
        // X, G, F ...: a single letter is none of the statements and calls below (each name has
        // two letters or more, "=" is no letter), the common word of a CAM block past them at once.
        const bool address = k.size() == 1 && k[0] >= 'A' && k[0] <= 'Z';
        if (!address && statement_or_call(x, calls, words)) continue;
        words = true;  // an address, G/M function, keyword or call: more than a computation
        if (is_unsupported(k) || (x.is("G") && (x.value == static_cast<double>(G110) || x.value == static_cast<double>(G111) || x.value == static_cast<double>(G112))))
            fail(code::unsupported_word, (x.is("G") ? "G" + std::to_string(int_value(x.value)) : k.str()) +
                                         " is not supported by toolcomp", x.column);
        // an address with its value, or with a text (T="DRILL"); SUB("abc", 5) is a call
        if (x.has_value || x.expr >= 0 || (!x.text.empty() && x.text.front() == '"' && is_address(k))) {
            if (k.size() == 1 && k[0] >= 'A' && k[0] <= 'Z') {
                const char l = k[0];
                if (l == 'G') {
                    double v = value_of(x);
                    if (v != std::floor(v) || v < 0 || v > 9999)
                        fail(code::alarm_12470, "12470 G function G" + shortest_number(v) + " is unknown", x.column);
                    b.g.emplace_back(int_value(v), x.column);
                    continue;
                }
                if (l == 'M') {
                    const double v = value_of(x);
                    if (v != std::floor(v) || v < 0 || v > 2147483647)
                        fail(code::unsupported_m_code, "M" + shortest_number(v) + " is not an M function", x.column);
                    int m = int_value(v);
                    // A builder code of the machine stands for the standard code of its action.
                    if (const MachineCode* code = opts_.machine ? opts_.machine->m_code(m) : nullptr) {
                        taken += code->words;
                        m = standard_m_code(code->action);
                        if (m < 0) continue;
                    }
                    b.m.emplace_back(m, x.column);
                    continue;
                }
                if (l == 'L' && x.text.size() > 1 && x.expr < 0) {  // L10: subprogram call
                    calls.name = x.text;
                    calls.column = x.column;
                    continue;
                }
                if (l == 'T' && !x.text.empty() && x.text.front() == '"') {
                    b.tool_name = x.text.substr(1, x.text.size() - 2);
                    b.tool_name_column = x.column;
                    b['T'] = Value{.column = x.column, .set = true};
                    continue;
                }
                if (l == 'R')  // R5 without "=": a parameter named alone does nothing
                    fail(code::unused_word, "R" + std::to_string(int_value(value_of(x))) +
                                            ": an R parameter alone does nothing (assign with R1=..., read with X=R1)",
                         x.column);
                Value& v = b[l];
                if (v.set) fail(code::alarm_12010, "12010 Address " + k + " programmed too often", x.column);
                set_address(v, x);
                continue;
            }
            Value* v = x.is("CR") ? &b.cr : x.is("AR") ? &b.ar : x.is("TURN") ? &b.turn : x.is("DISC") ? &b.disc
                     : x.is("OFFN") ? &b.offn : x.is("RPL") ? &b.rpl : x.is("I1") ? &b.i1 : x.is("J1") ? &b.j1
                     : x.is("K1") ? &b.k1 : x.is("TCARR") ? &b.tcarr : x.is("LIMS") ? &b.lims : x.is("RND") ? &b.rnd
                     : x.is("CHF") ? &b.chf : x.is("CHR") ? &b.chr : nullptr;
            if (!v) fail(code::unsupported_word, (x.text.empty() || x.text[0] == '"' ? k + "=" : x.text.str()) + " is not supported by toolcomp", x.column);
            if (v->set) fail(code::alarm_12010, "12010 Address " + k + " programmed too often", x.column);
            set_address(*v, x);
            continue;
        }
        if (is_keyword(k)) {
            if ((k == "COMPON" || k == "COMPCURV" || k == "COMPCAD") && !blending_noted_) {
                info(code::blending_not_modelled,
                     k + " smooths the executed path within a tolerance: toolcomp returns the programmed path", x.column);
                blending_noted_ = true;
            }
            b.keywords.emplace_back(k, x.column);
            continue;
        }
        if (k.rfind("GOTO", 0) == 0 || x.is("IF") || x.is("FOR") || x.is("WHILE"))
            fail(code::syntax_error, k + " must begin its block", x.column);
        // Anything else names a subprogram (found on the search path, or an error there), with
        // its arguments if it has them: NAME(1, , R5).
        if (!calls.name.empty()) fail(code::alarm_12010, "12010 Two subprogram calls in one block", x.column);
        calls.name = k;
        calls.args = x.text != k ? x.text.str() : std::string();
        calls.column = x.column;
    }
    for (char c : taken) b[c].set = false;
    if (b.has('P') && calls.name.empty())
        fail(code::unused_word, "P (the passes of a subprogram call) without a call in the block", b['P'].column);
    const std::size_t moves_before = moves_;
    const bool comp_before = st_.side != 0;
    if (calls.mcall && !calls.drill) modal_call_.reset();  // MCALL alone ends the modal call
    execute(b, t[0].column);
    if (calls.drill && calls.mcall) {
        modal_call_ = ModalCall{calls.drill->first, calls.drill->second};
    } else if (calls.drill) {
        drilling_cycle(calls.drill->first, calls.drill->second, t[0].column);
    } else if (calls.pattern) {
        hole_pattern(calls.pattern->first, calls.pattern->second, t[0].column);
    } else if (modal_call_ && (b.has('X') || b.has('Y') || b.has('Z')) && moves_ > moves_before) {
        drilling_cycle(modal_call_->name, modal_call_->args, t[0].column);  // after the block's move
    }
    // A block that moved nothing while TRC stays on (not the one that selects it, a stop or a
    // call): one of the "empty blocks" the control counts (alarm 10762).
    bool stop = false;
    for (auto [m, column] : b.m) stop = stop || m == M0 || m == M1;
    if (words && moves_ == moves_before && comp_before && st_.side != 0 && calls.name.empty() && !ended_ && !stop &&
        profile_.radius.count_blocks_without_motion)
        sink_.control({ControlKind::no_motion, line_, Vec3::Zero(), file()});
    if (!calls.name.empty() && !ended_) {
        int passes = 1;
        if (b.has('P')) {
            passes = int_value(b['P'].v);
            if (passes < 1 || passes > 9999) fail(code::alarm_14770, "14770 Number of passes P out of range 1..9999", b['P'].column);
        }
        call(calls.name, passes, calls.column, calls.args);
    }
}

}  // namespace toolcomp::sinumerik
