// LinuxCNC's splines (profile.splines): G5 cubic and G5.1 quadratic B-splines, G5.2 / G5.3
// NURBS, as LinuxCNC 2.9 runs them. The interpreter turns each curve into control points and
// an order (interp_convert.cc: convert_spline, convert_nurbs); the machine's task turns those
// into 4 spans per control point, each a biarc: two arcs, or a line where an arc is flat
// (emccanon.cc: NURBS_FEED, biarc, arc). toolcomp follows both step by step, so the arcs are
// the machine's (its preview draws 15 lines per control point instead).
//   * G5 X Y I J P Q: start, start + (I, J), end + (P, Q), end; without I J the last G5's
//     -P -Q (the curve goes on tangent); G5.1 X Y I J: start, start + (I, J), end;
//   * G5 and G5.1 leave the motion mode as it was; G5.2 X Y P [L] adds control points (P the
//     weight, L the order), G5.3 ends the curve and leaves no motion mode;
//   * a span the machine's biarc cannot fit (a straight piece of the curve: LinuxCNC emits
//     NaN or leaves the span out) is refused, as is a NURBS under cutter radius compensation
//     (LinuxCNC does not compensate it and breaks the path).
#include <cmath>
#include <vector>

#include "interp.hpp"
#include "toolcomp/program/codes.hpp"

