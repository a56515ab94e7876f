// Program flow of the Sinumerik interpreter: the block loop, control structures (IF/ELSE/
// ENDIF, WHILE, FOR, REPEAT/UNTIL, LOOP), jumps (GOTOF/GOTOB/GOTO/GOTOC to labels and block
// numbers), subprogram calls (L<n>, by name, with P passes) and returns (M17, RET, M2/M30
// in a subprogram), and the block limit.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <utility>
#include <sstream>

#include "interp.hpp"
#include "toolcomp/dialects/sinumerik/lexer.hpp"
#include "toolcomp/program/codes.hpp"
#include "toolcomp/program/input_limits.hpp"
#include "toolcomp/program/text.hpp"

namespace toolcomp::sinumerik {

Interp::Interp(const Program& prog, const ToolTable* tools, const ControlProfile& profile, const InterpretOptions& opts,
               MotionSink& sink, std::vector<Diagnostic>& diags)
    : main_(prog), tools_(tools), profile_(profile), opts_(opts), corners_(sink), sink_(corners_), diags_(diags) {
    edges_ = opts_.tool_data;
    holders_ = opts_.toolholders;
    st_.plane = profile_.startup_plane;
    // On a machine the run starts with the axes at the machine's zero.
    if (const Machine* m = opts_.machine) {
        for (int i = 0; i < 3; ++i) work_origin_[i] = m->work_origin[static_cast<std::size_t>(i)];
        if (m->kind == MachineKind::lathe) work_origin_.x() /= 2;  // a lathe's machine X is a diameter
        pos_ = -work_origin_;
    }
    if (opts_.start) {
        Vec3 at = *opts_.start;
        if (opts_.machine && opts_.machine->kind == MachineKind::lathe) at.x() /= 2;
        pos_ = at - work_origin_;
    }
}

void Interp::fail(const std::string& code, const std::string& msg, int column) const {
    const int f = stack_.empty() ? 0 : stack_.back().file;
    throw ProgramError(code, msg, {line_, column, f > 0 ? files_.names()[static_cast<std::size_t>(f)] : std::string()});
}

void Interp::info(const char* code, const std::string& msg, int column) {
    diags_.push_back({code, Severity::info, msg, {line_, column}});
}

const ProgramInfo& Interp::info_of(const Program& p) {
    auto& slot = infos_[&p];
    if (slot) return *slot;
    auto info = std::make_unique<ProgramInfo>();
    if (!p.control_statements) return *(slot = std::move(info));  // nothing to index
    const auto& blocks = p.blocks();
    info->partner.assign(blocks.size(), 0);
    info->kind.assign(blocks.size(), ctl_none);
    std::vector<std::size_t> open;
    for (std::size_t i = 0; i < blocks.size(); ++i) {
        auto t = statements(p.tokens(blocks[i]));
        if (t.empty()) continue;
        if (t[0].is("PROC") && t.size() > 1 && t[1].is("PROCARGS"))
            info->formals = parse_formals(t[1].text, blocks[i].line, t[1].column);
        Ctl k = ctl_of(t[0].key);
        if (t[0].is("REPEATB") || (k == ctl_repeat && t.size() > 1)) k = ctl_section;  // not a REPEAT/UNTIL loop
        if (k == ctl_if) {
            bool jump = false;
            for (const Token& x : t) jump |= x.key.starts_with("GOTO");
            if (jump) k = ctl_jump;
        } else if (t[0].key.starts_with("GOTO") || t[0].is("CASE")) {
            k = ctl_jump;
        }
        if (k != ctl_none && (t[0].has_value || ((k == ctl_if || k == ctl_while || k == ctl_until || k == ctl_for) &&
                                                 t[0].expr < 0)))
            throw ProgramError(code::syntax_error, "12080 Syntax error: " + (t[0].text.empty() ? t[0].key : t[0].text),
                               {blocks[i].line, t[0].column});
        info->kind[i] = k;
        auto mismatch = [&](const char* what) {
            throw ProgramError(code::alarm_14060, std::string("14060 ") + what + " without its opening statement",
                               {blocks[i].line, t[0].column});
        };
        auto close = [&](Ctl opener, const char* what) {
            if (open.empty() || (info->kind[open.back()] != opener && !(opener == ctl_if && info->kind[open.back()] == ctl_else)))
                mismatch(what);
            std::size_t o = open.back();
            open.pop_back();
            info->partner[o] = i;
            info->partner[i] = o;
        };
        switch (k) {
            case ctl_if: case ctl_while: case ctl_for: case ctl_repeat: case ctl_loop: open.push_back(i); break;
            case ctl_else:
                if (open.empty() || info->kind[open.back()] != ctl_if) mismatch("ELSE");
                info->partner[open.back()] = i;
                open.back() = i;
                break;
            case ctl_endif: {
                if (open.empty() || (info->kind[open.back()] != ctl_if && info->kind[open.back()] != ctl_else)) mismatch("ENDIF");
                std::size_t o = open.back();
                open.pop_back();
                info->partner[o] = i;
                break;
            }
            case ctl_endwhile: close(ctl_while, "ENDWHILE"); break;
            case ctl_endfor: close(ctl_for, "ENDFOR"); break;
            case ctl_until: close(ctl_repeat, "UNTIL"); break;
            case ctl_endloop: close(ctl_loop, "ENDLOOP"); break;
            default: break;
        }
    }
    if (!open.empty()) {
        const Block& b = blocks[open.back()];
        throw ProgramError(code::alarm_14060, "14060 Control structure not closed (" + statements(p.tokens(b))[0].key + " without its end)",
                           {b.line, statements(p.tokens(b))[0].column});
    }
    slot = std::move(info);
    return *slot;
}

double Interp::eval(std::int32_t e, int column) {
    try {
        return expr::evaluate(stack_.back().prog->expression(e), *this);
    } catch (const expr::MathError& err) {
        fail(code::math_error, std::string("14051 Arithmetic error in part program: ") + err.what(), column);
    }
}

double Interp::eval_text(const std::string& text, int column) {
    try {
        return expr::evaluate(expr::parse_all(text, expr::sinumerik_syntax()), *this);
    } catch (const expr::SyntaxError& err) {
        fail(code::syntax_error, std::string("12080 Syntax error: ") + err.what(), column);
    } catch (const expr::MathError& err) {
        fail(code::math_error, std::string("14051 Arithmetic error in part program: ") + err.what(), column);
    }
}

std::string Interp::eval_text_string(const std::string& text, int column) {
    try {
        return eval_string(expr::parse_all(text, expr::sinumerik_syntax()), column);
    } catch (const expr::SyntaxError& err) {
        fail(code::syntax_error, std::string("12080 Syntax error: ") + err.what(), column);
    }
}

std::string Interp::eval_string(const expr::Expr& e, int column) {
    try {
        return expr::evaluate_text(e, *this);
    } catch (const expr::MathError& err) {
        fail(code::math_error, std::string("14051 Arithmetic error in part program: ") + err.what(), column);
    }
}

double Interp::value_of(const Token& t) { return t.expr >= 0 ? eval(t.expr, t.column) : t.value; }

void Interp::set_address(Value& v, const Token& t) {
    v.v = value_of(t);  // first: a value that fails leaves v as it was
    v.column = t.column;
    v.mod = static_cast<std::int16_t>(t.param);
    v.set = true;
}

void Interp::run() {
    stack_.push_back(Context{&main_, &info_of(main_), 0, {}, false, 0, 0, file_index(main_.name)});
    // A PROC run as the main program: its parameters as omitted ones (0, "", VAR ones too)
    for (const Formal& f : stack_.back().info->formals) {
        Variable v;
        v.integer = f.integer;
        v.text = f.text > 0;
        v.axis = f.axis;
        v.length = f.text;
        v.v.assign(1, 0.0);
        if (v.text) v.s.assign(1, std::string());
        stack_.back().locals.emplace(f.name, std::move(v));
        stack_.back().subpar.push_back(false);
    }
    try {
        while (step()) {
        }
    } catch (...) {
        corners_.abandon();
        sink_.finish();
        throw;
    }
    sink_.finish();
    // Read whole, a program's syntax error is raised after M30 too: the pieces after the end
    // are read for it.
    while (next_main_piece()) {
    }
    if (const auto& e = stack_.front().prog->syntax_error) throw ParseError(e->code, e->message, e->pos);
}

// Path::files index of a program, told to InterpretOptions::file_opened when it is new.
int Interp::file_index(const std::string& name) {
    const std::size_t known = files_.names().size();
    const int i = files_.index(name);
    if (files_.names().size() > known && opts_.file_opened) opts_.file_opened(name);
    return i;
}

// The main program's next piece (InterpretOptions::next_piece), in place of the one run
// through; false at the end of the program, or after a piece that ended with a syntax error.
bool Interp::next_main_piece() {
    Context& c = stack_.front();
    if (!opts_.next_piece || pieces_ended_ || c.prog->syntax_error) return false;
    const Program* next = opts_.next_piece();
    if (!next) {
        pieces_ended_ = true;
        return false;
    }
    infos_.erase(next);  // the pieces take turns in the same Program objects
    c.prog = next;
    c.info = &info_of(*next);
    c.pc = 0;
    return true;
}

bool Interp::step() {
    Context& c = stack_.back();
    const auto& blocks = c.prog->blocks();
    while (!c.sections.empty() && c.pc == c.sections.back().end + 1) {  // the end of a repeated section
        auto& s = c.sections.back();
        if (s.left-- > 0) {
            c.pc = s.start;
            break;
        }
        c.pc = s.back;
        c.sections.pop_back();
    }
    if (c.pc >= blocks.size()) {
        if (stack_.size() == 1 && next_main_piece()) return true;
        if (c.prog->syntax_error && stack_.size() > 1) {  // at the end of a called file: that file's line
            const auto& e = *c.prog->syntax_error;
            throw ParseError(e.code, e.message, {e.pos.line, e.pos.column, c.prog->name});
        }
        return ret();
    }
    const Block& b = blocks[c.pc];
    const std::size_t here = c.pc++;
    if (b.block_delete && opts_.block_delete) return true;
    line_ = b.line;
    if (++executed_ > profile_.block_limit)
        fail(code::block_limit, "Block limit of " + std::to_string(profile_.block_limit) +
                                " executed blocks exceeded (endless loop?)");
    if (idle_.too_long(moves_, profile_.no_motion_limit)) [[unlikely]]
        fail(code::no_progress, no_progress_text(profile_.no_motion_limit));
    if (opts_.progress && executed_ % opts_.progress_every == 0) opts_.progress(executed_);
    auto t = statements(c.prog->tokens(b));
    if (t.empty()) return true;
    const std::uint8_t kind = c.info->kind.empty() ? std::uint8_t{ctl_none} : c.info->kind[here];
    if (kind != ctl_none) {
        c.executable_seen = true;
        control(t, kind);
        return !ended_;
    }
    block(t);
    return !ended_;
}

bool Interp::control(std::span<const Token> t, std::uint8_t kind) {
    Context& c = stack_.back();
    const std::size_t here = c.pc - 1;
    const std::size_t partner = c.info->partner[here];
    auto truth = [&](const Token& x) { return eval(x.expr, x.column) != 0; };
    switch (kind) {
        case ctl_jump: {
            std::size_t i = 0;
            if (t[0].key == "CASE") {  // the branch of the value, else DEFAULT, else the next block
                const double v = eval(t[0].expr, t[0].column);
                const Token* chosen = nullptr;
                for (const Token& b : t.subspan(1))
                    if ((b.param == 1 && b.value == v) || (b.param == 2 && !chosen)) chosen = &b;
                for (const Token& b : t.subspan(1))
                    if (b.param == 1 && b.value == v) chosen = &b;
                if (chosen) jump(*chosen);
                return true;
            }
            if (t[0].key == "IF") {
                if (!truth(t[0])) return true;
                i = 1;
            }
            if (i >= t.size() || t[i].key.rfind("GOTO", 0) != 0) fail(code::syntax_error, "GOTOF, GOTOB or GOTO expected", t[0].column);
            jump(t[i]);
            return true;
        }
        case ctl_if:
            if (!truth(t[0])) c.pc = partner + 1;
            return true;
        case ctl_else: c.pc = partner + 1; return true;  // the IF branch ran: skip the ELSE branch
        case ctl_endif: case ctl_repeat: case ctl_loop: return true;
        case ctl_section: section_repeat(t); return true;
        case ctl_while:
            if (!truth(t[0])) c.pc = partner + 1;
            return true;
        case ctl_endwhile: c.pc = partner; return true;
        case ctl_endloop: c.pc = partner + 1; return true;
        case ctl_until:
            if (!truth(t[0])) c.pc = partner + 1;
            return true;
        case ctl_for: {
            if (t.size() < 2 || t[1].key != "TO") fail(code::syntax_error, "FOR without TO", t[0].column);
            double start = eval(t[0].expr, t[0].column);
            set_variable(t[0].text, {}, start, t[0].column);
            if (get(t[0].text, {}) > eval(t[1].expr, t[1].column)) c.pc = partner + 1;
            return true;
        }
        case ctl_endfor: {
            auto ft = statements(c.prog->tokens(c.prog->blocks()[partner]));
            double v = get(ft[0].text, {}) + 1;
            set_variable(ft[0].text, {}, v, ft[0].column);
            if (v <= eval(ft[1].expr, ft[1].column)) c.pc = partner + 1;
            return true;
        }
        default: return false;
    }
}

// REPEATB label P=n: the block with the label (looked for towards the start first, then
// towards the end); REPEAT label P=n: from the label (before this block) up to the block
// before this one, or up to an ENDLABEL: between them; REPEAT label1 label2 P=n: from label1
// through label2. n times more (P omitted: once), then on after this block.
void Interp::section_repeat(std::span<const Token> t) {
    Context& c = stack_.back();
    const std::size_t here = c.pc - 1;
    std::vector<const Token*> names;
    long passes = 1;
    for (std::size_t i = 1; i < t.size(); ++i) {
        if (t[i].key == "P" && (t[i].has_value || t[i].expr >= 0)) {
            const double p = value_of(t[i]);
            if (!(p >= 1 && p <= 9999) || p != std::floor(p))
                fail(code::alarm_14770, "14770 Number of passes P out of range 1..9999", t[i].column);
            passes = std::lround(p);
        } else if (!t[i].key.empty() && !t[i].has_value && t[i].expr < 0 && t[i].key != "P") {
            names.push_back(&t[i]);
        } else {
            fail(code::syntax_error, "12080 Syntax error: " + t[0].key + " takes labels and P=", t[i].column);
        }
    }
    const bool single = t[0].key == "REPEATB";
    if (names.empty() || names.size() > (single ? 1u : 2u))
        fail(code::syntax_error, "12080 Syntax error: " + t[0].key + (single ? " needs one label" : " needs one or two labels"),
             t[0].column);
    const std::size_t n = c.prog->blocks().size();
    auto labelled = [&](std::size_t i, const std::string& name) {
        for (const Token& x : c.prog->tokens(c.prog->blocks()[i]))
            if (x.key == ":" && x.text == name) return true;
        return false;
    };
    auto find = [&](const Token& name, bool forward_too) {
        for (std::size_t i = here; i-- > 0;)
            if (labelled(i, name.key)) return i;
        if (forward_too)
            for (std::size_t i = here + 1; i < n; ++i)
                if (labelled(i, name.key)) return i;
        fail(code::alarm_14080, "14080 Jump destination " + name.key + " not found", name.column);
    };
    std::size_t start = find(*names[0], single), end = start;
    if (names.size() == 2) {
        end = find(*names[1], true);
        if (end < start) fail(code::alarm_14080, "14080 " + names[1]->key + " lies before " + names[0]->key, names[1]->column);
    } else if (!single) {
        end = here - 1;
        for (std::size_t i = start; i < here; ++i)
            if (labelled(i, "ENDLABEL")) {
                end = i;
                break;
            }
    }
    c.sections.push_back({start, end, here + 1, passes - 1});
    c.pc = start;
}

void Interp::jump(const Token& t) {
    Context& c = stack_.back();
    const std::size_t here = c.pc - 1;
    std::optional<std::size_t> target;
    const std::string& label = t.text;
    auto find_in = [&](std::size_t from, std::size_t to) -> std::optional<std::size_t> {  // [from, to)
        for (std::size_t i = from; i < to; ++i) {
            for (const Token& x : c.prog->tokens(c.prog->blocks()[i])) {
                if (x.key == ":" && x.text == label) return i;
                if (x.key == "N" && x.text.empty() && label.size() > 1 && label.size() <= 10 && label[0] == 'N' &&
                    label.find_first_not_of("0123456789", 1) == std::string::npos &&
                    static_cast<long>(x.value) == std::stol(label.substr(1)))
                    return i;
            }
        }
        return std::nullopt;
    };
    const std::size_t n = c.prog->blocks().size();
    if (t.key == "GOTOF") {
        target = find_in(here + 1, n);
    } else if (t.key == "GOTOB") {
        for (std::size_t i = here + 1; i-- > 0 && !target;) target = find_in(i, i + 1);
    } else {  // GOTO / GOTOC: forward first, then backward
        target = find_in(here + 1, n);
        for (std::size_t i = here + 1; !target && i-- > 0;) target = find_in(i, i + 1);
    }
    if (!target) {
        if (t.key == "GOTOC") return;
        fail(code::alarm_14080, "14080 Jump destination " + label + " not found", t.column);
    }
    c.pc = *target;
}

// ShopMill / ShopTurn step programs: each step calls a Siemens cycle (F_HEAD, F_DRILL, F_CON,
// E_HEAD, E_POCKET, ...) with packed parameters, computing the tool path inside it.
bool Interp::shopturn_step(const std::string& name) {
    return name.size() > 2 && (name[0] == 'F' || name[0] == 'E') && name[1] == '_' &&
           std::all_of(name.begin() + 2, name.end(), [](char ch) { return (ch >= 'A' && ch <= 'Z') || ch == '_'; });
}

// The Siemens cycles a program calls by name (CYCLE95, POCKET3, SLOT1, LONGHOLE, ...).
bool Interp::standard_cycle(const std::string& name) {
    auto numbered = [&](std::string_view prefix) {
        return name.size() > prefix.size() && name.compare(0, prefix.size(), prefix) == 0 &&
               name.find_first_not_of("0123456789", prefix.size()) == std::string::npos;
    };
    return numbered("CYCLE") || numbered("POCKET") || numbered("SLOT") || name == "LONGHOLE" || name == "CONTPRON" ||
           name == "CONTDCON" || name == "E_MANAGER";
}

void Interp::refuse_shopturn(const std::string& name, int column) const {
    fail(code::shopturn_program,
         "ShopMill/ShopTurn step program (" + name +
             "): its steps call Siemens cycles whose tool paths are computed inside them, not given by the program "
             "text; toolcomp cannot reproduce them (post the part as plain G code)",
         column);
}

void Interp::call(const std::string& name, int passes, int column, const std::string& args) {
    if (name == "F_HEAD" || name == "E_HEAD") refuse_shopturn(name, column);
    if (static_cast<int>(stack_.size()) >= opts_.max_call_depth)
        fail(code::call_depth, "Subprogram nesting deeper than " + std::to_string(opts_.max_call_depth) + " program levels",
             column);
    const Program* p = nullptr;
    if (auto it = loaded_by_name_.find(name); it != loaded_by_name_.end()) p = it->second;
    if (!p) {
        namespace fs = std::filesystem;
        std::string found;
        for (const std::string& dir : opts_.search.dirs) {
            // NAME.SPF before NAME.MPF before NAME, in any case; several spellings: the first
            // in byte order (a directory lists its entries in no fixed order).
            const std::string wanted[] = {name + ".SPF", name + ".MPF", name};
            std::optional<std::pair<int, std::string>> best;
            std::error_code ec;
            for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
                const std::string file = it->path().filename().string();
                std::string up;
                for (char ch : file) up.push_back(ascii_upper(ch));
                for (int rank = 0; rank < 3; ++rank)
                    if (up == wanted[rank] && (!best || std::make_pair(rank, file) < *best)) best.emplace(rank, file);
            }
            if (!best) continue;
            const CalledEntry entry = look_in(opts_.search, dir, fs::path(dir) / best->second);
            if (entry.kind == CalledEntry::absent) continue;  // a link to nothing
            if (entry.kind == CalledEntry::refused) fail(entry.code, "Program " + name + ": " + entry.message, column);
            found = entry.path.string();
            break;
        }
        if (found.empty() && shopturn_step(name)) refuse_shopturn(name, column);
        if (found.empty() && standard_cycle(name))
            fail(code::unsupported_word, "The 840D's standard cycle " + name +
                                             " is not supported by toolcomp (its tool path is computed inside the cycle; "
                                             "a cycle program of that name on the search path is called)",
                 column);
        if (found.empty())
            fail(code::alarm_14011, "14011 Program " + name + " not existing or will be edited" +
                              (opts_.search.dirs.empty() ? " (no search path given)" : " (not on the search path)"),
                 column);
        CalledText f = read_called(opts_.search, found, cr_ends_line(Dialect::sinumerik));
        if (!f.ok()) fail(f.code, "Program " + name + ": " + f.message, column);
        try {
            loaded_.push_back(parse(f.text, found, false));
        } catch (const ParseError& e) {  // a syntax error in the called file: its line there
            throw ParseError(e.code(), e.what(), {e.line(), e.column(), found});
        }
        p = &loaded_.back();
        loaded_by_name_[name] = p;
    }
    const ProgramInfo& callee = info_of(*p);
    std::map<std::string, Variable> locals = bind_arguments(name, callee, args, column);
    stack_.push_back(Context{p, &callee, 0, std::move(locals), false, 0, 0, file_index(p->name)});
    stack_.back().passes_left = passes - 1;
    stack_.back().call_line = line_;
    std::vector<std::string> given = args.find_first_not_of(" \t") == std::string::npos ? std::vector<std::string>{}
                                                                                        : split_args(args);
    for (std::size_t i = 0; i < callee.formals.size(); ++i)
        stack_.back().subpar.push_back(i < given.size() && !given[i].empty());
}

