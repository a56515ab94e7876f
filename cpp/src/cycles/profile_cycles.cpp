#include "profile_cycles.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "profile_geometry.hpp"

namespace toolcomp::cycles::profile {

namespace {

Piece line_piece(Point from, Point to) { return {Piece::line, from, to, {}, false, 0}; }

// The moves, taken in the normal frame and given in the program's.
class Moves {
public:
    Moves(int frame, std::size_t max_moves) : frame_(frame), max_(max_moves) {}
    void rapid(Point p) { push(StepKind::rapid, p); }
    void feed(Point p) { push(StepKind::feed, p); }
    // LinuxCNC leaves out an arc that ends where the tool stands.
    void arc(bool ccw, Point centre, Point end) {
        const Point e = to_program(end);
        if (std::abs(real(e) - real(at_)) < kTol && std::abs(imag(e) - imag(at_)) < kTol) return;
        const bool mirrored = frame_ == 1 || frame_ == 2 || frame_ == 5 || frame_ == 6;
        push(StepKind::arc, end, to_program(centre), ccw != mirrored ? 1 : -1);
    }
    void draw(const Piece& p) {
        if (is_round(p)) arc(p.ccw, p.centre, p.end);
        else feed(p.end);
    }
    std::vector<Step> steps;

private:
    Point to_program(Point p) const {
        switch (frame_) {
            case 1: return -conj(p);
            case 2: return conj(p);
            case 3: return -p;
            case 4: return kI * p;
            case 5: return conj(kI * p);
            case 6: return -conj(kI * p);
            case 7: return -kI * p;
            default: return p;
        }
    }
    void push(StepKind kind, Point end, Point centre = {}, int dir = 0) {
        if (steps.size() >= max_) throw MoveLimit{};
        at_ = to_program(end);
        steps.push_back({kind, Vec2(real(at_), imag(at_)), Vec2(real(centre), imag(centre)), dir, 0});
    }
    int frame_;
    std::size_t max_;
    Point at_{std::nan(""), std::nan("")};
};

// Roughing in the normal frame: levels of constant X from the start point's X down, each cut
// toward -Z from the lead-in (or a pocket's entry wall) to the profile, then the profile.
class Rougher {
public:
    Rougher(std::vector<Piece>& pieces, Moves& out, double depth, double escape)
        : pieces_(pieces), out_(out), delta_(std::max(depth, 2 * kTol)), escape_(escape * Point(1, 1)) {}
    void run(int variant, Point at);

private:
    bool dive(std::size_t p, Point& at, double x);  // false: down along p toward level x
    bool climb(const Piece& p, Point& at);           // true: a pocket starts (or a top was passed)
    void climb_only(const Piece& p, Point& at);      // G7x.1: along the profile, over the pockets
    bool cut_level(std::size_t& p, Point at, double& x);
    double next_level(double x, Point at) const;
    std::vector<Piece>& pieces_;
    Moves& out_;
    double delta_;
    Point escape_;
    std::vector<Point> starts_;  // G7x.2: the top of the pocket being roughed
    std::size_t spins_ = 0;
    std::size_t work_ = 0;  // pieces searched for a level's end: a bound on the time
};

bool Rougher::dive(std::size_t i, Point& at, double x) {
    const Piece& p = pieces_[i];
    const bool fast = i == 0;  // along the lead-in at rapid
    if (!is_round(p)) {
        if (imag(p.start) <= imag(p.end) + kTol) return true;
        Point to = p.end;
        if (x >= imag(p.end)) {
            const Crossings c = crossings(p, x);
            if (c.empty()) geometry_error("x too large in straight dive");
            to = Point(c.front(), x);
        }
        fast ? out_.rapid(to) : out_.feed(to);
        at = to;
        return false;
    }
    if (std::abs(at - p.end) < kTol || real(at - p.end) <= kTol) {
        at = p.end;
        return false;
    }
    Crossings c = crossings(p, x);
    if (c.empty()) c = crossings(p, x - kTol);
    if (p.ccw) {
        if (real(at) - kTol > real(p.centre)) return true;
        const Point to = c.empty() || c.back() > real(p.centre) ? p.end : Point(c.back(), x);
        out_.arc(p.ccw, p.centre, to);
        at = to;
        return false;
    }
    if (real(at) <= real(p.centre)) return true;
    if (!c.empty() && c.front() < real(p.centre)) return false;  // only the far side: the level drops
    const Point to = c.empty() ? p.end : Point(c.front(), x);
    out_.arc(p.ccw, p.centre, to);
    at = to;
    return false;
}

// A counter-clockwise arc is climbed to its top at most, and then always stops the climb.
bool Rougher::climb(const Piece& p, Point& at) {
    if (!is_round(p)) {
        if (imag(p.end) + kTol < imag(p.start)) return true;
        if (std::abs(at - p.start) > kTol) geometry_error("How did we get here?");
        out_.feed(p.end);
        at = p.end;
        return false;
    }
    if (!p.ccw) {
        if (real(at) > real(p.centre)) return true;
        if (std::abs(at - p.end) > kShort) out_.arc(false, p.centre, p.end);
        at = p.end;
        return false;
    }
    if (real(at) < real(p.centre)) return true;
    Point to = p.end;
    if (real(p.end) < real(p.centre)) to = Point(real(p.centre), imag(p.centre) + std::abs(p.start - p.centre));
    if (std::abs(at - to) > kShort) out_.arc(true, p.centre, to);
    at = to;
    return true;
}

void Rougher::climb_only(const Piece& p, Point& at) {
    if (!is_round(p) && imag(p.end) < imag(p.start)) return;
    const Crossings c = crossings(p, imag(at));
    if (c.empty()) return;
    if (!is_round(p)) {
        at.real(c.front());
        out_.feed(at);
        out_.feed(p.end);
        at = p.end;
        return;
    }
    if (!p.ccw ? c.back() > real(p.centre) : c.front() < real(p.centre)) return;
    at.real(!p.ccw ? c.back() : c.front());
    out_.feed(at);
    Point to = p.end;
    if (p.ccw && real(p.end) < real(p.centre))
        to = Point(real(p.centre), imag(p.centre) + std::abs(p.start - p.centre));
    if (std::abs(at - to) > kShort) out_.arc(p.ccw, p.centre, to);
    at = to;
}

// LinuxCNC's levels: subtracted from the top one by one (the same doubles as its loop).
double Rougher::next_level(double x, Point at) const {
    if ((x - imag(at)) / delta_ > 1e7) geometry_error("more than 10 million levels (I is too small)");
    while (x - kTol > imag(at)) x -= delta_;
    return x;
}

// One level at the tool's X, from `at` toward -Z to the first piece it meets: the cut, the
// 45-degree escape, the return over the start of the cut, back down to it. False when the
// level gave no cut and `p` or `x` moved on instead.
bool Rougher::cut_level(std::size_t& p, Point at, double& x) {
    for (std::size_t ip = p; ip < pieces_.size(); ++ip) {
        if (++work_ > 2'000'000'000) geometry_error("more than 2 billion crossings of levels and pieces");
        const Crossings c = crossings(pieces_[ip], imag(at));
        if (c.empty()) continue;
        const double z = ip != p ? c.front() : c.back();
        const double distance = std::abs(z - real(at));
        if (z - kTol > real(at)) continue;  // behind the tool
        if (distance < kTol) {
            if (ip == p) continue;  // the piece it dives along, where it stands
            if (std::abs(at - pieces_[ip].start) < kTol) p = ip;  // the next piece starts here
            else x -= delta_;                                     // nothing to cut at this level
            return false;
        }
        Point to = at;
        to.real(z);
        out_.feed(to);
        const double scale = std::min(1.0, distance / 2 / real(escape_));
        out_.rapid(to + scale * escape_);
        out_.rapid(at - conj(scale * escape_));
        p == 0 ? out_.rapid(at) : out_.feed(at);
        x -= delta_;
        return true;
    }
    return false;
}

// LinuxCNC's pocket(): a call per pocket, each the rest of the one before; as a loop here.
void Rougher::run(int variant, Point at) {
    starts_ = {at};
    std::size_t p = 0;
    for (;;) {
        double x = imag(starts_.back());
        if (variant == 2) {  // no outer levels: down the first descent to its bottom
            while (p < pieces_.size() && !dive(p, at, -1e9)) ++p;
            variant = 3;
        }
        bool pocket = false;
        std::size_t last_p = pieces_.size();  // the turn before's piece, tool and level
        Point last_at = at;
        double last_x = std::numeric_limits<double>::quiet_NaN();
        while (p < pieces_.size() && !pocket) {
            // A turn that leaves the piece, the tool and the level as they were repeats itself
            // for ever (the loop depends on nothing else); the count is the backstop.
            if (++spins_ > 50'000'000 || (p == last_p && at == last_at && x == last_x))
                geometry_error("the cycle does not end: no level is cut from Z" + std::to_string(real(at)) +
                               " (normal frame) and the level does not drop (LinuxCNC loops here forever)");
            last_p = p, last_at = at, last_x = x;
            x = next_level(x, at);
            if (dive(p, at, x)) {  // the profile rises from here
                if (variant == 1) {
                    for (; p < pieces_.size(); ++p) climb_only(pieces_[p], at);
                    return;
                }
                for (; p < pieces_.size() && !pocket; ++p) pocket = climb(pieces_[p], at);
                if (!pocket) return;
                --p;
                if (variant == 3) {
                    if (imag(at) > imag(starts_.back()) && starts_.size() > 1) starts_.pop_back();
                    if (starts_.size() == 1) starts_.push_back(at);
                }
                break;
            }
            // At the last piece the cycle ends (LinuxCNC 2.10; 2.9 can loop here forever).
            if (p + 1 == pieces_.size()) return;
            if (std::abs(imag(at) - x) > kTol || pieces_[p].end == at) {
                ++p;  // this piece is done down to its end
                continue;
            }
            cut_level(p, at, x);
        }
        if (!pocket) return;
    }
}

}  // namespace

std::vector<Step> finish(std::vector<Piece> pieces, const Finishing& f, std::size_t max_moves) {
    // The frame: from the profile without its lead-in; turned as G72's when that alone is
    // not monotonic.
    Profile probe;
    probe.pieces.assign(pieces.begin() + 1, pieces.end());
    probe.normalise();
    if (!std::all_of(probe.pieces.begin(), probe.pieces.end(), monotonic)) {
        probe.turn();
        probe.normalise();
    }
    probe.check_monotonic();
    Profile all;
    all.pieces = std::move(pieces);
    if (probe.frame & 4) all.turn();
    all.normalise();
    all.make_corners();
    all.check_monotonic();
    Moves out(all.frame, max_moves);
    if (!(f.passes < 1e6)) geometry_error("P, the number of passes, above a million");
    for (long pass = f.passes > 0 ? static_cast<long>(f.passes) : 0; pass > 0; --pass) {
        Profile path = all;
        path.add_distance(static_cast<double>(pass - 1) * (f.start_distance - f.end_distance) / f.passes + f.end_distance);
        out.rapid(path.pieces.front().start);
        out.rapid(path.pieces.front().end);
        for (std::size_t i = 1; i < path.pieces.size(); ++i) out.draw(path.pieces[i]);
    }
    return std::move(out.steps);
}

std::vector<Step> rough(std::vector<Piece> pieces, const Roughing& r, std::size_t max_moves) {
    // A profile that ends short of the start point's level gets a piece up (G71) or across
    // (G72) to it.
    const Point start = pieces.front().start, end = pieces.back().end;
    const Point first = pieces.front().end - pieces.front().start, last = pieces.back().end - pieces.back().start;
    if (!r.facing && std::abs(real(last)) > 0 && imag(first) * (imag(start) - imag(end)) < 0)
        pieces.push_back(line_piece(end, Point(real(end), imag(start))));
    if (r.facing && std::abs(imag(last)) > 0 && real(first) * (real(start) - real(end)) < 0)
        pieces.push_back(line_piece(end, Point(real(start), imag(end))));
    Profile prof;
    prof.pieces = std::move(pieces);
    if (r.facing) prof.turn();
    prof.normalise();
    prof.make_corners();
    prof.check_monotonic();
    prof.add_distance(r.allowance);
    std::vector<Piece>& ps = prof.pieces;
    Moves out(prof.frame, max_moves);
    out.rapid(ps.front().start);
    if (imag(ps.back().end) < imag(ps.front().start))
        ps.push_back(line_piece(ps.back().end, Point(real(ps.back().end), imag(ps.front().start))));
    Rougher(ps, out, r.depth, r.escape).run(r.variant, ps.front().start);
    return std::move(out.steps);
}

}  // namespace toolcomp::cycles::profile
