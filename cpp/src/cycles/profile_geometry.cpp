#include "profile_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "toolcomp/program/codes.hpp"

namespace toolcomp::cycles::profile {

void geometry_error(const std::string& what) {
    throw CycleError{code::profile_cycle_geometry, "G7X error: " + what, 0};
}

bool is_round(const Piece& p) { return p.kind == Piece::arc || p.kind == Piece::fillet; }

double extent(const Piece& p) {
    return is_round(p) ? std::min(std::abs(p.start - p.end), std::abs(p.start - p.centre)) : std::abs(p.start - p.end);
}

bool monotonic(const Piece& p) {
    if (p.kind == Piece::fillet && p.size != 0) return true;  // a fillet still to be made
    if (!is_round(p)) return real(p.end - p.start) <= kShort;
    const double entry = imag(p.start - p.centre), exit = imag(p.end - p.centre), dz = real(p.end - p.start);
    if (p.ccw) return entry >= -kShort && exit >= -kShort && dz <= -kShort;
    return entry <= kShort && exit <= kShort && dz <= -kShort;
}

void offset(Piece& p, double d) {
    if (is_round(p)) {
        const double r = std::abs(p.start - p.centre);
        const double k = (r + (p.ccw ? d : -d)) / r;
        p.start = k * (p.start - p.centre) + p.centre;
        p.end = k * (p.end - p.centre) + p.centre;
    } else {
        const Point v = kI * d * (p.start - p.end) / std::abs(p.start - p.end);
        p.start += v;
        p.end += v;
    }
}

namespace {

// On the arc from its start to its end, in its direction (within the tolerance).
bool on_arc(const Piece& a, Point q) {
    const double from_start = imag(conj(a.start - a.centre) * (q - a.centre));
    const double to_end = imag(conj(a.end - a.centre) * (q - a.centre));
    return a.ccw ? from_start >= -kTol && to_end <= kTol : from_start <= kTol && to_end >= -kTol;
}

// The point where a line (through `from` toward `to`) meets the circle about `centre`
// through `on`, nearest to `near`.
Point line_meets_circle(Point from, Point to, Point centre, Point on, Point near) {
    const Point rot = conj(to - from) / std::abs(to - from);
    const Point pe = (on - from) * rot, pc = (centre - from) * rot;
    double b = std::norm(pc - pe) - imag(pc) * imag(pc);
    b = b < 0 ? 0 : std::sqrt(b);
    const Point s1 = (real(pc) + b) / rot + from, s2 = (real(pc) - b) / rot + from;
    return std::abs(near - s1) < std::abs(near - s2) ? s1 : s2;
}

}  // namespace

Crossings crossings(const Piece& p, double x) {
    Crossings c;
    if (is_round(p)) {
        const double r = std::abs(p.start - p.centre);
        double s = -(x - r - imag(p.centre)) * (x + r - imag(p.centre));
        if (s < -kTol) return c;
        s = std::sqrt(s < 0 ? 0 : s);
        for (double z : {real(p.centre) + s, real(p.centre) - s})
            if (on_arc(p, Point(z, x))) c.z[c.n++] = z;
        return c;
    }
    if (std::min(imag(p.start), imag(p.end)) > x + kTol || std::max(imag(p.start), imag(p.end)) < x - kTol) return c;
    if (std::abs(imag(p.start - p.end)) < kTol) {
        c.z[c.n++] = real(p.start);
        c.z[c.n++] = real(p.end);
    } else {
        c.z[c.n++] = (x - imag(p.start)) / (imag(p.end) - imag(p.start)) * (real(p.end) - real(p.start)) + real(p.start);
    }
    return c;
}

void intersect(Piece& a, Piece& b) {
    Point q;
    if (!is_round(a) && !is_round(b)) {  // two lines: where their lines cross, in b's frame
        const Point rot = conj(b.start - b.end) / std::abs(b.start - b.end);
        const Point ps = (a.start - b.end) * rot, pe = (a.end - b.end) * rot;
        if (imag(ps - pe) == 0) geometry_error("Cannot intersect parallel lines");
        const double f = imag(ps) / imag(ps - pe);
        q = (ps + f * (pe - ps)) / rot + b.end;
    } else if (!is_round(b)) {  // arc, then line
        if (std::abs(b.start - a.end) < kTol) return;
        q = line_meets_circle(b.end, b.start, a.centre, a.end, b.start);
    } else if (!is_round(a)) {  // line, then arc
        if (std::abs(b.start - a.end) < kTol) return;
        q = line_meets_circle(a.end, a.start, b.centre, b.end, b.start);
    } else {  // two arcs: the crossing of their circles on the counter-clockwise side
        const double ra = std::abs(b.start - b.centre), rb = std::abs(a.start - a.centre);
        const double c = std::abs(b.centre - a.centre);
        const double cos_b = (c * c + ra * ra - rb * rb) / 2.0 / ra / c;
        const double cos2 = std::min(cos_b * cos_b, 1.0);
        q = Point(cos_b, std::sqrt(1 - cos2)) * (a.centre - b.centre) / c * ra + b.centre;
    }
    a.end = b.start = q;
}

void Profile::turn() {
    for (Piece& p : pieces) {
        p.start = -p.start * kI;
        p.end = -p.end * kI;
        p.centre = -p.centre * kI;
    }
    frame ^= 4;
}

void Profile::normalise() {
    const Point dir = pieces.front().end - pieces.back().end;
    if (imag(dir) > 0) {
        for (Piece& p : pieces) {
            p.start = conj(p.start), p.end = conj(p.end), p.centre = conj(p.centre);
            p.ccw = !p.ccw;
        }
        frame ^= 2;
    }
    if (real(dir) < 0) {
        for (Piece& p : pieces) {
            p.start = -conj(p.start), p.end = -conj(p.end), p.centre = -conj(p.centre);
            p.ccw = !p.ccw;
        }
        frame ^= 1;
    }
}

namespace {

// A fillet or chamfer h between prev and next: both offset by its size (to the other side
// when that opens the corner), where they meet is the fillet's centre, and offset back the
// pieces end at its tangent points.
Point make_corner(Piece& h, Piece& prev, Piece& next) {
    auto shifted = [&](double d) {
        Piece p = prev, n = next;
        offset(p, d);
        offset(n, d);
        return std::pair{p, n};
    };
    auto [p, n] = shifted(h.size);
    if (real(p.end - n.start) > kGap) {
        h.size = -h.size;
        std::tie(p, n) = shifted(h.size);
    }
    if (real(p.end - n.start) > kGap) {
        char at[80];
        std::snprintf(at, sizeof at, "(%g,%g)", real(prev.end), imag(prev.end));
        geometry_error(std::string("Corner finish failed at ") + at);
    }
    intersect(p, n);
    const Point centre = (p.end + n.start) / 2.0;
    offset(p, -h.size);
    offset(n, -h.size);
    h.start = prev.end = p.end;
    h.end = next.start = n.start;
    return centre;
}

}  // namespace

void Profile::make_corners() {
    for (std::size_t h = 1; h + 1 < pieces.size(); ++h) {
        Piece& c = pieces[h];
        if (c.kind == Piece::fillet) {
            c.centre = make_corner(c, pieces[h - 1], pieces[h + 1]);
            c.ccw = imag(c.start - c.centre) > 0 || imag(c.end - c.centre) > 0;
            c.kind = Piece::arc;
            c.size = 0;
        } else if (c.kind == Piece::chamfer) {
            make_corner(c, pieces[h - 1], pieces[h + 1]);
            c.kind = Piece::line;
        }
    }
    std::erase_if(pieces, [](const Piece& p) { return extent(p) < kShort; });
    if (pieces.empty()) geometry_error("the profile has no piece longer than 0.001");
}

void Profile::check_monotonic() {
    Piece& lead = pieces.front();
    if (real(lead.end - lead.start) > 0) lead.start.real(real(lead.end));
    for (const Piece& p : pieces)
        if (!monotonic(p)) geometry_error("Not monotonic");
}

// Offset in steps of at most half the shortest piece: after each, the pieces that vanished
// drop out, the corners that opened get an arc about the corner before the step, pieces
// that turned back drop out, and the neighbours are trimmed to meet.
void Profile::add_distance(double distance) {
    const Point v1 = pieces.front().end - pieces.front().start, v2 = pieces.back().start - pieces.front().start;
    if (imag(v1 / v2) < 0) distance = -distance;
    const Piece lead = pieces.front();
    pieces.erase(pieces.begin());
    double done = 0;
    std::size_t work = 0;  // pieces offset so far: a bound on the time a fine profile takes
    for (int round = 0; done != distance; ++round) {
        if (pieces.empty() || round > 100000) geometry_error("the profile vanishes at an offset of " + std::to_string(distance));
        if ((work += pieces.size()) > 200'000'000)
            geometry_error("the profile is too fine for an offset of " + std::to_string(distance) +
                           ": more than 200 million piece offsets");
        double step = 1e9;
        for (const Piece& p : pieces) step = std::min(step, extent(p) / 2);
        step = std::min(step, std::abs(distance - done));
        if (distance < 0) step = -step;
        for (std::size_t i = 0; i < pieces.size();) {
            offset(pieces[i], step);
            if (extent(pieces[i]) < kShort) pieces.erase(pieces.begin() + static_cast<std::ptrdiff_t>(i));
            else ++i;
        }
        for (std::size_t i = 0; i + 1 < pieces.size(); ++i) {
            if (real(pieces[i].end - pieces[i + 1].start) <= kGap) continue;
            Piece a = pieces[i], b = pieces[i + 1];
            offset(a, -step);
            offset(b, -step);
            Piece joint{Piece::arc, pieces[i].end, pieces[i + 1].start, (a.end + b.start) / 2.0, distance > 0, 0};
            pieces.insert(pieces.begin() + static_cast<std::ptrdiff_t>(i + 1), joint);
            ++i;
        }
        for (std::size_t i = 0; i + 1 < pieces.size(); ++i) {
            if (!monotonic(pieces[i])) {  // turned back: the shorter of it and the one before goes
                const std::size_t gone = i == 0 || extent(pieces[i]) < extent(pieces[i - 1]) ? i : i - 1;
                pieces.erase(pieces.begin() + static_cast<std::ptrdiff_t>(gone));
                i = 0;
                if (pieces.size() < 2) break;
            }
            if (extent(pieces[i]) < kShort) {
                pieces.erase(pieces.begin() + static_cast<std::ptrdiff_t>(i));
                i = 0;  // the walk goes on from the second piece
                continue;
            }
            intersect(pieces[i], pieces[i + 1]);
        }
        done += step;
    }
    for (std::size_t i = 0; i + 1 < pieces.size(); ++i) {
        const Point mid = (pieces[i].end + pieces[i + 1].start) / 2.0;
        pieces[i].end = pieces[i + 1].start = mid;
    }
    if (pieces.empty()) geometry_error("the profile vanishes at an offset of " + std::to_string(distance));
    Piece in = lead;
    in.end = pieces.front().start;
    pieces.insert(pieces.begin(), in);
}

}  // namespace toolcomp::cycles::profile