namespace toolcomp::iso {

namespace {

using Knots = std::vector<unsigned>;
constexpr unsigned kMaxNurbsOrder = 16;
constexpr std::size_t kMaxNurbsPoints = 5000;

// Clamped uniform integer knots of n + 1 points of order k.
Knots knots(unsigned n, unsigned k) {
    Knots v;
    for (unsigned i = 0; i <= n + k; ++i) v.push_back(i < k ? 0 : i <= n ? i - k + 1 : n - k + 2);
    return v;
}

// Cox-de Boor, LinuxCNC's (a closed interval at order 1, a term over an empty span dropped).
// Zero outside [knot i, knot i + k]: not worked out there (its terms would all be 0).
double basis(unsigned i, unsigned k, double u, const Knots& kv) {
    if (u < kv[i] || u > kv[i + k]) return 0;
    if (k == 1) return u >= kv[i] && u <= kv[i + 1] ? 1 : 0;
    const unsigned d1 = kv[i + k - 1] - kv[i], d2 = kv[i + k] - kv[i + 1];
    if (d1 == 0 && d2 != 0) return ((kv[i + k] - u) * basis(i + 1, k - 1, u, kv)) / d2;
    if (d2 == 0 && d1 != 0) return ((u - kv[i]) * basis(i, k - 1, u, kv)) / d1;
    if (d1 == 0 && d2 == 0) return 0;
    return ((u - kv[i]) * basis(i, k - 1, u, kv)) / d1 + ((kv[i + k] - u) * basis(i + 1, k - 1, u, kv)) / d2;
}

struct ControlPoint {
    double x, y, w;
};

Vec2 point(double u, unsigned k, const std::vector<ControlPoint>& cps, const Knots& kv) {
    double den = 0;
    for (unsigned i = 0; i < cps.size(); ++i) den = den + basis(i, k, u, kv) * cps[i].w;
    Vec2 p(0, 0);
    for (unsigned i = 0; i < cps.size(); ++i) {
        const double n = basis(i, k, u, kv);
        p.x() = p.x() + cps[i].x * n * cps[i].w / den;
        p.y() = p.y() + cps[i].y * n * cps[i].w / den;
    }
    return p;
}

Vec2 unit(Vec2 v) {
    const double h = std::hypot(v.x(), v.y());
    if (h != 0) v /= h;
    return v;
}

Vec2 tangent(double u, unsigned k, const std::vector<ControlPoint>& cps, const Knots& kv) {
    const double umax = static_cast<double>(static_cast<unsigned>(cps.size() - 1) - k + 2);
    const double lo = std::max(0.0, u - 1e-5), hi = std::min(umax, u + 1e-5);
    const Vec2 a = point(lo, k, cps, kv), b = point(hi, k, cps, kv);
    return unit(Vec2((b.x() - a.x()) / (hi - lo), (b.y() - a.y()) / (hi - lo)));
}

}  // namespace

// One arc (or line) of a biarc, from `from` (where the tool is) to `to`, leaving along `d`.
void Interp::spline_arc(const Vec2& from, const Vec2& to, const Vec2& d) {
    const double x = to.x() - from.x(), y = to.y() - from.y();
    const double den = 2 * (y * d.x() - x * d.y());
    Vec6 end = pos_;
    end[0] = to.x();
    end[1] = to.y();
    if (std::fabs(den) > 0.000001) {
        const double r = -(x * x + y * y) / den;
        Motion m = motion_to(r < 0 ? MotionKind::arc_ccw : MotionKind::arc_cw, end);
        m.center = Vec3(from.x() + d.y() * r, from.y() + -d.x() * r, pos_[2]);
        m.feed = feed_;
        emit(m);
    } else {
        straight(MotionKind::line, end, feed_);
    }
}

// LinuxCNC's NURBS_FEED: 4 spans per control point, a biarc each.
void Interp::nurbs_feed(const std::vector<std::array<double, 3>>& points, unsigned k, int col) {
    std::vector<ControlPoint> cps;
    for (const auto& p : points) cps.push_back({p[0], p[1], p[2]});
    const unsigned n = static_cast<unsigned>(cps.size() - 1);
    const double umax = static_cast<double>(n - k + 2);
    const unsigned div = static_cast<unsigned>(cps.size()) * 4;
    const Knots kv = knots(n, k);
    Vec2 p0 = point(0, k, cps, kv), t0 = tangent(0, k, cps, kv);
    for (unsigned i = 1; i <= div; ++i) {
        const double u = umax * i / div;
        const Vec2 p4 = point(u, k, cps, kv), t4 = tangent(u, k, cps, kv);
        // biarc(p0, t0, p4, t4), r = 1
        const Vec2 ts = unit(t0), te = unit(t4);
        const double vx = p0.x() - p4.x(), vy = p0.y() - p4.y();
        const double c = vx * vx + vy * vy;
        const double b = 2 * (vx * (1.0 * ts.x() + te.x()) + vy * (1.0 * ts.y() + te.y()));
        const double a = 2 * 1.0 * (ts.x() * te.x() + ts.y() * te.y() - 1);
        const double disc = b * b - 4 * a * c;
        const double root = std::sqrt(disc);
        const double beta1 = (-b - root) / 2 / a, beta2 = (-b + root) / 2 / a;
        const double beta = beta1 < beta2 ? beta2 : beta1;
        if (disc < 0 || (beta1 > 0 && beta2 > 0) || !std::isfinite(beta))
            fail(code::spline_degenerate,
                 "A straight piece of a spline: LinuxCNC's biarcs cannot follow it (the machine moves to NaN or leaves "
                 "the piece out); not supported by toolcomp",
                 col);
        const double alpha = beta * 1.0, ab = alpha + beta;
        const Vec2 p1(p0.x() + alpha * ts.x(), p0.y() + alpha * ts.y());
        const Vec2 p3(p4.x() - beta * te.x(), p4.y() - beta * te.y());
        const Vec2 p2((p1.x() * beta + p3.x() * alpha) / ab, (p1.y() * beta + p3.y() * alpha) / ab);
        spline_arc(p0, p2, ts);
        spline_arc(p2, p4, unit(Vec2(p3.x() - p2.x(), p3.y() - p2.y())));
        p0 = p4;
        t0 = t4;
    }
}

void Interp::spline(const BlockWords& bw, int code) {
    const int col = bw.g[g_motion] >= 0 ? bw.g_column[g_motion] : bw.axis_column();
    auto bad = [&](const char* msg) { fail(code::spline_words, msg, col); };
    st_.motion = prev_motion_;  // G5 and G5.1 leave the motion mode as it was
    if (comp_on()) bad("Cannot convert spline with cutter radius compensation");
    if (st_.feed_mode != G93 && feed_ == 0) bad("Cannot make arc with zero feed rate");
    if (st_.feed_mode == G93 && !bw.has('F')) bad("F word missing with inverse time arc move");
    if (st_.plane != Plane::xy) bad("Splines must be in the XY plane");
    if (bw.has('Z') || bw.has('A') || bw.has('B') || bw.has('C')) bad("Splines may not have motion in Z, A, B, or C");
    const bool i = bw.has('I'), j = bw.has('J');
    if (code == G5_1 && !(i && j)) bad("Must specify both I and J with G5.1");
    if (code == G5 && i != j) bad("Must specify both I and J, or neither");
    const Vec6 end = find_end(bw);
    if (code == G5 && !(bw.has('P') && bw.has('Q'))) bad("Must specify both P and Q with G5");
    if (!nurbs_points_.empty())
        fail(code::spline_words,
             "G5 or G5.1 after G5.2 control points that no G5.3 ended: LinuxCNC puts them before the spline's; not "
             "supported by toolcomp",
             col);
    const double sx = pos_[0], sy = pos_[1];
    std::vector<std::array<double, 3>> cps{{sx, sy, 1}};
    if (code == G5) {
        const double ci = i ? bw['I'].value : cyc_.i, cj = j ? bw['J'].value : cyc_.j;
        cps.push_back({sx + ci, sy + cj, 1});
        cps.push_back({end[0] + bw['P'].value, end[1] + bw['Q'].value, 1});
        cyc_.i = -bw['P'].value;  // the next G5 without I J goes on tangent (shared with G87)
        cyc_.j = -bw['Q'].value;
    } else {
        cps.push_back({sx + bw['I'].value, sy + bw['J'].value, 1});
    }
    cps.push_back({end[0], end[1], 1});
    nurbs_feed(cps, code == G5 ? 4 : 3, col);
    pos_[0] = end[0];
    pos_[1] = end[1];
}

void Interp::nurbs_point(const BlockWords& bw) {
    const int col = bw.g[g_motion] >= 0 ? bw.g_column[g_motion] : bw.axis_column();
    auto bad = [&](const char* msg) { fail(code::spline_words, msg, col); };
    if (comp_on())
        fail(code::spline_words,
             "G5.2 with cutter radius compensation on is not supported by toolcomp (LinuxCNC leaves the curve "
             "uncompensated and breaks the path)",
             col);
    const bool x = bw.has('X'), y = bw.has('Y'), p = bw.has('P');
    const double w = p ? bw['P'].value : -1;
    if (x != y) bad("You must specify both X and Y coordinates for Control Points");
    if (x && !p)
        fail(code::spline_words,
             "G5.2 X Y without its weight P: LinuxCNC 2.9 takes -1 (its manual says 1); not supported by toolcomp: "
             "give P",
             col);
    if (!x && p && w > 0 && !nurbs_points_.empty()) bad("Can specify P without X and Y only for the first control point");
    if (w <= 0 && !nurbs_points_.empty()) bad("Must specify positive weight P for every Control Point");
    if (st_.feed_mode != G93 && feed_ == 0) bad("Cannot make a NURBS with 0 feedrate");
    if (prev_motion_ != G5_2) nurbs_points_.clear();
    if (nurbs_points_.empty()) {
        nurbs_points_.push_back({pos_[0], pos_[1], p && w > 0 && !x && !y ? w : 1.0});
        nurbs_order_ = 3;
    }
    if (bw.has('L') && bw['L'].value > 3) nurbs_order_ = static_cast<unsigned>(int_value(bw['L'].value));
    if (x && y) {
        const Vec6 e = find_end(bw);  // G91: from the curve's start (the point does not move)
        nurbs_points_.push_back({e[0], e[1], w});
    }
}

void Interp::nurbs_end(const BlockWords& bw) {
    const int col = bw.g_column[g_nonmodal];
    if (bw.g[g_motion] >= 0 && bw.g[g_motion] != G5_2)
        fail(code::spline_words, "Between G5.2 and G5.3 codes, only additional G5.2 codes are allowed.", col);
    if (st_.motion != G5_2) fail(code::spline_words, "Cannot use G5.3 without G5.2 first", col);
    // The basis takes 2^order steps, a curve 12 n^2 of them: bounds that no real curve reaches.
    if (nurbs_order_ > kMaxNurbsOrder || nurbs_points_.size() > kMaxNurbsPoints)
        fail(code::spline_words,
             "A NURBS of order " + std::to_string(nurbs_order_) + " with " + std::to_string(nurbs_points_.size()) +
                 " control points: toolcomp takes orders up to " + std::to_string(kMaxNurbsOrder) + " and up to " +
                 std::to_string(kMaxNurbsPoints) + " points",
             col);
    if (nurbs_points_.size() < nurbs_order_)
        fail(code::spline_words,
             "You must specify a number of control points at least equal to the order L = " + std::to_string(nurbs_order_),
             col);
    const auto cps = std::move(nurbs_points_);
    nurbs_points_.clear();
    nurbs_feed(cps, nurbs_order_, col);
    pos_[0] = cps.back()[0];
    pos_[1] = cps.back()[1];
    st_.motion = 800;  // no motion mode: axis words alone are an error now
}

}  // namespace toolcomp::iso
