// LinuxCNC's lathe profile cycles (ControlProfile::profile_cycles): G70 finishing, G71 / G72
// roughing and their .1 / .2 variants. The block's words and the profile, read from the
// subroutine O<Q> as LinuxCNC reads it; the geometry is in cycles/profile_cycles.cpp.
#include <cmath>

#include "../../cycles/profile_cycles.hpp"
#include "codes.hpp"
#include "interp.hpp"
#include "toolcomp/program/codes.hpp"
#include "whole_numbers.hpp"

namespace toolcomp::iso {

using cycles::profile::Piece;
using cycles::profile::Point;

namespace {

std::string cycle_name(int code) { return "G" + std::to_string(code / 10) + "." + std::to_string(code % 10); }

}  // namespace

// A block of the profile: its end from X / Z (G91: increments) or U / W (increments in G90),
// an arc's centre from I / K (not halved in G7) or R, a fillet (A) or chamfer (C) at its end.
// Nothing else of the block acts (F, S, M, T, G41/G42, G7/G8, G90/G91 are read, not run).
void Interp::profile_piece(const BlockWords& w, int& mode, Point& at, std::vector<Piece>& pieces) const {
    const bool inc = st_.incremental;
    // LinuxCNC writes "G7x error" for U and W, "G7X error" for the others.
    auto refuse = [&](char c, const std::string& what, char x = 'x') {
        fail(code::profile_cycle_block, std::string("G7") + x + " error: " + what, w[c].column);
    };
    if (w.has_polar()) fail(code::unsupported_word, "Polar coordinates in a G7x profile are not supported by toolcomp", w.axis_column());
    Point end = inc ? Point(0, 0) : at;
    if (w.has('U')) {
        if (inc) refuse('U', "Cannot use U in incremental mode (G91)");
        if (w.has('X')) refuse('U', "Cannot use U and X in the same block");
        end.imag(end.imag() + w['U'].value * (st_.diameter ? 0.5 : 1.0));
    } else if (w.has('X')) {
        end.imag(axis_value(w, 0));
    }
    if (w.has('W')) {
        if (inc) refuse('W', "Cannot use W in incremental mode (G91)");
        if (w.has('Z')) refuse('W', "Cannot use W and Z in the same block");
        end.real(end.real() + w['W'].value);
    } else if (w.has('Z')) {
        end.real(w['Z'].value);
    }
    if (inc) end += at;
    if (w.g[g_motion] >= 0) mode = w.g[g_motion];
    if (end == at) return;
    const bool straight = mode == G0 || mode == G1, arc = mode == G2 || mode == G3;
    if (straight) pieces.push_back({Piece::line, at, end});
    if (arc) {
        Point centre(w.has('K') ? w['K'].value : 0.0, w.has('I') ? w['I'].value : 0.0);
        if (w.has('R')) {
            if (w.has('I') || w.has('K')) refuse('R', "both R and I or K flag used for arc", 'X');
            const double r = w['R'].value, chord2 = std::norm(end - at);
            if (r * r < chord2 / 4)
                fail(code::profile_cycle_block, "G7x error: the arc's radius R is less than half the distance to its end",
                     w['R'].column);
            const Point d = Point(0, 1) * std::sqrt((r * r - chord2 / 4) / chord2) * (end - at);
            centre = (at + end) / 2.0 + (mode == G3 ? d : -d);
        } else {
            if (!w.has('I') && !w.has('K'))
                fail(code::profile_cycle_block, "G7X error: either I or K must be present for arc", w.g_column[g_motion]);
            if (!st_.arc_absolute) centre += at;
        }
        pieces.push_back({Piece::arc, at, end, centre, mode == G3});
    }
    if (straight || arc) {
        if (w.has('A') && w.has('C')) refuse('C', "Both A and C parameters on a corner", 'X');
        if (w.has('A')) pieces.push_back({Piece::fillet, end, end, end, false, w['A'].value});
        if (w.has('C')) pieces.push_back({Piece::chamfer, end, end, end, false, w['C'].value});
    }
    at = end;
}

// The profile: the subroutine O<q> run from its call to its return, its control statements
// and assignments executed, its other blocks read for their geometry only. The first piece
// is the lead-in from `start`; the motion mode starts as G0 (the cycle's first rapid).
std::vector<Piece> Interp::read_profile(const BlockWords& bw, Point start, int& mode) {
    const WordSlot q = bw['Q'];
    if (!linuxcnc_whole(q.value)) fail(code::non_integer_value, "Non integer value for integer", q.column);
    const std::size_t depth = frames_.size();
    call_o_sub(std::to_string(std::lround(q.value)), {}, q.column);
    std::vector<Piece> pieces;
    mode = 0;
    Point at = start;
    try {
        read_profile_blocks(depth, mode, at, pieces);
    } catch (const Error&) {
        frames_.resize(depth);  // LinuxCNC reports an error of the profile at its line, not at the call
        throw;
    }
    return pieces;
}

void Interp::read_profile_blocks(std::size_t depth, int& mode, Point& at, std::vector<Piece>& pieces) {
    while (frames_.size() > depth) {
        Frame& f = frames_.back();
        const Program& p = f.prog();
        if (f.pc >= p.size()) end_of_file(f);
        const std::size_t k = f.pc++;
        const Block& block = p.blocks()[k];
        if (block.block_delete && opts_.block_delete) continue;
        line_ = block.line;
        file_ = f.at->file;
        count_block();
        block_ = &block;
        if (block.statement_count) {
            if (const Statement* s = control_statement(p, block)) {
                control(*s, k);
                continue;
            }
        }
        const BlockWords w = collect_words(block_words(block), block.line, profile_, opts_.machine, true);
        if (block.statement_count) assignments(block);
        profile_piece(w, mode, at, pieces);
    }
}

// G70 Q [X Z] [D E P], G71 / G72 Q [X Z] [D I R]: a rapid to X Z (the start point), the
// profile, the moves.
void Interp::profile_cycle(const BlockWords& bw, int code) {
    const int col = bw.g_column[g_motion];
    const std::string name = cycle_name(code);
    if (!bw.has('Q')) fail(code::profile_cycle_words, "G7x.x  requires a Q word", col);
    if (comp_on() && code != G70) fail(code::profile_cycle_start, name + " cannot be used with cutter compensation enabled", col);
    if (st_.plane != Plane::zx) fail(code::profile_cycle_start, name + " can only be used in XZ plane (G18)", col);
    if (comp_on())
        fail(code::profile_cycle_start,
             "G70 under cutter radius compensation: LinuxCNC 2.9.0 rapids to a wrong point first, later versions "
             "switch compensation off for the rapids; not supported by toolcomp",
             col);
    if (st_.feed_mode == G93) fail(code::cycle_inverse_time, name + " in inverse time feed (G93): not supported by toolcomp", col);
    // The start point: X / Z (G91: from here). The first rapid goes to the words as absolute
    // coordinates even in G91, as LinuxCNC's does.
    const Vec6 start = find_end(bw);
    const bool incremental = st_.incremental;
    st_.incremental = false;
    const Vec6 first = find_end(bw);
    st_.incremental = incremental;
    straight(MotionKind::rapid, first, std::nan(""));
    int mode = 0;
    std::vector<Piece> pieces = read_profile(bw, Point(start[2], start[0]), mode);  // errors from here: at its end
    if (pieces.size() < 2) {
        st_.motion = mode;
        line_ = bw.line;
        file_ = frames_.back().at->file;
        info(code::profile_cycle_empty, name + ": the profile O" + std::to_string(std::lround(bw['Q'].value)) +
                                            " has no move after the first: LinuxCNC makes only the rapid to the start point",
             col);
        return;
    }
    auto word = [&](char c, double otherwise) { return bw.has(c) ? bw[c].value : otherwise; };
    // At most the blocks still allowed, and 50 million moves (2.4 GB).
    constexpr std::size_t kMaxMoves = 50'000'000;
    const std::size_t max_moves = std::min(kMaxMoves, block_budget());
    std::vector<cycles::Step> steps;
    try {
        if (code == G70) {
            steps = cycles::profile::finish(std::move(pieces), {word('D', 0), word('E', 0), word('P', 1)}, max_moves);
        } else {
            const double depth = word('I', 1);
            if (!(depth > 0)) fail(code::profile_cycle_geometry, "G7X error: I must be greater than zero.");
            steps = cycles::profile::rough(std::move(pieces), {code % 10, code / 10 == 72, word('D', 0), depth, word('R', 0.5)},
                                           max_moves);
        }
    } catch (const cycles::MoveLimit&) {
        line_ = bw.line;
        file_ = frames_.back().at->file;
        if (max_moves < kMaxMoves) block_limit_exceeded(col);
        fail(code::profile_cycle_geometry, "G7X error: more than " + std::to_string(kMaxMoves) + " moves");
    } catch (const cycles::CycleError& e) {
        fail(e.code, e.message);
    }
    line_ = bw.line;  // the cycle's moves are its block's
    file_ = frames_.back().at->file;
    for (const cycles::Step& s : steps) {
        count_block(col);
        Vec6 end = pos_;
        end[2] = s.end.x();
        end[0] = s.end.y();
        if (s.kind == cycles::StepKind::rapid) {
            straight(MotionKind::rapid, end, std::nan(""));
            st_.motion = 0;
        } else if (s.kind == cycles::StepKind::feed) {
            if (feed_ <= 0) fail(code::zero_feed, "Cannot do g1 with zero feed rate", col);
            check_feed_per_rev(col);
            straight(MotionKind::line, end, feed_for(bw, 10, 0, end[0]));
            st_.motion = 10;
        } else {
            if (feed_ <= 0) fail(code::zero_feed, "Cannot make arc with zero feed rate", col);
            check_arc_ends(Vec2(pos_[2], pos_[0]), s.center, s.end, 'Z', 'X');  // as LinuxCNC's arcs of the cycle
            Motion m = motion_to(s.dir > 0 ? MotionKind::arc_ccw : MotionKind::arc_cw, end);
            m.center = pos_.head<3>();
            m.center[2] = s.center.x();
            m.center[0] = s.center.y();
            m.feed = feed_for(bw, 20, 0, end[0]);
            emit(m);
            st_.motion = s.dir > 0 ? 30 : 20;
        }
    }
}

}  // namespace toolcomp::iso
