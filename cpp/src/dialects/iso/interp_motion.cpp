// Straight moves and arcs (LinuxCNC convert_straight / convert_arc / arc_data_ijk / arc_data_r).
#include <cmath>
#include <cstdio>

#include "interp.hpp"
#include "toolcomp/motion/spindle.hpp"
#include "toolcomp/program/codes.hpp"

namespace toolcomp::iso {

namespace {
constexpr char kAxisLetter[6] = {'X', 'Y', 'Z', 'A', 'B', 'C'};
}

// Centre of an R-format arc with LinuxCNC's own arithmetic (arc_data_r), so that exact
// comparisons of centres later decide as the control does. NaN when R cannot reach.
Vec2 Interp::center_from_radius_lcnc(const Vec2& s, const Vec2& e, double R, int dir) const {
    const double abs_r = std::fabs(R);
    const Vec2 mid((e.x() + s.x()) / 2.0, (e.y() + s.y()) / 2.0);
    double half = std::hypot(mid.x() - e.x(), mid.y() - e.y());
    if (half - abs_r > profile_.arc_min_radius[unit_index()]) return Vec2(std::nan(""), std::nan(""));
    if (half / abs_r > 1 - 1e-12) half = abs_r;  // a half circle, centre at the midpoint
    const long double quarter = 1.570796326794896619231321691639751442L;
    const long double base = std::atan2(e.y() - s.y(), e.x() - s.x());
    const double theta = static_cast<double>(((dir < 0 && R > 0) || (dir > 0 && R < 0)) ? base - quarter : base + quarter);
    const double offset = abs_r * std::cos(std::asin(half / abs_r));
    return {mid.x() + offset * std::cos(theta), mid.y() + offset * std::sin(theta)};
}

double Interp::axis_value(const BlockWords& bw, int axis) const {
    double v = bw[kAxisLetter[axis]].value;
    if (axis == 0 && st_.diameter) v *= 0.5;  // G7: every X word is a diameter
    return v;
}

Vec6 Interp::find_end(const BlockWords& bw) const {
    Vec6 end = pos_;
    for (int i = 0; i < 6; ++i) {
        if (!bw.has(kAxisLetter[i])) continue;
        double v = axis_value(bw, i);
        end[i] = st_.incremental ? pos_[i] + v : v;
    }
    // Fanuc lathes: U and W are increments of X (a diameter in diameter mode) and Z.
    if (bw.has('U')) end[0] = pos_[0] + bw['U'].value * (st_.diameter ? 0.5 : 1.0);
    if (bw.has('W')) end[2] = pos_[2] + bw['W'].value;
    if (bw.has_polar()) polar_end(bw, end);
    return end;
}

// LinuxCNC's polar coordinates (G17, no X or Y: polar_checks): @ the radius and ^ the angle
// (degrees) about the program's origin, the one not given kept from the current point. In
// G91 @ adds to the current point's radius and ^ turns it about the origin. (find_ends)
void Interp::polar_end(const BlockWords& bw, Vec6& end) const {
    constexpr double kD2R = 3.14159265358979323846 / 180.0;
    double& x = end[0];
    double& y = end[1];
    const bool r = bw.has('@'), t = bw.has('^');
    auto fail_polar = [&](const char* why) { fail(code::polar_coordinates, why, bw[r ? '@' : '^'].column); };
    if (!st_.incremental) {
        if (r && t) {
            x = bw['@'].value * std::cos(bw['^'].value * kD2R);
            y = bw['@'].value * std::sin(bw['^'].value * kD2R);
        } else if (r) {
            if (y == 0 && x == 0) fail_polar("Must specify angle in polar coordinate if at the origin");
            const double theta = std::atan2(y, x);
            x = bw['@'].value * std::cos(theta);
            y = bw['@'].value * std::sin(theta);
        } else {
            const double radius = std::hypot(y, x);
            x = radius * std::cos(bw['^'].value * kD2R);
            y = radius * std::sin(bw['^'].value * kD2R);
        }
        return;
    }
    if (r) {
        if (y == 0 && x == 0) fail_polar("Incremental motion with polar coordinates is indeterminate when at the origin");
        const double theta = std::atan2(y, x), radius = std::hypot(y, x) + bw['@'].value;
        x = radius * std::cos(theta);
        y = radius * std::sin(theta);
    }
    if (t) {
        if (y == 0 && x == 0) fail_polar("G91 motion with polar coordinates is indeterminate when at the origin");
        const double theta = std::atan2(y, x) + bw['^'].value * kD2R, radius = std::hypot(y, x);
        x = radius * std::cos(theta);
        y = radius * std::sin(theta);
    }
}

// What LinuxCNC refuses of polar coordinates before it runs the block (enhance_block), and
// the codes that take axis words, where toolcomp does not read them.
void Interp::polar_checks(const BlockWords& bw) const {
    const int col = bw[bw.has('@') ? '@' : '^'].column, g0 = bw.g[g_nonmodal];
    if (st_.plane != Plane::xy) fail(code::polar_coordinates, "Cannot use polar coordinate except in G17 plane", col);
    if (bw.has('X')) fail(code::polar_coordinates, "Cannot specify both polar coordinate and X word", bw['X'].column);
    if (bw.has('Y')) fail(code::polar_coordinates, "Cannot specify both polar coordinate and Y word", bw['Y'].column);
    if (g0 == G92) fail(code::polar_coordinates, "Polar coordinates can only be used for motion", col);
    if (g0 == G53) fail(code::polar_coordinates, "Cannot use polar coordinates with G53", col);
    if (g0 == G10 || g0 == G28 || g0 == G30 || g0 == G52)
        fail(code::unsupported_word, "Polar coordinates with G" + std::to_string(g0 / 10) + " are not supported by toolcomp", col);
}

// LinuxCNC keeps an inverse-time move's rate as its feed rate (what a canned cycle in G93
// finds: zero before any such move).
void Interp::inverse_time_rate(double feed) {
    if (st_.feed_mode == G93 && profile_.feed_mode_clears_feed) feed_ = feed;
}

// Feed per revolution needs a spindle speed (S; M5 keeps it).
void Interp::check_feed_per_rev(int column) const {
    if (st_.feed_mode == G95 && spindle().speed == 0)
        fail(code::zero_spindle_speed, "Cannot feed with zero spindle speed in feed per rev mode", column);
}

double Interp::feed_for(const BlockWords& bw, int code, double length, double x_end) const {
    if (code == G0) return std::nan("");
    switch (st_.feed_mode) {
        case G93:  // inverse time: the move takes 1/F minutes
            if (!bw.has('F'))
                fail(code::inverse_time_feed_missing,
                     code == G1 ? "F word missing with inverse time g1 move" : "F word missing with inverse time arc move");
            return std::max(profile_.inverse_time_min_rate * scale(), bw['F'].value * length);
        case G95: {  // units per revolution
            const double rpm = spindle_rpm(x_end);
            return std::isfinite(rpm) ? feed_ * rpm : std::nan("");
        }
        default:
            return feed_;
    }
}

// G96: the spindle turns to keep the surface speed at the tool's radius, taken where the
// move ends, no faster than D (or G50 S). At the axis without a limit: not known (inf).
double Interp::spindle_rpm(double x_end) const {
    const Spindle& s = spindle();
    if (!s.css) return s.speed;
    const double r = std::fabs(x_end) * scale();  // mm
    double rpm = css_rpm(s.speed * (st_.inch ? 304.8 : 1000.0), r);  // S in ft/min or m/min
    if (s.css_max > 0) rpm = std::min(rpm, s.css_max);
    if (spindle_clamp_ > 0) rpm = std::min(rpm, spindle_clamp_);
    return rpm;
}

Motion Interp::motion_to(MotionKind kind, const Vec6& end) const {
    Motion m;
    m.kind = kind;
    m.plane = st_.plane;
    m.start = pos_.head<3>();
    m.end = end.head<3>();
    m.abc = {end[3], end[4], end[5]};
    m.line = line_;
    m.file = file_;
    m.tool = tool_;
    m.tool_offset = tlo_.head<3>();
    // machine = R (program + G92) + G5x + tool offset (to_machine): R G92 + G5x is the offset.
    const double rotation = rotation_[st_.coord_system - 1];
    Vec3 g92 = g92_.head<3>();
    if (rotation != 0) {
        const double r = rotation * kPi / 180, c = std::cos(r), s = std::sin(r), x = g92.x();
        g92.x() = c * x - s * g92.y();
        g92.y() = s * x + c * g92.y();
    }
    m.work_offset = g92 + g5x_[st_.coord_system - 1].head<3>();
    m.work_rotation = rotation;
    m.radius = radius_;
    m.unit = scale();
    m.tool_axis = Vec3::Zero();
    m.tool_axis[axes(st_.plane).c] = 1;
    return m;
}

void Interp::straight(MotionKind kind, const Vec6& end, double feed) {
    Motion m = motion_to(kind, end);
    m.feed = feed;
    emit(m);
}

// A move of the program: to the sink (or to a lathe cycle's contour being read).
void Interp::emit(const Motion& m) {
    comp_moved_ = comp_moved_ || comp_on();
    if (travel_ && !capture_) check_travel(m);
    ++moves_;
    out().push(m);
    pos_.head<3>() = m.end;
    pos_.tail<3>() = Vec3(m.abc[0], m.abc[1], m.abc[2]);
}

void Interp::motion_line(const BlockWords& bw, int code, bool machine_coords) {
    arc_not_allowed_ = false;
    Vec6 end = find_end(bw);
    if (machine_coords) {
        // G53: the words are machine coordinates of the controlled point.
        Vec6 m = to_machine(pos_);
        for (int i = 0; i < 6; ++i)
            if (bw.has(kAxisLetter[i])) m[i] = axis_value(bw, i);
        end = from_machine(m);
    }
    if (code == G1 && st_.feed_mode != G93 && feed_ <= 0)
        fail(code::zero_feed, "Cannot do g1 with zero feed rate", bw.axis_column());
    if (code == G1) check_feed_per_rev(bw.axis_column());
    if (machine_coords && comp_on() && radius_.radius > 0)
        fail(code::comp_g53, "Cannot use g53 with cutter radius comp", bw.g_column[g_nonmodal]);
    // The length an inverse-time feed is worked out from: of X, Y, Z, or, when only rotary
    // axes move, of A, B, C in degrees (LinuxCNC's find_straight_length).
    double length = (end.head<3>() - pos_.head<3>()).norm() * scale();
    if (length == 0) length = (end.tail<3>() - pos_.tail<3>()).norm() * scale();
    double feed = feed_for(bw, code, length, end[0]);
    if (code == G1) inverse_time_rate(feed);
    straight(code == G0 ? MotionKind::rapid : MotionKind::line, end, feed);
}

// LinuxCNC's check of a centre-format arc: both ends at a radius above the least, and on one
// circle within the control's tolerance (a slight spiral passes).
void Interp::check_arc_ends(const Vec2& s, const Vec2& c, const Vec2& e, char a_l, char b_l) const {
    const double min_r = profile_.arc_min_radius[unit_index()];
    const double r1 = (s - c).norm(), r2 = (e - c).norm();
    auto describe = [&](const char* head) {
        char buf[512];
        std::snprintf(buf, sizeof buf,
                      "%sstart=(%c%.4f,%c%.4f) center=(%c%.4f,%c%.4f) end=(%c%.4f,%c%.4f) r1=%.4f r2=%.4f", head,
                      a_l, s.x(), b_l, s.y(), a_l, c.x(), b_l, c.y(), a_l, e.x(), b_l, e.y(), r1, r2);
        return std::string(buf);
    };
    if (r1 < min_r || r2 < min_r) fail(code::arc_zero_radius, describe("Zero-radius arc: "));
    double abs_err = std::fabs(r1 - r2);  // program units, as the control compares
    double rel_err = abs_err / std::max(r1, r2);
    double tol = profile_.arc_spiral_abs[unit_index()];
    if (abs_err > profile_.arc_spiral_hard_factor * tol || (rel_err > profile_.arc_spiral_rel && abs_err > tol)) {
        char tail[96];
        std::snprintf(tail, sizeof tail, " abs_err=%.4g rel_err=%.4f%%", abs_err, rel_err * 100);
        fail(code::arc_end_off_circle, describe("Radius to end of arc differs from radius to start: ") + tail);
    }
}

void Interp::motion_arc(const BlockWords& bw, int code) {
    const PlaneAxes ax = axes(st_.plane);
    const char* plane_name = st_.plane == Plane::xy ? "xy" : st_.plane == Plane::zx ? "xz" : "yz";
    const char letters[3] = {'X', 'Y', 'Z'};
    const char offset_letter[3] = {'I', 'J', 'K'};  // centre word of each axis
    const char a_l = letters[ax.a], b_l = letters[ax.b];
    const char a_off = offset_letter[ax.a], b_off = offset_letter[ax.b], c_off = offset_letter[ax.c];
    if (arc_not_allowed_) fail(code::comp_exit_arc, profile_.radius.messages.exit_arc);
    if (st_.feed_mode != G93 && feed_ <= 0) fail(code::zero_feed, "Cannot make arc with zero feed rate");
    check_feed_per_rev(0);
    const bool r_form = bw.has('R');
    if (r_form && (bw.has('I') || bw.has('J') || bw.has('K')))
        fail(code::mixed_arc_format, "Mixed radius ijk format for arc", bw['R'].column);
    if (!r_form && !bw.has(a_off) && !bw.has(b_off)) {
        if (!bw.has('I') && !bw.has('J') && !bw.has('K')) fail(code::arc_words_missing, "R i j k words all missing for arc");
    }
    if (bw.has(c_off))
        fail(code::arc_offset_wrong_axis,
             std::string(1, c_off) + " word given for arc in " + plane_name + " plane", bw[c_off].column);
    auto has_axis_word = [&](char l) {  // polar coordinates count for X and Y (G17 only)
        return bw.has(l) || (l == 'X' && bw.has('U')) || (l == 'Z' && bw.has('W')) || (l != 'Z' && bw.has_polar());
    };
    if (r_form && !has_axis_word(a_l) && !has_axis_word(b_l)) {
        // LinuxCNC names the axes in alphabetical order: "X and z words missing ... xz plane".
        const char* names = st_.plane == Plane::xy ? "X and y" : st_.plane == Plane::zx ? "X and z" : "Y and z";
        fail(code::arc_axis_words_missing, std::string(names) + " words missing for arc in " + plane_name + " plane");
    }
    int p = 1;
    if (bw.has('P') && !profile_.arc_turns_word)
        fail(code::unused_word, "P in G2/G3 is LinuxCNC's number of turns; this control's arcs take no P",
             bw['P'].column);
    if (bw.has('P')) {
        double pv = bw['P'].value;
        // LinuxCNC refuses a P more than 0.001 from an integer; Fanuc takes it as written.
        if (std::fabs(std::round(pv) - pv) > (profile_.integer_word_slack ? 0.001 : 1e-9))
            fail(code::arc_p_not_integer, "P value not an integer with M19 G2 or G3", bw['P'].column);
        if (pv > kMaxArcTurns + 1.5)
            fail(code::arc_too_many_turns,
                 "P value of G2 or G3 is more than " + std::to_string(kMaxArcTurns + 1) + " turns",
                 bw['P'].column);
        p = int_value(pv);
        if (p < 1) fail(code::arc_p_not_positive, "P value should be 1 or greater with G2 or G3", bw['P'].column);
    }

    Vec6 end = find_end(bw);
    Vec2 s(pos_[ax.a], pos_[ax.b]), e(end[ax.a], end[ax.b]);
    Vec2 c;
    const int dir = code == G3 ? 1 : -1;
    if (r_form) {
        if (s == e) fail(code::arc_same_point, "Current point same as end point of arc", bw['R'].column);
        const double R = bw['R'].value;
        c = center_from_radius_lcnc(s, e, R, dir);
        if (std::isnan(c.x())) fail(code::arc_radius_too_small, "Arc radius too small to reach end point", bw['R'].column);
    } else {
        auto centre_word = [&](char off, int axis) -> double {
            if (st_.arc_absolute) {
                if (!bw.has(off))
                    fail(code::arc_center_missing, std::string(1, off) + " word missing in absolute center arc");
                return bw[off].value;
            }
            (void)axis;
            return bw.has(off) ? bw[off].value : 0.0;
        };
        double ci = centre_word(a_off, ax.a), cj = centre_word(b_off, ax.b);
        c = st_.arc_absolute ? Vec2(ci, cj) : Vec2(s.x() + ci, s.y() + cj);
        check_arc_ends(s, c, e, a_l, b_l);
    }

    Vec6 centre = pos_;
    centre[ax.a] = c.x();
    centre[ax.b] = c.y();
    Motion m = motion_to(code == G3 ? MotionKind::arc_ccw : MotionKind::arc_cw, end);
    m.center = centre.head<3>();
    m.turns = p - 1;
    // An inverse-time arc's length as LinuxCNC measures it: the start radius times the sweep
    // (a slight spiral is not averaged), with the helix rise.
    double length = 0;
    if (st_.feed_mode == G93) {
        const Arc a = m.arc();
        length = std::hypot(arc_start_radius(a) * arc_sweep(a), end[ax.c] - pos_[ax.c]) * scale();
    }
    m.feed = feed_for(bw, code, length, end[0]);
    inverse_time_rate(m.feed);
    emit(m);
}

}  // namespace toolcomp::iso