bool Interp::ret() {
    if (stack_.size() == 1) {  // the main program ends with its last block
        if (!ended_) sink_.control({ControlKind::program_end, line_, Vec3::Zero(), file()});
        ended_ = true;
        return false;
    }
    Context& c = stack_.back();
    if (c.saved) {  // PROC ... SAVE: the caller's G functions and frame again
        if (st_.side != 0 && c.saved->modal.side == 0)  // G40 again: the compensation ends here
            sink_.control({ControlKind::radius_off, line_, Vec3::Zero(), file()});
        const int settable = st_.settable;
        st_ = c.saved->modal;
        set_programmable(c.saved->frame, c.saved->components);
        if (st_.settable != settable) select_settable(st_.settable);  // the G function again, its frame
    }
    if (c.passes_left > 0) {
        --c.passes_left;
        c.pc = 0;
        c.locals.clear();
        c.executable_seen = false;
        return true;
    }
    stack_.pop_back();
    return true;
}

void interpret(const Program& program, const ToolTable* tools, const ControlProfile& profile,
               const InterpretOptions& options, MotionSink& sink, std::vector<Diagnostic>& diagnostics,
               InterpretOutput* out) {
    Interp interp(program, tools, profile, options, sink, diagnostics);
    run_reporting(interp, out, [](const Interp& i) { return InterpretOutput{i.files(), {}, {}, i.dwell_seconds()}; });
}

}  // namespace toolcomp::sinumerik
