// The ISO interpreter: its start state, the run over the program's blocks (control
// statements, words, comments, M98/M99 and remaps around each block), and the checks of a
// block's words. A block itself runs step by step in interp_execute.cpp.
#include <cctype>
#include <cmath>
#include <stdexcept>

#include "interp.hpp"
#include "toolcomp/program/codes.hpp"
#include "toolcomp/program/source_files.hpp"
#include "toolcomp/tools/tool_table.hpp"

namespace toolcomp::iso {

Interp::Interp(const Program& prog, const ToolTable* tools, const ControlProfile& profile,
               const InterpretOptions& opts, MotionSink& sink, std::vector<Diagnostic>& diags)
    : prog_(prog), tools_(tools), profile_(profile), opts_(opts), sink_(sink), diags_(diags),
      params_(prog.dialect == Dialect::fanuc) {
    if (prog.dialect == Dialect::linuxcnc) syntax_ = &expr::linuxcnc_syntax();
    if (prog.dialect == Dialect::fanuc) syntax_ = &expr::fanuc_syntax();
    for (auto& o : g5x_) o.setZero();
    st_.inch = profile.startup_inch;
    st_.diameter = profile.x_diameter;
    st_.plane = profile.startup_plane;
    if (profile.startup_feed_per_rev) st_.feed_mode = G95;
    st_.motion = profile.startup_motion;
    st_.retract_initial = profile.startup_retract_initial;
    if (st_.motion != G80) plain_motion_ = st_.motion;
    load_parameters(opts.parameters);
    if (opts.machine) place_machine(*opts.machine, opts.parameters);
    if (opts.start) {
        Vec6 at = Vec6::Zero();
        for (int j = 0; j < 3; ++j) at[j] = (*opts.start)[j] / machine_scale(j);
        pos_ = from_machine(at);
    }
    if (opts.machine && opts.machine->has_travel_limits()) travel_.emplace(*opts.machine);
}

// The machine's work origin (G54) and G28/G30 positions, in machine coordinates, where the
// parameters (a .var file: the machine's live state) do not give them; the machine stands
// at its zero.
void Interp::place_machine(const Machine& m, const ParameterValues& values) {
    for (int j = 0; j < 3; ++j) {
        const double u = machine_scale(j);  // a lathe's machine X is a diameter
        if (!values.count(5221 + j)) g5x_[0][j] = m.work_origin[static_cast<std::size_t>(j)] / u;
        if (!values.count(5161 + j)) g28_[j] = m.g28[static_cast<std::size_t>(j)] / u;
        if (!values.count(5181 + j)) g30_[j] = m.g30[static_cast<std::size_t>(j)] / u;
    }
    pos_ = from_machine(Vec6::Zero());
}

// The start values of the numbered parameters (a .var file). LinuxCNC keeps the machine's
// state there too, and takes it back at start: the G28/G30 positions (#5161-#5166,
// #5181-#5186), the G92 offsets (#5210, #5211-#5216), the coordinate system in use (#5220)
// and the G54-G59.3 origins and XY rotations (#5221 + 20 n ... +9), in the units the program
// starts in; the machine stands at its zero. A value that is not finite, or a number the
// dialect does not keep, is refused, never dropped.
void Interp::load_parameters(const ParameterValues& values) {
    for (const auto& [n, v] : values) {
        if (!std::isfinite(v))
            throw std::invalid_argument("parameters: #" + std::to_string(n) + " is not a finite number");
        if (!params_.stored(n))
            throw std::invalid_argument("parameters: #" + std::to_string(n) + " is not a parameter of the " +
                                        std::string(dialect_name(prog_.dialect)) + " dialect");
    }
    params_.load(values);
    if (params_.fanuc()) return;
    auto value = [&](int n) {
        auto it = values.find(n);
        return it == values.end() ? 0.0 : it->second;
    };
    for (int j = 0; j < 6; ++j) {
        g28_[j] = value(5161 + j);
        g30_[j] = value(5181 + j);
        g92_saved_[j] = value(5211 + j);
        for (int cs = 0; cs < 9; ++cs) g5x_[static_cast<std::size_t>(cs)][j] = value(5221 + 20 * cs + j);
    }
    for (int cs = 0; cs < 9; ++cs) rotation_[static_cast<std::size_t>(cs)] = value(5230 + 20 * cs);
    // U, V, W (the 7th to 9th value of each group): axes toolcomp does not run.
    std::vector<int> uvw{5161, 5181, 5211};
    for (int cs = 0; cs < 9; ++cs) uvw.push_back(5221 + 20 * cs);
    for (int first : uvw)
        for (int n = first + 6; n < first + 9; ++n)
            if (value(n) != 0)
                throw std::invalid_argument("parameters: #" + std::to_string(n) +
                                            " is a U, V or W axis value, which toolcomp does not run");
    g92_on_ = value(5210) != 0;
    g92_ = g92_on_ ? g92_saved_ : Vec6::Zero();
    if (values.count(5220)) {
        const double c = value(5220);
        if (c != std::floor(c) || c < 1 || c > 9)
            throw std::invalid_argument("parameters: #5220 (the coordinate system in use) must be 1 to 9");
        st_.coord_system = static_cast<int>(c);
    }
    pos_ = from_machine(Vec6::Zero());
}

// G20/G21: everything the interpreter keeps in program units is converted, so the machine
// stays where it is (LinuxCNC's convert_length_units).
void Interp::set_units(bool inch) {
    if (st_.inch == inch) return;
    st_.inch = inch;
    const double f = inch ? 1 / kMmPerInch : kMmPerInch;
    auto lengths = [f](Vec6& v) { v.head<3>() *= f; };
    lengths(pos_);
    for (auto& o : g5x_) lengths(o);
    lengths(g92_);
    lengths(g92_saved_);
    lengths(tlo_);
    lengths(g28_);
    lengths(g30_);
    for (double* v : {&cyc_.r, &cyc_.z, &cyc_.q, &cyc_.i, &cyc_.j, &cyc_.k, &cycle_il_}) *v *= f;
    radius_.radius *= f;
    // LinuxCNC reads the G64 tolerance back from the machine here, which holds it in G64 only.
    if (st_.path_control != G64) tolerance_ = 0;
}

void Interp::fail(const char* code, const std::string& msg, int column) const {
    throw ProgramError(code, msg, {line_, column, file_name()});
}

void Interp::info(const char* code, const std::string& msg, int column) {
    diags_.push_back({code, Severity::info, msg, {line_, column, file_name()}});
}

void Interp::count_block(int column) {
    if (++executed_ > profile_.block_limit) block_limit_exceeded(column);
    if (idle_.too_long(moves_, profile_.no_motion_limit)) [[unlikely]]
        fail(code::no_progress, no_progress_text(profile_.no_motion_limit), column);
}

void Interp::block_limit_exceeded(int column) const {
    fail(code::block_limit, "More than " + std::to_string(profile_.block_limit) +
                                " blocks executed, canned cycle repeats included (ControlProfile.block_limit)",
         column);
}

void Interp::run() {
    main_.prog = &prog_;
    main_.flow = scan_flow(prog_);
    files_.push_back(prog_.name);
    if (opts_.file_opened) opts_.file_opened(prog_.name);
    Frame top;
    top.at = &main_;
    frames_.push_back(top);
    try {
        run_blocks();
    } catch (const Error& e) {
        // LinuxCNC unwinds the calls before it reports: an error at any depth is reported at
        // the main program's line of the outermost call.
        // (A file that cannot be read or parsed fails at the call itself.)
        if (!profile_.errors_at_outermost_call || (frames_.size() < 2 && e.file().empty())) throw;
        throw_at(e, SourcePos{frames_.size() >= 2 ? frames_[1].call_line : line_, 0, {}});
    }
}

void Interp::run_blocks() {
    std::size_t read = 0;
    for (;;) {
        Frame& f = frames_.back();
        const Program& p = f.prog();
        if (f.kind == Frame::g70 && f.pc >= f.stop) {  // G70's contour done: back to where it began
            const Vec6 back = f.back;
            line_ = f.call_line;
            file_ = f.at->file;
            frames_.pop_back();
            if (back != pos_) straight(MotionKind::rapid, back, std::nan(""));
            continue;
        }
        if (f.pc >= p.size()) {
            if (frames_.size() == 1) {
                const Program* next = opts_.next_piece && !p.syntax_error ? opts_.next_piece() : nullptr;
                if (!next) break;
                main_.prog = next;
                main_.flow = scan_flow(*next);
                f.pc = 0;
                continue;
            }
            end_of_file(f);
        }
        const std::size_t k = f.pc++;
        const Block& block = p.blocks()[k];
        if (opts_.progress && ++read % opts_.progress_every == 0) opts_.progress(read);
        if (block.block_delete && opts_.block_delete) continue;
        line_ = block.line;
        file_ = f.at->file;
        count_block();
        block_ = &block;
        if (block.statement_count)
            if (const Statement* s = control_statement(p, block); s && !(s->kind == Stmt::m99_return && frames_.size() < 2)) {
                control(*s, k);
                if (ended_) {  // a remapped code's block ended the program when its sub returned
                    sink_.finish();
                    return;
                }
                continue;
            }
        const std::span<const Word> words = syntax_ ? block_words(block) : p.words(block);
        if (profile_.macro_calls) {
            bool g65 = false;
            for (const Word& w : words) g65 = g65 || (w.letter == 'G' && w.value == written(G65));
            if (g65) {
                int column = 0;
                for (const Word& w : words)
                    if (w.letter == 'G') column = w.column;
                macro_call(words, column);
                continue;
            }
        }
        BlockWords bw = collect_words(words, block.line, profile_, opts_.machine);
        if (profile_.dwell_x_seconds && bw.g[g_nonmodal] == G4) fanuc_dwell(bw);
        alarm_text_.clear();
        if (profile_.macro_calls && block.comment_count) alarm_text_ = p.comments(block)[0].text;
        if (block.statement_count) assignments(block);  // messages show the values after them
        if (profile_.last_comment_only) {  // LinuxCNC: the last in parentheses overwrote the others
            const Comment* last = nullptr;
            for (const Comment& c : p.comments(block))
                if (!c.semicolon) last = &c;
            if (last) message_comment(*last);
        } else {
            for (const Comment& c : p.comments(block)) message_comment(c);
        }
        // Fanuc M98 / M99 run after the rest of their block.
        const int sub_m = bw.m[m_subprogram];
        WordSlot p_word, l_word;
        if (sub_m >= 0) {
            p_word = bw['P'];
            l_word = bw['L'];
            bw.remove('P');
            bw.remove('L');
        }
        if (bw.machine_call && prog_.dialect == Dialect::linuxcnc) {
            // LinuxCNC: the remap's sub runs after the block's M codes, the rest of the block
            // when it returns (return_from_sub).
            if (const int motion = execute_head(bw); motion != kBlockEnded) {
                machine_subprogram(bw);
                frames_.back().resume = std::make_shared<BlockWords>(bw);
                frames_.back().resume_motion = motion;
            }
            continue;
        }
        const std::size_t moves_before = moves_;
        if (!execute(bw)) {
            sink_.finish();
            return;
        }
        // A block that moved nothing under compensation (not the one that switched it, a stop,
        // whose events settle the stage anyway, or a subprogram call), for controls that count
        // such blocks.
        if (moves_ == moves_before && comp_on() && !words.empty() && profile_.radius.count_blocks_without_motion &&
            bw.g[g_radius_comp] < 0 && bw.m[m_stop] < 0 && sub_m < 0)
            sink_.control({ControlKind::no_motion, line_, Vec3::Zero(), file_});
        if (sub_m >= 0) subprogram(sub_m, p_word, l_word, bw.m_column[m_subprogram]);
        if (bw.machine_call) machine_subprogram(bw);
    }
    sink_.finish();
    line_ = 0;
    file_ = 0;
    const Program& last = *main_.prog;  // the whole program, or its last piece
    if (const auto& e = last.syntax_error) throw ParseError(e->code, e->message, e->pos);
    if (profile_.program_end_required) {
        // LinuxCNC refuses a file that simply stops: it must end with M2/M30 or '%'.
        line_ = last.last_line;
        if (last.percent_open && !last.percent_closed)
            fail(code::no_program_end, "File ended with no percent sign");
        if (!last.percent_open) fail(code::no_program_end, "File ended with no percent sign or program end");
    }
}

// A subprogram's file ends before its return: its syntax error, or the missing return.
void Interp::end_of_file(const Frame& f) {
    const Program& p = f.prog();
    line_ = p.last_line;
    file_ = f.at->file;
    if (const auto& e = p.syntax_error) throw ParseError(e->code, e->message, e->pos);
    fail(code::subprogram_end_missing, f.kind == Frame::o_call ? "File ended inside a subroutine (no endsub)"
                                                           : "Subprogram file ended without M99");
}

void Interp::check_words(const BlockWords& bw, int motion_to_be) {
    constexpr std::uint32_t kChecked = letter_bit('D') | letter_bit('E') | letter_bit('H') | letter_bit('I') |
                                       letter_bit('J') | letter_bit('K') | letter_bit('L') | letter_bit('P') |
                                       letter_bit('Q') | letter_bit('R');
    if (profile_.c_word_is_chamfer && bw.has('C') && motion_to_be == G1 &&
        (bw.has('X') || bw.has('Z') || bw.has('U') || bw.has('W')))
        fail(code::unsupported_word,
             "C beside X or Z in G1 is the chamfer of a Fanuc lathe: not supported by toolcomp (a C axis move "
             "stands in a block of its own)",
             bw['C'].column);
    const bool sync = motion_to_be == G33 || motion_to_be == G33_1, g76 = motion_to_be == G76;  // LinuxCNC
    const bool g5 = motion_to_be == G5, g51 = motion_to_be == G5_1, g52 = motion_to_be == G5_2;  // splines
    const bool g7x = profile_.profile_cycles && is_profile_cycle(motion_to_be);  // LinuxCNC G70-G72
    const bool g70 = g7x && motion_to_be == G70, g71 = g7x && !g70;
    const bool m19 = bw.m[m_spindle] == M19;  // LinuxCNC's spindle orient: R Q P
    if ((bw.letters & kChecked) == 0 && !sync && !g76) return;  // none of the words that need a code to use them
    const int g0 = bw.g[g_nonmodal];
    if (g0 >= G70 && g0 <= G76 && g0 % 10 == 0) return;  // the lathe cycles G70-G76 read their words
    const bool arc = motion_to_be == G2 || motion_to_be == G3;
    const bool g87 = motion_to_be == G87;  // back boring takes I J K too
    const bool cycle_block = is_cycle(motion_to_be);
    auto col = [&](char c) { return bw[c].column; };
    if (bw.has('D') && !(profile_.d_word_alone && !profile_.t_offsets)) {
        int rc = bw.g[g_radius_comp];
        if (!(rc == G41 || rc == G41_1 || rc == G42 || rc == G42_1 || bw.g[g_spindle_mode] == G96 || g7x))
            fail(code::unused_word, "D word with no G41, G41.1, G42, G42.1, G71, G71.1, G71.2 or G96 to use it", col('D'));
    }
    const bool io = bw.m[m_io] >= 0;  // M62-M68 take P, Q and E
    if (bw.has('E') && !(io && bw.m[m_io] >= M66) && !g76 && !g70) fail(code::unused_word, "E word with no G70, G76, M66, M67 or M68 to use it", col('E'));
    if (bw.has('H')) {
        int lc = bw.g[g_length_comp];
        if (!(lc == G43 || lc == G43_2 || lc == G44 || g76)) fail(code::unused_word, "H word with no G43 or G76 to use it", col('H'));
    }
    const bool exit_dir = bw.g[g_radius_comp] == G40 && profile_.radius.exit_direction_words;
    if (bw.has('I') && !(arc || g87 || exit_dir || g0 == G10 || motion_to_be == G33_1 || g76 || g5 || g51 || g71))
        fail(code::unused_word, "I word with no G2, G3, G5, G5.1, G10, G33.1, G76, or G87 to use it", col('I'));
    if (bw.has('J') && !(arc || g87 || exit_dir || g0 == G10 || g76 || g5 || g51))
        fail(code::unused_word, "J word with no G2, G3, G5, G5.1, G10, G76 or G87 to use it", col('J'));
    if (bw.has('K') && !(arc || g87 || exit_dir || sync || g76)) fail(code::unused_word, "K word with no G2, G3, G33, G33.1, G76, or G87 to use it", col('K'));
    if (bw.has('L')) {
        int rc = bw.g[g_radius_comp];
        if (!(g0 == G10 || cycle_block || rc >= G41 || bw.m[m_io] == M66 || g76 || g52))  // G41, G41.1, G42, G42.1, M66
            fail(code::unused_word,
                 "L word with no G10, cutter compensation, canned cycle, digital/analog input, M98 or NURBS code",
                 col('L'));
    }
    if (bw.has('P')) {
        int m = bw.m[m_override];
        bool ok = arc || io || g0 == G4 || g0 == G10 || bw.g[g_path_control] == G64 || motion_to_be == G82 ||
                  motion_to_be == G86 || motion_to_be == G88 || motion_to_be == G89 ||
                  (m >= M50 && m <= M53) || g76 || g5 || g52 || g70 || m19;
        if (!ok)
            fail(code::unused_word,
                 "P word with no G2 G3 G4 G10 G64 G5 G5.2 G76 G82 G86 G88 G89 or M50 M51 M52 M53 M62 M63 M64 "
                 "M65 M66 M98 or user M code to use it",
                 col('P'));
    }
    if (bw.has('Q')) {
        bool ok = (io && bw.m[m_io] >= M66) || g0 == G10 || bw.g[g_path_control] == G64 || motion_to_be == G73 || motion_to_be == G83 ||
                  bw.m[m_tool_change] == M61 || g76 || g5 || g7x || m19;
        if (!ok)
            fail(code::unused_word,
                 "Q word with no G5, G10, G64, G73, G76, G83, M19, M66, M67, M68 or user M code that uses it",
                 col('Q'));
    }
    const bool single_cycle = motion_to_be == G90 || motion_to_be == G92 || motion_to_be == G94;
    if (bw.has('R') && !(arc || cycle_block || single_cycle || g0 == G10 || g76 || g71 || m19))
        fail(code::unused_word, "R word with no g code that uses it", col('R'));
    if (m19) {
        const double p = bw['P'].value;
        if (bw.has('P') && std::fabs(std::round(p) - p) > 0.001)
            fail(code::arc_p_not_integer, "P value not an integer with M19 G2 or G3", col('P'));
        if (bw.has('P') && (std::round(p) > 2 || std::round(p) < 0))
            fail(code::spindle_orient_words, "P value must be 0,1,or 2 with M19", col('P'));
        if (bw.has('R') && (bw['R'].value > 360.0 || bw['R'].value < 0.0))
            fail(code::spindle_orient_words, "R value must be within 0..360 with M19", col('R'));
    }
    const int mcol = bw.g[g_motion] >= 0 ? bw.g_column[g_motion] : bw.axis_column();
    if (sync && !bw.has('K')) fail(code::sync_motion_words, "K word missing with g33/g33.1", mcol);
    if (sync && bw.has('F')) fail(code::sync_motion_words, "F word used with a g33/g33.1", col('F'));
    if (g76 && (!bw.has('P') || bw['P'].value == -1)) fail(code::sync_motion_words, "P word missing with G76", mcol);
    if (g76 && !(bw.has('I') && bw.has('J') && bw.has('K')))
        fail(code::sync_motion_words, "I J or K words missing with G76", mcol);
}

// Fanuc G04 X1.5 / U1.5 (lathes): the dwell in seconds, the X or U word not a move. Only one
// of X, U and P may give it.
void Interp::fanuc_dwell(BlockWords& bw) const {
    for (char c : {'X', 'U'}) {
        if (!bw.has(c) || (c == 'U' && !profile_.incremental_uw)) continue;  // U: lathes only
        if (bw.has('P') || (c == 'U' && bw.has('X')))
            fail(code::dwell_twice, "G4 with two dwell times (X, U or P): give it once", bw[c].column);
        bw.set('P', bw[c].value * 1000, bw[c].column);  // P is in milliseconds
        bw.remove(c);
    }
}

// Fanuc lathes, G-code system A: G90, G92 and G94 name cycles there, not the mill's modes.
void Interp::system_a_codes(const BlockWords& bw) const {
    struct Refused {
        int group, code;
        const char *error, *message;
    };
    static constexpr Refused kRefused[] = {
        {g_distance, G90, code::unsupported_g_code, "G90 is the turning cycle in G-code system A: not supported by toolcomp"},
        {g_distance, G91, code::unknown_g_code, "G91 does not exist in G-code system A (U and W are the incremental words)"},
        {g_nonmodal, G92, code::unsupported_g_code, "G92 is the threading cycle in G-code system A: not supported by toolcomp"},
        {g_feed_mode, G94, code::unsupported_g_code, "G94 is the facing cycle in G-code system A: not supported by toolcomp"},
        // The mill's canned cycles mean other cycles on a Fanuc lathe (G73 pattern repeating,
        // G74 end face peck drilling, G83-G89 face and side drilling with live tools).
        {g_motion, G73, code::unsupported_g_code, "G73 is the pattern repeating cycle on a lathe: not supported by toolcomp"},
        {g_motion, G74, code::unsupported_g_code, "G74 is the end face peck drilling cycle on a lathe: not supported by toolcomp"},
        {g_motion, G81, code::unsupported_g_code, "G81 is a lathe drilling cycle here: not supported by toolcomp"},
        {g_motion, G82, code::unsupported_g_code, "G82 is a lathe drilling cycle here: not supported by toolcomp"},
        {g_motion, G83, code::unsupported_g_code, "G83 is the face drilling cycle on a lathe: not supported by toolcomp"},
        {g_motion, G84, code::unsupported_g_code, "G84 is the face tapping cycle on a lathe: not supported by toolcomp"},
        {g_motion, G85, code::unsupported_g_code, "G85 is the face boring cycle on a lathe: not supported by toolcomp"},
        {g_motion, G86, code::unsupported_g_code, "G86 is a lathe cycle here: not supported by toolcomp"},
        {g_motion, G87, code::unsupported_g_code, "G87 is the side drilling cycle on a lathe: not supported by toolcomp"},
        {g_motion, G88, code::unsupported_g_code, "G88 is the side tapping cycle on a lathe: not supported by toolcomp"},
        {g_motion, G89, code::unsupported_g_code, "G89 is the side boring cycle on a lathe: not supported by toolcomp"},
    };
    for (const Refused& r : kRefused)
        if (bw.g[r.group] == r.code) fail(r.error, r.message, bw.g_column[r.group]);
}

// Which motion the axis words feed (LinuxCNC's "motion_to_be"): the block's motion code, or
// the modal one.
int Interp::motion_of(const BlockWords& bw) const {
    const int g0 = bw.g[g_nonmodal];
    const bool axes = bw.has_axis();
    int motion_to_be = bw.g[g_motion];
    if (motion_to_be < 0 && axes && !axes_are_data(bw)) motion_to_be = st_.motion;
    if (g0 == G53 && profile_.g53_rapid && axes) motion_to_be = G0;  // Fanuc: G53 at rapid, whatever the mode
    if (profile_.bare_motion_codes && motion_to_be < 0 && !axes && (st_.motion == G2 || st_.motion == G3) &&
        (bw.has('I') || bw.has('J') || bw.has('K')))
        motion_to_be = st_.motion;  // "I1" alone under G2: an arc
    return motion_to_be;
}

void interpret(const Program& program, const ToolTable* tools, const ControlProfile& profile,
               const InterpretOptions& options, MotionSink& sink, std::vector<Diagnostic>& diagnostics,
               InterpretOutput* output) {
    Interp interp(program, tools, profile, options, sink, diagnostics);
    run_reporting(interp, output, [](const Interp& i) { return i.output(); });
}

}  // namespace toolcomp::iso
