// Programs that compute: control statements (LinuxCNC O-words, Fanuc Macro B), subprogram
// calls and returns, subprogram files on the search path, the computed values of words and
// the parameter assignments of a block.
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "interp.hpp"
#include "whole_numbers.hpp"
#include "toolcomp/dialects/iso/lexer.hpp"
#include "toolcomp/program/codes.hpp"
#include "toolcomp/program/input_limits.hpp"

namespace toolcomp::iso {

namespace {
// LinuxCNC's words for math errors (Fanuc: the same meaning, alarm PS0112 / PS0119 there).
const char* math_message(expr::MathFault f) {
    switch (f) {
        case expr::MathFault::divide_by_zero: return "Attempt to divide by zero";
        case expr::MathFault::sqrt_negative: return "Negative argument to sqrt";
        case expr::MathFault::ln_domain: return "Zero or negative argument to ln";
        case expr::MathFault::asin_domain: return "Argument to asin out of range";
        case expr::MathFault::acos_domain: return "Argument to acos out of range";
        case expr::MathFault::negative_power: return "Attempt to raise negative to non-integer power";
        case expr::MathFault::out_of_range: return "Calculation resulted in 'infinity'";
        case expr::MathFault::not_a_number: return "Calculation resulted in 'not a number'";
        default: return nullptr;
    }
}
constexpr std::size_t npos = FlowInfo::npos;
}  // namespace

double Interp::eval(std::int32_t e, int column) {
    eval_column_ = column;
    try {
        return expr::evaluate(frames_.back().prog().expression(e), *this, syntax_);
    } catch (const expr::MathError& err) {
        const char* m = math_message(err.fault);
        fail(code::math_error, m ? m : err.what(), column);
    }
}

std::span<const Word> Interp::block_words(const Block& b) {
    const Program& p = frames_.back().prog();
    std::span<const Word> words = p.words(b);
    if (!b.computed) return words;
    scratch_words_.clear();
    for (const Word& w : words) {
        Word v = w;
        if (w.expr >= 0) {
            v.value = eval(w.expr, w.column);
            v.expr = -1;
            if (std::isnan(v.value)) continue;  // Fanuc: an address with a vacant value is left out
        }
        scratch_words_.push_back(v);
    }
    return scratch_words_;
}

void Interp::assignments(const Block& b) {
    const Program& p = frames_.back().prog();
    // Every value of the block is read before any parameter is set (LinuxCNC: "#1=2 #2=#1"
    // gives #2 the old #1). A Fanuc IF [..] THEN guards the assignments after it.
    struct Set {
        double number;
        const std::string* name;
        double value;
        int column;
    };
    std::vector<Set> sets;
    bool active = true;
    for (const Statement& s : p.statements(b)) {
        if (s.kind == Stmt::if_then) {
            active = condition(s.value, s.column);
            continue;
        }
        if (s.kind != Stmt::assign || !active) continue;
        const double number = s.label.empty() ? eval(s.target, s.column) : 0;
        sets.push_back({number, s.label.empty() ? nullptr : &s.label, eval(s.value, s.column), s.column});
    }
    for (const Set& s : sets) {
        if (s.name && predefined(*s.name))
            fail(code::read_only_parameter, "Cannot assign to read-only parameter #<" + *s.name + ">", s.column);
        if (s.name)
            params_.set_named(*s.name, s.value);
        else
            set_param(s.number, s.value, s.column);
    }
}

// LinuxCNC declares a named parameter (value 0) as it reads its assignment, left to right:
// "#<b> = 4 G1 X#<b>" moves to X0, "G1 X#<b> #<b> = 4" reads #<b> before it is declared.
bool Interp::declared_before(const std::string& name) const {
    if (!block_ || !block_->statement_count) return false;
    for (const Statement& s : frames_.back().prog().statements(*block_))
        if (s.kind == Stmt::assign && s.label == name && s.column <= eval_column_) return true;  // its own value too
    return false;
}

// A structure whose end the rest of the file lacks: LinuxCNC seeks to the end of the file. A
// file read leniently stops at its first syntax error: that error is why the end is missing.
void Interp::file_ended(const Program& p) {
    if (const auto& e = p.syntax_error) throw ParseError(e->code, e->message, e->pos);
    line_ = p.last_line;
    fail(code::o_word_structure, "File ended with no percent sign or program end");
}

void Interp::push_frame(Frame f) {
    if (frames_.size() > profile_.call_depth_limit)
        fail(code::call_depth, !profile_.call_depth_message.empty()
                               ? profile_.call_depth_message
                               : "More than " + std::to_string(profile_.call_depth_limit) +
                                     " nested subprogram calls (ControlProfile.call_depth_limit)");
    frames_.push_back(std::move(f));
}

// A call of the LinuxCNC subroutine that begins at `block` of `where` (its sub or O<n> line),
// from the running block.
void Interp::enter_sub(Frame::Kind kind, const LoadedProgram* where, std::size_t block) {
    Frame f;
    f.kind = kind;
    f.call_line = line_;
    f.at = where;
    f.pc = f.entry = block + 1;
    f.sub_block = block;
    push_frame(std::move(f));
}

const LoadedProgram* Interp::load(const std::string& file_name) {
    if (auto it = by_file_.find(file_name); it != by_file_.end()) return it->second;
    for (const std::string& dir : opts_.search.dirs) {
        const CalledEntry entry = look_in(opts_.search, dir, std::filesystem::path(dir) / file_name);
        if (entry.kind == CalledEntry::absent) continue;
        if (entry.kind == CalledEntry::refused) fail(entry.code.c_str(), entry.message);
        const std::filesystem::path& path = entry.path;
        CalledText text = read_called(opts_.search, path, cr_ends_line(prog_.dialect));
        if (!text.ok()) fail(text.code.c_str(), text.message);
        try {
            loaded_programs_.push_back(parse(text.text, prog_.dialect, path.string(), true));
        } catch (const ParseError& e) {  // a syntax error in the called file: its line there
            throw ParseError(e.code(), e.what(), {e.line(), e.column(), path.string()});
        }
        LoadedProgram lp;
        lp.prog = &loaded_programs_.back();
        lp.flow = scan_flow(*lp.prog);
        lp.file = static_cast<int>(files_.size());
        files_.push_back(path.string());
        if (opts_.file_opened) opts_.file_opened(files_.back());
        loaded_.push_back(std::move(lp));
        by_file_[file_name] = &loaded_.back();
        return &loaded_.back();
    }
    return by_file_[file_name] = nullptr;
}

void Interp::call_sub(const Statement& s) {
    std::vector<double> args;
    args.reserve(s.args.size());
    for (std::int32_t a : s.args) args.push_back(eval(a, s.column));
    // "o#1 call": the number the expression gives (an integer word, LinuxCNC's slack).
    std::string computed;
    if (s.target >= 0) {
        const double v = eval(s.target, s.column);
        if (!linuxcnc_whole(v)) fail(code::non_integer_value, "Non integer value for integer", s.column);
        computed = std::to_string(std::lround(v));
    }
    call_o_sub(s.target >= 0 ? computed : s.label, args, s.column);
}

void Interp::call_o_sub(const std::string& label, const std::vector<double>& args, int column) {
    // The sub: a file <label>.ngc on the search path (LinuxCNC looks there first), else a
    // definition in the running file, else one in the main program.
    const std::string name = label.front() == '<' ? label.substr(1, label.size() - 2) : label;
    // A subroutine name names a file in a search directory, never a path out of it.
    if (name.find_first_of("/\\") != std::string::npos || name.find("..") != std::string::npos)
        fail(code::bad_o_word, "Subroutine name o<" + name + "> cannot name a file: '/', '\\' and '..' are not allowed",
             column);
    const LoadedProgram* where = load(name + ".ngc");
    if (where && !where->flow.subs.count(label))
        fail(code::unknown_o_word, "EOF in file:" + where->prog->name + " seeking o-word: o<" + name + "> from line: 0");
    if (!where) where = frames_.back().at;
    auto found = where->flow.subs.find(label);
    if (found == where->flow.subs.end() && where != &main_) {
        where = &main_;
        found = where->flow.subs.find(label);
    }
    if (found == where->flow.subs.end()) {
        for (const auto& [l, at] : where->flow.numbered)  // LinuxCNC's search meets a numbered sub
            if (l == label) fail(code::o_word_structure, "Fanuc 'O....' subroutine must be called with 'M98'");
        fail(code::unknown_o_word, "EOF in file:" + frames_.back().prog().name + " seeking o-word: o<" + name +
                                   "> from line: " + std::to_string(line_));
    }
    const std::size_t sub = found->second;
    if (where->flow.at(sub).partner == npos) file_ended(*where->prog);
    // A definition the flow has not passed yet is recorded now (a forward call): the flow
    // must then never reach it.
    recorded_subs_.insert({where, sub});
    enter_sub(Frame::o_call, where, sub);
    params_.enter(args);
    value_returned_ = false;
}

void Interp::return_from_sub(const Statement& s) {
    if (frames_.size() > 1 && frames_.back().kind == Frame::m98 && profile_.numbered_subprograms)
        fail(code::o_word_structure, "Fanuc 'O....' subroutine definition must end with 'M99'");
    if (frames_.size() < 2 || frames_.back().kind != Frame::o_call)
        fail(code::return_outside_sub, std::to_string(line_) + ": not in a subroutine definition: '" + s.text + "'");
    const bool has_value = s.value >= 0;
    const double v = has_value ? eval(s.value, s.column) : 0.0;
    const ModalSnapshot saved = frames_.back().saved;
    const int call_line = frames_.back().call_line;
    const std::shared_ptr<const BlockWords> resume = frames_.back().resume;
    const int resume_motion = frames_.back().resume_motion;
    frames_.pop_back();
    params_.leave();
    value_returned_ = has_value;
    value_ = v;  // a return without a value resets #<_value> to 0
    restore_on_return(saved, call_line);
    if (resume) {  // a remapped M code's sub: the rest of its block now, at its line
        line_ = call_line;
        file_ = frames_.back().at->file;
        if (!execute_tail(*resume, resume_motion)) ended_ = true;
    }
}

void Interp::control(const Statement& s, std::size_t k) {
    Frame& f = frames_.back();
    const FlowInfo& flow = f.at->flow;
    if (auto e = flow.errors.find(k); e != flow.errors.end()) fail(code::o_word_structure, e->second, s.column);
    const FlowInfo::Links& links = flow.at(k);
    // A structure whose end is missing: the control skips to the end of the file looking for it.
    auto unclosed = [&] { file_ended(f.prog()); };
    auto missing = [&](const char* what) {
        fail(code::o_word_structure, "o" + s.label + " has no matching " + what, s.column);
    };
    // Jumping over blocks to `to`: LinuxCNC reads the blocks it skips for the end it looks
    // for, so a block of the same label that does not fit there, or a sub defined inside the
    // sub passed over, is its error.
    auto skip_to = [&](std::size_t to) {
        for (auto e = flow.errors.upper_bound(k); e != flow.errors.end() && e->first < to; ++e) {
            const Statement* c = control_statement(f.prog(), f.prog().blocks()[e->first]);
            if (e->second == kNestedSub ? s.kind == Stmt::o_sub : c && c->label == s.label) {
                line_ = f.prog().blocks()[e->first].line;
                fail(code::o_word_structure, e->second, c ? c->column : 0);
            }
        }
        f.pc = to;
    };
    // An if, while or repeat opened on another line with the same label, in this call (do
    // labels may repeat).
    auto opened = [&] {
        auto [it, fresh] = f.opened.emplace(s.label, k);
        if (fresh || it->second == k) return;
        const std::string first = std::to_string(f.prog().blocks()[it->second].line);
        fail(code::o_word_structure,
             s.kind == Stmt::o_if
                 ? std::to_string(line_) + ": duplicate O-word label - already defined in line " + first + ": '" + s.text + "'"
                 : std::to_string(line_) + ": duplicate O-word label: '" + s.text + "' - defined in line " + first);
    };
    switch (s.kind) {
        case Stmt::o_sub: {  // a definition met in the flow: recorded and skipped
            if (!recorded_subs_.insert({f.at, k}).second)
                fail(code::o_word_structure, "File:" + f.prog().name + " line:" + std::to_string(line_) + " sub: o|" +
                                             s.label + "| found in illegal location");
            if (auto first = flow.subs.find(s.label); first != flow.subs.end() && first->second != k)
                fail(code::o_word_structure, "File:" + f.prog().name + " line:" + std::to_string(line_) +
                                             " redefining sub: o|" + s.label + "| already defined in file:" + f.prog().name);
            if (links.partner == npos) unclosed();
            skip_to(links.partner + 1);
            break;
        }
        case Stmt::o_endsub: case Stmt::o_return:
            return_from_sub(s);
            break;
        case Stmt::o_call:
            call_sub(s);
            break;
        case Stmt::o_if: {
            opened();
            std::size_t at = k;
            bool take = condition(s.value, s.column);
            while (!take) {
                const std::size_t next = f.at->flow.at(at).partner;
                if (next == npos) unclosed();
                const Statement& b = *control_statement(f.prog(), f.prog().blocks()[next]);
                at = next;
                if (b.kind == Stmt::o_elseif) {
                    line_ = f.prog().blocks()[next].line;
                    count_block();
                    take = condition(b.value, b.column);
                } else {
                    break;  // else or endif
                }
            }
            f.pc = at + 1;
            break;
        }
        case Stmt::o_elseif: case Stmt::o_else:  // the branch before it ran: on to the endif
            // LinuxCNC evaluates every elseif it reaches, even after a taken branch.
            if (s.kind == Stmt::o_elseif) (void)condition(s.value, s.column);
            if (links.endif == npos) unclosed();
            f.pc = links.endif + 1;
            break;
        case Stmt::o_endif: case Stmt::o_do:  // (LinuxCNC lets do labels repeat)
            break;
        case Stmt::program_number:  // a program's number (Fanuc); LinuxCNC: where a numbered sub begins
            if (profile_.numbered_subprograms && f.kind == Frame::o_call)
                fail(code::o_word_structure, "Fanuc 'O....' subroutine must be called with 'M98'");
            break;
        case Stmt::m98_call:
            numbered_call(k);
            break;
        case Stmt::m99_return:
            numbered_return(k);
            break;
        case Stmt::o_while:
            if (links.closes_do) {
                if (condition(s.value, s.column)) f.pc = links.partner + 1;
                break;
            }
            opened();
            if (!condition(s.value, s.column)) {
                if (links.partner == npos) unclosed();
                skip_to(links.partner + 1);
            }  // a while without endwhile that runs goes on (LinuxCNC: no error)
            break;
        case Stmt::o_endwhile:
            if (links.partner == npos) missing("while");
            f.pc = links.partner;
            break;
        case Stmt::o_repeat: {
            opened();
            // The count rounds half to even ([2.5]: two passes), as LinuxCNC reads it.
            const double n = std::nearbyint(eval(s.value, s.column));
            if (n >= 1) {  // without its endrepeat the body runs on to whatever fails to close it
                if (links.partner != npos) f.repeat_counts[k] = static_cast<long>(std::min(n, 1e15));
            } else {
                if (links.partner == npos) unclosed();
                f.pc = links.partner + 1;
            }
            break;
        }
        case Stmt::o_endrepeat: {
            if (links.partner == npos) missing("repeat");
            auto it = f.repeat_counts.find(links.partner);
            if (it != f.repeat_counts.end() && --it->second > 0) {
                f.pc = links.partner + 1;
            } else if (it != f.repeat_counts.end()) {
                f.repeat_counts.erase(it);
            }
            break;
        }
        case Stmt::o_break: case Stmt::o_continue: {
            const std::size_t loop = links.loop;
            const FlowInfo::Links& l = flow.at(loop);
            if (l.partner == npos) missing("loop end");
            const Stmt lk = control_statement(f.prog(), f.prog().blocks()[loop])->kind;
            if (lk == Stmt::o_repeat)  // LinuxCNC: break and continue belong to while and do loops only
                fail(code::o_word_structure, std::to_string(line_) + ": no matching while/do label: '" + s.text +
                                             "' (found 'repeat' in line " + std::to_string(f.prog().blocks()[loop].line) + ")");
            if (s.kind == Stmt::o_break) {
                f.pc = l.partner + 1;
            } else {
                f.pc = lk == Stmt::o_while ? loop : l.partner;  // while: test again; do / repeat: at the end
            }
            break;
        }
        case Stmt::goto_n:
            goto_sequence(eval(s.target, s.column), s.column);
            break;
        case Stmt::if_goto:
            if (condition(s.value, s.column)) goto_sequence(eval(s.target, s.column), s.column);
            break;
        case Stmt::while_do:
            if (links.partner == npos) fail(code::macro_loop, "WHILE [...] DO " + std::to_string(s.loop) + " without END " + std::to_string(s.loop), s.column);
            if (!condition(s.value, s.column)) f.pc = links.partner + 1;
            break;
        case Stmt::end_loop:
            f.pc = links.partner;
            break;
        default:
            break;
    }
}

void Interp::goto_sequence(double n, int column) {
    Frame& f = frames_.back();
    if (std::isnan(n) || n < 0 || n > 99999999 || n != std::floor(n))
        fail(code::bad_sequence_number, "GOTO with a sequence number outside 1..99999999", column);
    auto it = f.at->flow.numbers.find(std::lround(n));
    if (it == f.at->flow.numbers.end())
        fail(code::sequence_number_not_found, "Sequence number N" + std::to_string(std::lround(n)) + " not found", column);
    f.pc = it->second;
}

const LoadedProgram* Interp::fanuc_program(long number) {
    // O<number> in the running file or the main program, else a file of that name.
    for (const LoadedProgram* lp : {frames_.back().at, static_cast<const LoadedProgram*>(&main_)})
        if (lp->flow.programs.count(number)) return lp;
    const std::string n = std::to_string(number);
    std::string padded = n;
    while (padded.size() < 4) padded.insert(padded.begin(), '0');
    for (const std::string& name : {"O" + padded + ".nc", "O" + padded, "O" + n + ".nc", n + ".nc"})
        if (const LoadedProgram* lp = load(name)) return lp;
    return nullptr;
}

void Interp::subprogram(int mcode, const WordSlot& p_word, const WordSlot& l_word, int column) {
    if (mcode == M99) {  // M99: return (to N P of the caller when given)
        if (frames_.size() < 2) {
            // In the main program M99 runs it again from the top (the block limit stops it).
            frames_.back().pc = 0;
            if (p_word.set) goto_sequence(p_word.value, p_word.column);
            return;
        }
        Frame& f = frames_.back();
        if (f.kind == Frame::o_call) fail(code::m99_in_sub, "M99 inside an O-word subroutine", column);
        if (f.repeats_left > 0) {
            --f.repeats_left;
            f.pc = f.entry;
            return;
        }
        if (f.kind == Frame::g65) params_.leave();
        frames_.pop_back();
        if (p_word.set) goto_sequence(p_word.value, p_word.column);
        return;
    }
    call_program(Frame::m98, p_word, l_word, column);
}

void Interp::call_program(Frame::Kind kind, const WordSlot& p_word, const WordSlot& l_word, int column) {
    const char* what = kind == Frame::g65 ? "G65" : "M98";
    if (!p_word.set) fail(code::program_number_missing, std::string(what) + " without P (program number)", column);
    const double p = p_word.value;
    if (!(p >= 1 && p <= 99999999 && p == std::floor(p)))
        fail(code::bad_program_number, std::string(what) + " P must be a program number 1..99999999", p_word.column);
    long number = std::lround(p), times = 1;
    if (l_word.set) {
        const double l = l_word.value;
        if (!(l >= 1 && l <= 9999 && l == std::floor(l)))
            fail(code::bad_repeat_count, "L must be a whole number 1..9999", l_word.column);
        times = std::lround(l);
    } else if (kind == Frame::m98 && number > 9999) {  // M98 P30001000: 3 passes of O1000
        times = number / 10000;
        number %= 10000;
    }
    const LoadedProgram* lp = fanuc_program(number);
    if (!lp)
        fail(code::program_not_found,
             "Program O" + std::to_string(number) + " not found" +
                 (opts_.search.dirs.empty() ? " (no search path given)" : " (not in the file nor on the search path)"),
             p_word.column);
    Frame f;
    f.kind = kind;
    f.call_line = line_;
    f.at = lp;
    auto start = lp->flow.programs.find(number);
    f.pc = f.entry = start == lp->flow.programs.end() ? 0 : start->second + 1;
    f.repeats_left = times - 1;
    push_frame(std::move(f));
}

void Interp::macro_call(std::span<const Word> words, int column) {
    // Argument specification I: A B C -> #1 #2 #3, I J K -> #4 #5 #6, D E F -> #7 #8 #9,
    // H -> #11, M -> #13, Q R S T U V W X Y Z -> #17 ... #26. Specification II: the n-th I, J
    // and K (up to ten of each) -> #(4 + 3(n-1)), #(5 + 3(n-1)), #(6 + 3(n-1)); where the two
    // name the same variable the later word wins. Unset arguments stay vacant; any other
    // letter given twice is refused.
    static constexpr std::pair<char, int> kArgs[] = {
        {'A', 1}, {'B', 2}, {'C', 3}, {'I', 4}, {'J', 5}, {'K', 6}, {'D', 7}, {'E', 8}, {'F', 9}, {'H', 11},
        {'M', 13}, {'Q', 17}, {'R', 18}, {'S', 19}, {'T', 20}, {'U', 21}, {'V', 22}, {'W', 23}, {'X', 24},
        {'Y', 25}, {'Z', 26}};
    std::array<double, 34> locals;
    locals.fill(ParameterStore::kVacant);
    WordSlot p_word, l_word;
    int ijk_count[3] = {0, 0, 0};
    std::uint32_t seen = 0;  // letters other than I, J, K
    for (const Word& w : words) {
        if (w.letter == 'N') continue;
        if (w.letter == 'G') {
            if (w.value != written(G65)) fail(code::g65_other_codes, "G65 must be the only G code of its block", w.column);
            continue;
        }
        if (w.letter == 'P' || w.letter == 'L') {
            WordSlot& slot = w.letter == 'P' ? p_word : l_word;
            if (slot.set) fail(code::multiple_words, std::string("Multiple ") + static_cast<char>(w.letter + 32) + " words on one line", w.column);
            slot = {.value = w.value, .column = w.column, .set = true};
            continue;
        }
        if (w.letter == 'I' || w.letter == 'J' || w.letter == 'K') {
            const int k = w.letter - 'I';
            if (ijk_count[k] == 10)
                fail(code::bad_macro_argument, std::string("More than ten ") + w.letter + " arguments in one G65 block",
                     w.column);
            locals[static_cast<std::size_t>(4 + k + 3 * ijk_count[k]++)] = w.value;
            continue;
        }
        bool ok = false;
        for (auto [letter, n] : kArgs)
            if (letter == w.letter) {
                const std::uint32_t bit = std::uint32_t{1} << (letter - 'A');
                if (seen & bit)
                    fail(code::multiple_words, std::string("Multiple ") + static_cast<char>(w.letter + 32) + " words on one line",
                         w.column);
                seen |= bit;
                locals[static_cast<std::size_t>(n)] = w.value;
                ok = true;
            }
        if (!ok) fail(code::bad_macro_argument, std::string("Address ") + w.letter + " is not a G65 argument", w.column);
    }
    call_program(Frame::g65, p_word, l_word, column);
    params_.enter_fanuc(locals);
}

}  // namespace toolcomp::iso
