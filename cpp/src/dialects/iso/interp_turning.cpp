// The Fanuc T series' multiple repetitive cycles (ControlProfile::turning_cycles): G71 / G72
// stock removal in turning / facing and G70 finishing, along the contour of the blocks
// N<P> .. N<Q>. The contour's blocks are read as they would run from the start point (their
// moves only: the state is left as it was); the passes are computed by
// cycles/turning_roughing.cpp.
#include <cmath>

#include "../../cycles/turning_roughing.hpp"
#include "toolcomp/compensation/nose.hpp"
#include "interp.hpp"
#include "toolcomp/program/codes.hpp"
#include "toolcomp/program/text.hpp"

namespace toolcomp::iso {

namespace {
// Collects the moves of a contour being read.
struct ContourSink final : MotionSink {
    std::vector<Motion> moves;
    void push(const Motion& m) override { moves.push_back(m); }
};

// G-code system A has no G91: U and W are the increments; a cycle's U and W are its own.
double word(const BlockWords& bw, char c) { return bw.has(c) ? bw[c].value : 0.0; }
}  // namespace

std::pair<std::size_t, std::size_t> Interp::contour_blocks(const BlockWords& bw) {
    const int col = bw.g_column[g_nonmodal];
    if (!bw.has('P') || !bw.has('Q')) fail(code::cycle_p_q_missing, "PS0061 ADDRESS P/Q NOT FOUND IN G70-G73", col);
    const Frame& f = frames_.back();
    auto find = [&](char c) {
        const double n = bw[c].value;
        auto it = n >= 0 && n == std::floor(n) && n < 1e9 ? f.at->flow.numbers.find(std::lround(n)) : f.at->flow.numbers.end();
        if (it == f.at->flow.numbers.end())
            fail(code::cycle_sequence_not_found, "PS0063 SEQUENCE NUMBER NOT FOUND: N" + shortest_number(n), bw[c].column);
        return it->second;
    };
    const std::size_t from = find('P'), to = find('Q');
    if (to < from)
        fail(code::cycle_sequence_not_found, "PS0063 SEQUENCE NUMBER NOT FOUND: N" + shortest_number(bw['Q'].value) +
                                                 " comes before N" + shortest_number(bw['P'].value),
             bw['Q'].column);
    return {from, to};
}

// Runs blocks [from, to] of the running program into a ContourSink and puts everything
// back as it was: the contour's F, S, G41/G42 act in G70 only. What a contour may hold:
// moves (G00-G03, X Z U W R I K), F, S, G40-G42; anything else is PS0066.
Interp::ContourMoves Interp::read_contour(std::size_t from, std::size_t to) {
    const Frame& f = frames_.back();
    const Program& p = f.prog();
    const int line = line_;
    const Block* block = block_;
    const ModalState st = st_;
    const Vec6 pos = pos_;
    const double feed = feed_;
    const Spindle saved_spindle = spindle();
    const bool arc_not_allowed = arc_not_allowed_, comp_moved = comp_moved_;
    const RadiusRequest radius = radius_;
    const std::size_t moves = moves_;
    const int plain_motion = plain_motion_, prev_motion = prev_motion_, last_d = last_d_;
    ContourSink sink;
    ContourMoves out;
    capture_ = &sink;
    struct Restore {
        Interp& i;
        ~Restore() { i.capture_ = nullptr; }
    } restore{*this};
    for (std::size_t k = from; k <= to; ++k) {
        const Block& b = p.blocks()[k];
        if (b.block_delete && opts_.block_delete) continue;
        line_ = b.line;
        block_ = &b;
        count_block();
        if (b.statement_count) fail(code::cycle_improper_block, "PS0066 IMPROPER G-CODE IN G71-G73: a macro statement in the contour");
        const BlockWords bw = collect_words(syntax_ ? block_words(b) : p.words(b), b.line, profile_, opts_.machine);
        for (int g = 0; g < g_group_count; ++g)
            if (bw.g[g] >= 0 && g != g_motion && g != g_radius_comp && g != g_spindle_mode)
                fail(code::cycle_improper_block, "PS0066 IMPROPER G-CODE IN G71-G73: G" + shortest_number(bw.g[g] / 10.0) +
                                                     " in the contour", bw.g_column[g]);
        if (bw.g[g_motion] >= 0 && bw.g[g_motion] != G0 && bw.g[g_motion] != G1 && bw.g[g_motion] != G2 && bw.g[g_motion] != G3)
            fail(code::cycle_improper_block, "PS0066 IMPROPER G-CODE IN G71-G73: G" + shortest_number(bw.g[g_motion] / 10.0) +
                                                 " in the contour", bw.g_column[g_motion]);
        if (bw.m_count || bw.machine_call)
            fail(code::cycle_improper_block, "PS0066 IMPROPER G-CODE IN G71-G73: an M code in the contour");
        if (bw.has('T')) fail(code::cycle_improper_block, "PS0066 IMPROPER G-CODE IN G71-G73: a T word in the contour", bw['T'].column);
        execute(bw);
        if (radius_.side != 0 && out.nose.side == 0) out.nose = radius_;
        if (k == from) {
            out.first_end = pos_.head<3>();
            sink.moves.clear();
        }
    }
    line_ = line;
    block_ = block;
    st_ = st;
    pos_ = pos;
    feed_ = feed, spindle() = saved_spindle;
    arc_not_allowed_ = arc_not_allowed, comp_moved_ = comp_moved;
    radius_ = radius;
    moves_ = moves;
    plain_motion_ = plain_motion, prev_motion_ = prev_motion, last_d_ = last_d;
    out.moves = std::move(sink.moves);
    return out;
}

// G71 (turning: passes along Z, stepping in X) and G72 (facing: along X, stepping in Z).
// The first block of the two-block form gives the depth of cut and the escape (G71 U R,
// G72 W R); the block with P and Q runs the cycle: U and W there are the finishing
// allowance (U a diameter), D the depth of cut in the one-block form.
void Interp::roughing_cycle(const BlockWords& bw, int code) {
    const int col = bw.g_column[g_nonmodal];
    const bool g71 = code == G71;
    const char name[] = {'G', '7', g71 ? '1' : '2', '\0'};
    for (char c : {'X', 'Z'})
        if (bw.has(c))
            fail(code::unsupported_word, std::string(1, c) + " in " + name + " is not supported by toolcomp", bw[c].column);
    if (!bw.has('P') && !bw.has('Q')) {  // G71 U(depth) R(escape) / G72 W(depth) R(escape)
        const char depth = g71 ? 'U' : 'W';
        if (bw.has(g71 ? 'W' : 'U') || bw.has('D') || bw.has('I') || bw.has('K'))
            fail(code::unsupported_word, std::string(name) + " without P and Q reads " + depth + " (the depth of cut) and R (the escape)",
                 col);
        if (bw.has(depth)) turn_depth_ = bw[depth].value;
        if (bw.has('R')) turn_escape_ = bw['R'].value;
        if (turn_depth_ <= 0 && bw.has(depth))
            fail(code::cycle_bad_value, "PS0062 ILLEGAL COMMAND IN G71-G76: the depth of cut must be above 0", bw[depth].column);
        return;
    }
    if (bw.has('R') && bw['R'].value != 1)
        fail(code::cycle_bad_value, std::string("PS0062 ILLEGAL COMMAND IN G71-G76: R in ") + name +
                                        " with P and Q selects type II (R1)", bw['R'].column);
    contour_cycle_can_start(name, col);
    double depth = turn_depth_;
    if (bw.has('D')) depth = bw['D'].value;
    if (!(depth > 0)) fail(code::cycle_bad_value, "PS0062 ILLEGAL COMMAND IN G71-G76: no depth of cut (U in the first block, or D)", col);
    const double escape = turn_escape_ >= 0 ? turn_escape_ : profile_.turning_escape / scale();
    const auto [from, to] = contour_blocks(bw);

    // The P block: G00 or G01; type II when it has the cutting axis too (X for G71, Z for
    // G72: its word need not move it), or with R1 (Haas in YASNAC mode).
    const BlockWords first = first_block(from, col);
    const bool type2 = bw.has('R') || (g71 ? first.has('Z') || first.has('W') : first.has('X') || first.has('U'));
    cycles::Roughing r;
    r.rapid_infeed = (first.g[g_motion] >= 0 ? first.g[g_motion] : st_.motion) == 0;
    RadiusRequest nose;
    const cycles::Contour contour = cycle_contour(from, to, g71, &nose);
    line_ = bw.line;
    r.start = turning_uv(pos_.head<3>(), g71);
    r.depth = depth;
    r.retract = escape;
    r.max_moves = block_budget();
    const double du = word(bw, 'U') / 2, dw = word(bw, 'W');  // U: a diameter
    r.allowance = g71 ? Vec2(dw, du) : Vec2(du, dw);
    const double ri = word(bw, 'I'), rk = word(bw, 'K');  // Haas: rough allowances (I a radius)
    r.rough_allowance = g71 ? Vec2(rk, ri) : Vec2(ri, rk);
    if (nose.side != 0 && profile_.roughing_nose_allowance) r.allowance += nose_allowance(nose, contour, r.start, g71);
    std::vector<cycles::Step> steps;
    try {
        steps = type2 ? cycles::rough_type2(contour, r) : cycles::rough_type1(contour, r);
    } catch (const cycles::MoveLimit&) {
        block_limit_exceeded(col);
    } catch (const cycles::CycleError& e) {
        if (e.line) line_ = e.line;
        fail(e.code, e.message, e.line ? 0 : col);
    }
    emit_steps(steps, g71, bw, col);
    // A contour that follows its cycle is the cycle's: the program goes on after it.
    if (from == frames_.back().pc) frames_.back().pc = to + 1;
}

// G73 U(Δi) W(Δk) R(d); G73 P Q U(Δu) W(Δw) F: d passes along the contour, the first shifted
// by Δi + Δu/2 in X (radius) and Δk + Δw in Z, the last by the allowance, those between
// evenly; each from the start point and back to it. The contour need not be monotonic.
void Interp::pattern_cycle(const BlockWords& bw) {
    const int col = bw.g_column[g_nonmodal];
    for (char c : {'X', 'Z'})
        if (bw.has(c)) fail(code::unsupported_word, std::string(1, c) + " in G73 is not supported by toolcomp", bw[c].column);
    if (!bw.has('P') && !bw.has('Q')) {  // G73 U(Δi) W(Δk) R(d)
        for (char c : {'I', 'K', 'D'})
            if (bw.has(c)) fail(code::unsupported_word, std::string(1, c) + " in G73 without P and Q", bw[c].column);
        if (bw.has('U')) pattern_.relief_x = bw['U'].value;
        if (bw.has('W')) pattern_.relief_z = bw['W'].value;
        if (bw.has('R')) pattern_.divisions = pass_count(bw, 'R');
        return;
    }
    if (bw.has('R')) fail(code::unsupported_word, "R in G73 with P and Q is not supported by toolcomp", bw['R'].column);
    // The one-block form (Haas): I, K the distance from the first pass to the last (I a
    // radius), D the number of passes; for this cycle only.
    PatternRepeat pattern = pattern_;
    if (bw.has('I')) pattern.relief_x = bw['I'].value;
    if (bw.has('K')) pattern.relief_z = bw['K'].value;
    if (bw.has('D')) pattern.divisions = pass_count(bw, 'D');
    contour_cycle_can_start("G73", col);
    const auto [from, to] = contour_blocks(bw);
    const BlockWords first = first_block(from, col);
    const bool rapid = (first.g[g_motion] >= 0 ? first.g[g_motion] : st_.motion) == 0;
    const cycles::Contour contour = cycle_contour(from, to, true);
    line_ = bw.line;
    const Vec2 last(word(bw, 'W'), word(bw, 'U') / 2);  // (Z, X radius)
    const Vec2 relief(pattern.relief_z, pattern.relief_x);
    std::vector<cycles::Step> steps;
    try {
        steps = cycles::pattern_repeat(contour, turning_uv(pos_.head<3>(), true), last + relief, last, pattern.divisions, rapid,
                                       profile_.pattern_return_shifted, block_budget());
    } catch (const cycles::MoveLimit&) {
        block_limit_exceeded(col);
    } catch (const cycles::CycleError& e) {
        fail(e.code, e.message, col);
    }
    emit_steps(steps, true, bw, col);
    if (from == frames_.back().pc) frames_.back().pc = to + 1;
}

// G73 R (two-block) or D (one-block): the number of passes, a whole number from 1.
int Interp::pass_count(const BlockWords& bw, char c) const {
    const double d = bw[c].value;
    if (d != std::floor(d) || d < 1 || d > 100000)
        fail(code::cycle_bad_value, std::string("PS0062 ILLEGAL COMMAND IN G71-G76: G73 ") + c + " is the number of passes, 1 or more",
             bw[c].column);
    return static_cast<int>(d);
}

// What G71-G73 need to start: no nose radius compensation on, the ZX plane, a feed.
void Interp::contour_cycle_can_start(const char* name, int col) const {
    if (comp_on())
        fail(code::unsupported_g_code, std::string(name) + " with tool nose radius compensation on is not supported by "
                                       "toolcomp (G40 first; G41/G42 in the contour act in G70)", col);
    if (st_.plane != Plane::zx)
        fail(code::cycle_bad_value, std::string("PS0062 ILLEGAL COMMAND IN G71-G76: ") + name + " needs the ZX plane (G18)", col);
    if (feed_ <= 0) fail(code::zero_feed, std::string("Cannot feed with zero feed rate in ") + name, col);
    check_feed_per_rev(col);
}

// The P block of G71-G73: G00 or G01 (given, or the mode in force).
BlockWords Interp::first_block(std::size_t from, int col) {
    const Program& p = frames_.back().prog();
    const Block& b = p.blocks()[from];
    BlockWords first = collect_words(syntax_ ? block_words(b) : p.words(b), b.line, profile_, opts_.machine);
    const int motion = first.g[g_motion] >= 0 ? first.g[g_motion] : st_.motion;
    if (motion != G0 && motion != G1)
        fail(code::cycle_first_block, "PS0065 ILLEGAL COMMAND IN G71-G73: the P block must be G00 or G01", col);
    return first;
}

// Plane coordinates of a turning cycle's cut: G71 and G73 (u, v) = (Z, X), the ZX plane's
// (a, b); G72 (X, Z), mirrored, so its arcs turn the other way.
Vec2 Interp::turning_uv(const Vec3& q, bool along_z) { return along_z ? Vec2(q.z(), q.x()) : Vec2(q.x(), q.z()); }

cycles::Contour Interp::cycle_contour(std::size_t from, std::size_t to, bool along_z, RadiusRequest* nose) {
    const ContourMoves moves = read_contour(from, to);
    if (nose) *nose = moves.nose;
    cycles::Contour contour;
    contour.start = turning_uv(moves.first_end, along_z);
    for (const Motion& m : moves.moves) {
        cycles::ContourPiece piece{turning_uv(m.end, along_z), turning_uv(m.center, along_z), 0, m.line};
        if (m.is_arc()) piece.dir = (m.kind == MotionKind::arc_ccw ? 1 : -1) * (along_z ? 1 : -1);
        contour.pieces.push_back(piece);
    }
    return contour;
}

// Haas's reading of G41/G42 in a roughing contour: the passes leave the nose radius more, in
// each axis from the imaginary tip towards the nose's centre (-r·σ); where the tip lies at
// the centre in an axis (tips 5-9, 0), r towards the stock (the start point's side of the
// contour, in (u, v) of the cut).
Vec2 Interp::nose_allowance(const RadiusRequest& nose, const cycles::Contour& contour, const Vec2& start, bool g71) const {
    const TipVector t = tip_vector(nose.orientation, profile_.radius.tip_convention);
    const double r = nose.radius;
    const Vec2 stock(start.x() > contour.pieces.back().end.x() ? 1.0 : -1.0, start.y() > contour.start.y() ? 1.0 : -1.0);
    const Vec2 tip = g71 ? Vec2(t.z, t.x) : Vec2(t.x, t.z);  // (u, v)
    return {tip.x() != 0 ? -r * tip.x() : r * stock.x(), tip.y() != 0 ? -r * tip.y() : r * stock.y()};
}

// The moves of a turning cycle, at the cycle block's line: rapid, feed (the modal F, per
// revolution under G99), arcs.
void Interp::emit_steps(const std::vector<cycles::Step>& steps, bool along_z, const BlockWords& bw, int col) {
    auto at = [&](const Vec2& q) {
        Vec6 e = pos_;
        if (along_z) e[2] = q.x(), e[0] = q.y();
        else e[0] = q.x(), e[2] = q.y();
        return e;
    };
    for (const cycles::Step& s : steps) {
        count_block(col);
        const Vec6 end = at(s.end);
        if (end == pos_) continue;
        if (s.kind == cycles::StepKind::rapid) {
            straight(MotionKind::rapid, end, std::nan(""));
        } else if (s.kind == cycles::StepKind::feed) {
            straight(MotionKind::line, end, feed_for(bw, 10, 0, end[0]));
        } else {
            Motion m = motion_to((s.dir * (along_z ? 1 : -1)) > 0 ? MotionKind::arc_ccw : MotionKind::arc_cw, end);
            m.center = at(s.center).head<3>();
            m.feed = feed_for(bw, 20, 0, end[0]);
            emit(m);
        }
    }
}

// G70 P Q: the contour's blocks run as written (their F, S, G41/G42 now act), then the tool
// goes back to where it stood at rapid, and the program goes on after the G70 block.
void Interp::finishing_cycle(const BlockWords& bw) {
    const int col = bw.g_column[g_nonmodal];
    for (char c : {'X', 'Z', 'U', 'W', 'R', 'D', 'I', 'K'})
        if (bw.has(c)) fail(code::unsupported_word, std::string(1, c) + " in G70 is not supported by toolcomp", bw[c].column);
    const auto [from, to] = contour_blocks(bw);
    Frame f;
    f.kind = Frame::g70;
    f.at = frames_.back().at;
    f.pc = from;
    f.stop = to + 1;
    f.back = pos_;
    f.call_line = line_;
    (void)col;
    push_frame(std::move(f));
}

}  // namespace toolcomp::iso
