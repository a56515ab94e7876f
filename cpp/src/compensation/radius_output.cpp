// Held moves, the gouge check when a held move's end is pulled back, the profile's reaction
// to an unreachable element (error, skip with look-ahead, report), and the output window.
#include <cmath>
#include <cstdio>
#include <string>

#include "radius_math.hpp"
#include "toolcomp/compensation/radius.hpp"
#include "toolcomp/program/codes.hpp"

namespace toolcomp {

using namespace radius_math;

void RadiusCompensation::warn(const char* code, const std::string& msg, int line) {
    diags_.push_back({code, Severity::warning, msg, {line, 0, {}, file_of(line)}});
}

namespace {
// Where a move starts that follows one ending at `end` with offset `end_offset`: in program
// coordinates a new tool length offset moves that point.
Vec3 start_after(const Vec3& end, const Vec3& end_offset, const Motion& m) { return end + end_offset - m.tool_offset; }
}  // namespace

RadiusCompensation::Held& RadiusCompensation::hold(const Motion& m, const Vec2& dir, double sweep) {
    return queue_.emplace_back(m, dir, sweep);
}

// The overcut watch sees the programmed plane elements under compensation (not the entry
// move: the contour starts at its end) and the tool-centre moves as they leave the stage.
void RadiusCompensation::watch_programmed(const Element2& e, int line) { overcut_.programmed(e, line); }

void RadiusCompensation::watch_released(const Motion& m, bool approach, std::size_t settled) {
    if (approach || m.radius.side == 0) return;
    const Vec2 s = plane2(m.start), x = plane2(m.end);
    const Element2 el = m.is_arc() ? Element2::arc(s, x, plane2(m.center), m.kind == MotionKind::arc_ccw ? 1 : -1, m.turns)
                                   : Element2::line(s, x);
    overcut_.compensated(el, m.line, m.file, m.radius.radius, settled);
}

// A held move leaves the queue (which flush() clears after): its start follows the last
// emitted end. Without a look-ahead and with nothing waiting it goes straight out, changed
// in place; else it waits in the window until release() lets it go.
void RadiusCompensation::emit(Held& h) {
    Motion& m = h.m;
    const std::size_t settled = overcut_.contour_count();  // its neighbours are counted from here
    if (have_last_) m.start = start_after(last_, last_off_, m);
    if (m.is_arc()) m.center[axes(m.plane).c] = m.start[axes(m.plane).c];
    last_ = m.end;
    last_off_ = m.tool_offset;
    have_last_ = true;
    const std::size_t keep =
        gouge_ == GougeReaction::skip || lookahead_ > 0 ? static_cast<std::size_t>(std::max(0, lookahead() - 1)) : 0;
    if (keep == 0 && window_.empty()) {
        send(m, h.approach, settled);
        overcut_.report(diags_, unit_, /*all=*/false);
        return;
    }
    Emitted& e = window_.emplace_back(h);  // made in place: one copy
    e.settled = settled;
    e.in_plane = !m.generated && (plane2(m.end) - plane2(m.start)).squaredNorm() > tol::length * tol::length;
    release(keep);
}

// Sends the oldest emitted moves downstream until at most `keep` plane moves stay for the
// look-ahead.
void RadiusCompensation::release(std::size_t keep) {
    std::size_t in_plane = 0;
    for (const auto& e : window_) in_plane += e.in_plane;
    std::size_t n = 0;
    while (n < window_.size() && in_plane > keep) in_plane -= window_[n++].in_plane;
    if (keep == 0) n = window_.size();
    for (std::size_t i = 0; i < n; ++i) send(window_[i].m, window_[i].approach, window_[i].settled);
    window_.pop_front(n);
    overcut_.report(diags_, unit_, /*all=*/false);
}

// One move downstream, changed in place (it leaves the stage). Lathe tools: the controlled
// point is the imaginary tip, the nose centre shifted by the nose radius toward the tip (only
// in the ZX plane; numbering per profile).
void RadiusCompensation::send(Motion& m, bool approach, std::size_t settled) {
    if (refused_) return;  // a stage after this one refused a move: nothing goes out any more
    watch_released(m, approach, settled);
    const double r = m.radius.radius;
    if (m.plane == Plane::zx && r > 0 && m.radius.orientation != 0) {
        const TipVector tip = tip_vector(m.radius.orientation, profile_.radius.tip_convention);
        if (tip.x || tip.z) {
            const Vec3 shift(tip.x * r, 0, tip.z * r);
            m.end += shift;
            if (m.is_arc()) m.center += shift;
        }
    }
    if (have_out_) m.start = start_after(last_out_, last_out_off_, m);
    // A generated link of zero length (an activation that already stands at the contour's
    // equidistant, as after APPR) is not a move.
    if (m.generated && m.kind == MotionKind::line && !m.is_arc() && have_out_ && (m.end - m.start).norm() < 1e-12 &&
        m.radius.side != 0 && m.radius.orientation == 0)
        return;
    if (m.is_arc()) m.center[axes(m.plane).c] = m.start[axes(m.plane).c];
    last_out_ = m.end;
    last_out_off_ = m.tool_offset;
    have_out_ = true;
    try {
        out_.push(m);
    } catch (...) {
        // A stage or Path after this one refused the move: the path ends before it. Nothing
        // held or waiting goes out any more (a lenient run's finish() would send the moves
        // again, this one changed in place already). The held moves stay where they are: the
        // loops over them that led here end with the exception.
        refused_ = true;
        throw;
    }
}

void RadiusCompensation::passthrough(const Motion& m) {
    release(0);
    if (refused_) return;
    Motion o = m;
    // The exit move runs from the last compensated point to the programmed target.
    if (exit_pending_ && have_out_) o.start = start_after(last_out_, last_out_off_, o);
    exit_pending_ = false;
    last_out_ = last_ = o.end;
    last_out_off_ = last_off_ = o.tool_offset;
    have_out_ = true;
    have_last_ = true;
    out_.push(o);
}

void RadiusCompensation::flush() {
    for (auto& h : queue_) emit(h);
    queue_.clear();
    endpoint_valid_ = false;
}

void RadiusCompensation::move_end_and_flush(const Vec2& x, int line, bool check, const Element2* next) {
    if (queue_.empty()) return;
    const RadiusRules& rules = profile_.radius;
    // Would any held move run backwards (or sweep further) with this end point?
    const std::string* gouge = nullptr;
    for (const auto& h : queue_) {
        const Motion& m = h.m;
        if (m.is_arc()) {
            const Vec2 c = plane2(m.center);
            const double r1 = dist(plane2(m.end), c), r2 = dist(x, c);  // program units
            if (std::fabs(r1 - r2) > 0.01) {
                char buf[256];
                std::snprintf(buf, sizeof buf, rules.messages.arc_mismatch.c_str(), r1, r2);
                fail(code::comp_invalid_arc, buf, line);
            }
            if (check && !gouge && h.sweep != 0 && endpoint_valid_ &&
                std::fabs(find_turn(endpoint_, c, turn_of(m), x)) >
                    std::fabs(h.sweep) + rules.arc_sweep_tolerance[m.inch() ? 1 : 0])
                gouge = &rules.messages.gouge_arc;
        } else if (check && !gouge && endpoint_valid_ && h.dir.dot(x - endpoint_) < 0) {
            gouge = m.kind == MotionKind::rapid ? &rules.messages.gouge_traverse : &rules.messages.gouge_feed;
        }
    }
    if (gouge) {
        const int held_line = queue_.front().m.line;
        switch (reaction()) {
            case GougeReaction::error:
                fail(code::comp_gouge, *gouge, line);
            case GougeReaction::skip:
                if (next && skip_unreachable(*next, line)) return;
                fail(code::comp_gouge, *gouge, line);
            case GougeReaction::report:
                warn(code::comp_gouge,
                     *gouge + " (the move of line " + std::to_string(held_line) + ", at line " + std::to_string(line) +
                         ")",
                     line);
                break;
        }
    }
    for (auto& h : queue_) h.m.end = with_plane(h.m.end, x);
    flush();
    endpoint_ = x;
    endpoint_valid_ = true;
}

void RadiusCompensation::no_intersection(const Element2& next, int line, const std::string& msg) {
    switch (reaction()) {
        case GougeReaction::error:
            fail(code::comp_gouge, msg, line);
        case GougeReaction::skip:
            if (skip_unreachable(next, line)) return;
            fail(code::comp_gouge, msg, line);
        case GougeReaction::report:
            warn(code::comp_gouge, msg + " (at line " + std::to_string(line) + "; the previous move keeps its end)", line);
            move_end_and_flush(plane2(current_), line, false);
            return;
    }
}

// The held plane move cannot be reached: leave it out (and any corner pieces after the
// moves before it) and join the newest emitted plane move that the next element's
// equidistant crosses, looking back at most `lookahead` plane moves.
bool RadiusCompensation::skip_unreachable(const Element2& next, int line) {
    const int lookahead = std::max(1, this->lookahead());
    int looked = 0;
    std::string skipped = std::to_string(queue_.front().m.line);
    for (std::size_t k = window_.size(); k-- > 0;) {
        const Emitted& w = window_[k];
        const Vec2 s = plane2(w.m.start), e = plane2(w.m.end);
        // Programmed moves count against the look-ahead; corner pieces between them are
        // part of the tool's path too and may be where the next element is met.
        if (!w.in_plane && !(w.m.generated && (e - s).norm() > tol::length)) continue;
        if (w.in_plane) {
            if (looked == lookahead - 1) break;
            ++looked;
        }
        Element2 elem = w.m.is_arc() ? Element2::arc(s, e, plane2(w.m.center), w.m.kind == MotionKind::arc_ccw ? 1 : -1)
                                     : Element2::line(s, e);
        auto xs = intersect(elem, next);
        bool found = false;
        Vec2 x = Vec2::Zero();
        for (const Vec2& cand : xs) {
            // The joined move must keep its direction (lines) or not sweep further (arcs).
            bool ok = w.m.is_arc() ? std::fabs(find_turn(s, plane2(w.m.center), turn_of(w.m), cand)) <=
                                         std::fabs(w.sweep == 0 ? elem.sweep() : w.sweep) +
                                             profile_.radius.arc_sweep_tolerance[w.m.inch() ? 1 : 0]
                                   : w.dir.dot(cand - s) > 0 && (e - cand).dot(e - s) >= -tol::length;
            // A joined line is cut back, never extended past its end into what was left out,
            // and the next element must still run forwards from the join (lines).
            if (!next.is_arc && (next.p1 - cand).dot(next.p1 - next.p0) <= 0) ok = false;
            if (ok && (!found || (cand - e).norm() < (x - e).norm())) {
                x = cand;
                found = true;
            }
        }
        if (!found) {
            if (w.in_plane) skipped = std::to_string(w.m.line) + ", " + skipped;
            continue;
        }
        // Join at x: everything after w goes, the held moves without plane motion stay there.
        window_[k].m.end = with_plane(window_[k].m.end, x);
        window_.truncate(k + 1);
        last_ = window_[k].m.end;
        last_off_ = window_[k].m.tool_offset;
        std::vector<Held> keep;
        for (std::size_t i = 1; i < queue_.size(); ++i) {
            Held h = queue_[i];
            h.m.end = with_plane(h.m.end, x);
            keep.push_back(h);
        }
        queue_ = std::move(keep);
        warn(code::comp_skipped,
             "Elements of line(s) " + skipped + " cannot be reached by the tool and are left out (at line " +
                 std::to_string(line) + ")",
             line);
        flush();
        endpoint_ = x;
        endpoint_valid_ = true;
        return true;
    }
    return false;
}

}  // namespace toolcomp
