#include "turning_roughing.hpp"

#include <cmath>

#include "contour_math.hpp"
#include "toolcomp/program/codes.hpp"

namespace toolcomp::cycles {

namespace {
constexpr double kEps = kContourEps;

// Type I: from `from`, along the piece, u moves only in du and v only in dv (or stands).
void check_monotonic(const Vec2& from, const ContourPiece& p, double du, double dv) {
    if ((p.end.x() - from.x()) * du < -kEps || (p.end.y() - from.y()) * dv < -kEps) not_monotonic(p.line);
    if (p.dir == 0) return;
    // An arc turns back in u or v where it passes an extreme of its circle (angles 0, 90,
    // 180, 270 degrees) between its ends.
    const double a0 = angle_of(from, p.center), sweep = swept(a0, angle_of(p.end, p.center), p.dir);
    const double r = (from - p.center).norm();
    for (int k = 0; k < 4; ++k) {
        const double s = swept(a0, k * kPi / 2, p.dir);
        if (s * r > kEps && (sweep - s) * r > kEps) not_monotonic(p.line);
    }
    if (sweep * r <= kEps) not_monotonic(p.line);  // a whole circle
}

// Where a pass at v = level meets the contour: the u where the contour first rises beyond
// the level (h < 0: on the start's side of it); the contour's last u if it never does.
double meet(const Contour& c, double level, double dv) {
    auto h = [&](const Vec2& p) { return (p.y() - level) * dv; };
    Vec2 from = c.start;
    for (const ContourPiece& p : c.pieces) {
        if (h(p.end) < -kEps) {
            if (std::fabs(h(from)) <= kEps) return from.x();
            if (p.dir == 0) {
                const double t = (level - from.y()) / (p.end.y() - from.y());
                return from.x() + t * (p.end.x() - from.x());
            }
            // The arc (monotonic between its ends) meets the level once: of the circle's two
            // points at v = level, the one within the arc's sweep.
            const double r = (from - p.center).norm();
            const double dvc = level - p.center.y();
            const double du = std::sqrt(std::max(0.0, r * r - dvc * dvc));
            const double a0 = angle_of(from, p.center), sweep = swept(a0, angle_of(p.end, p.center), p.dir);
            double best = from.x(), best_s = 1e300;
            for (double s : {1.0, -1.0}) {
                const Vec2 q(p.center.x() + s * du, level);
                const double sq = swept(a0, angle_of(q, p.center), p.dir);
                if (sq <= sweep + 1e-12 && sq < best_s) best = q.x(), best_s = sq;
            }
            return best;
        }
        from = p.end;
    }
    return from.x();
}
}  // namespace

void check_roughing(const Contour& contour, const Roughing& r) {
    if (!(r.depth > 0) || !std::isfinite(r.depth))
        throw CycleError{code::cycle_bad_value, "PS0062 ILLEGAL COMMAND IN G71-G76: the depth of cut must be above 0"};
    if (!(r.retract >= 0) || !std::isfinite(r.retract))
        throw CycleError{code::cycle_bad_value, "PS0062 ILLEGAL COMMAND IN G71-G76: the escape amount must be 0 or more"};
    if (contour.pieces.empty())
        throw CycleError{code::cycle_bad_value, "PS0062 ILLEGAL COMMAND IN G71-G76: the contour has no element after its first block"};
}

std::vector<Step> rough_type1(const Contour& contour, const Roughing& r) {
    check_roughing(contour, r);
    // The contour shifted by the allowances: what the levels leave, then the finishing allowance.
    auto shifted = [&](const Vec2& by) {
        Contour c = contour;
        c.start += by;
        for (ContourPiece& p : c.pieces) {
            p.end += by;
            p.center += by;
        }
        return c;
    };
    const Contour c = shifted(r.allowance + r.rough_allowance);
    const Vec2 a = r.start;
    const double dv = sign_of(contour.start.y() - a.y());  // the passes step towards the contour's start
    const double du = sign_of(c.pieces.back().end.x() - c.start.x());
    if (dv == 0)
        throw CycleError{code::cycle_bad_value,
                         "PS0062 ILLEGAL COMMAND IN G71-G76: the contour starts level with the start point, so the "
                         "passes have no direction"};
    if (du == 0) not_monotonic(c.pieces.back().line);
    Vec2 from = c.start;
    for (const ContourPiece& p : c.pieces) {
        check_monotonic(from, p, du, -dv);
        from = p.end;
    }
    const double passes = std::floor((c.start.y() - a.y()) * dv / r.depth);
    if (passes > static_cast<double>(r.max_passes))
        throw CycleError{code::cycle_bad_value, "PS0062 ILLEGAL COMMAND IN G71-G76: more than " +
                                                    std::to_string(r.max_passes) + " passes"};

    std::vector<Step> out;
    const StepKind infeed = r.rapid_infeed ? StepKind::rapid : StepKind::feed;
    for (long k = 1;; ++k) {
        const double level = a.y() + dv * static_cast<double>(k) * r.depth;
        if ((c.start.y() - level) * dv <= kEps) break;  // the contour pass takes the rest
        const double end = meet(c, level, dv);
        if ((end - a.x()) * du <= kEps) continue;  // no stock at this level beyond the start
        out.push_back({infeed, Vec2(a.x(), level)});
        out.push_back({StepKind::feed, Vec2(end, level)});
        out.push_back({StepKind::rapid, Vec2(end - du * r.retract, level - dv * r.retract)});
        out.push_back({StepKind::rapid, Vec2(a.x(), level - dv * r.retract)});
        if (out.size() > r.max_moves) throw MoveLimit{};
    }
    const Contour f = shifted(r.allowance);
    out.push_back({infeed, f.start, Vec2::Zero(), 0, f.pieces.front().line});
    for (const ContourPiece& p : f.pieces)
        out.push_back({p.dir == 0 ? StepKind::feed : StepKind::arc, p.end, p.center, p.dir, p.line});
    out.push_back({StepKind::rapid, a});
    return out;
}

std::vector<Step> pattern_repeat(const Contour& contour, const Vec2& start, const Vec2& first, const Vec2& last,
                                 int passes, bool rapid_approach, bool return_shifted, std::size_t max_moves) {
    if (passes < 1)
        throw CycleError{code::cycle_bad_value, "PS0062 ILLEGAL COMMAND IN G71-G76: the number of divisions must be 1 or more"};
    std::vector<Step> out;
    auto shift = [&](int j) {
        const double t = passes == 1 ? 0.0 : static_cast<double>(passes - j) / (passes - 1);
        return last + t * (first - last);
    };
    for (int j = 1; j <= passes; ++j) {
        const Vec2 s = shift(j);
        out.push_back({rapid_approach ? StepKind::rapid : StepKind::feed, contour.start + s});
        for (const ContourPiece& p : contour.pieces)
            out.push_back({p.dir == 0 ? StepKind::feed : StepKind::arc, p.end + s, p.center + s, p.dir, p.line});
        out.push_back({StepKind::rapid, return_shifted && j < passes ? start + shift(j + 1) : start});
        if (out.size() > max_moves) throw MoveLimit{};
    }
    return out;
}

}  // namespace toolcomp::cycles
