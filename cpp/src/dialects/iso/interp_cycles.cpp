// Canned cycles G73, G74, G81-G89 expanded into their moves, the way
// LinuxCNC's interpreter does (convert_cycle_xy/_zx/_yz and the per-cycle functions):
// the XY move at the current level, the plunge to R, the cycle's own moves, the retract to
// the clearance level (G98: the initial level, G99: R), repeated L times.
#include <algorithm>
#include <cstdio>
#include <cmath>

#include "interp.hpp"
#include "toolcomp/program/codes.hpp"

namespace toolcomp::iso {

void Interp::cycle(const BlockWords& bw, int code) {
    const PlaneAxes ax = axes(st_.plane);
    const char letters[3] = {'X', 'Y', 'Z'};
    const char cl = letters[ax.c];
    const char* plane_name = st_.plane == Plane::xy ? "xy" : st_.plane == Plane::zx ? "xz" : "yz";
    const bool continuing = prev_motion_ == code;
    const std::string gname = "g" + std::to_string(code / 10);

    for (char c : {'A', 'B', 'C'})
        if (bw.has(c))
            fail(code::cycle_rotary, std::string("Cannot put ") + (c == 'A' ? "an " : "a ") +
                                     static_cast<char>(c - 'A' + 'a') + " in canned cycle", bw[c].column);
    // LinuxCNC's order: the feed, the feed mode, compensation, R, L, the depth, R against the
    // depth (below), then each cycle's own words. P and Q of -1 are LinuxCNC's "no word"
    // (its block keeps -1 for a missing P or Q); other negative values are read as given.
    if (feed_ <= 0) fail(code::zero_feed, "Cannot feed with zero feed rate");
    if (st_.feed_mode == G93) fail(code::cycle_inverse_time, "Cannot use inverse time feed with canned cycles");
    if (comp_on())
        fail(code::comp_canned_cycle, "Cannot use canned cycles with cutter compensation on",
             bw.g[g_motion] >= 0 ? bw.g_column[g_motion] : bw.axis_column());
    if (bw.has('R'))
        cyc_.r = bw['R'].value;
    else if (!continuing)
        fail(code::cycle_r_missing, "R clearance plane unspecified in cycle");
    int repeats = 1;
    if (bw.has('L')) {
        repeats = int_value(bw['L'].value);
        if (repeats < 0) fail(code::negative_l, "Negative l word used", bw['L'].column);
        if (repeats == 0) fail(code::zero_repeats, "Cannot do zero repeats of cycle", bw['L'].column);
    }
    if (bw.has(cl))
        cyc_.z = axis_value(bw, ax.c);  // G7 and the G19 depth X: a diameter
    else if (!continuing)
        fail(code::cycle_depth_missing, std::string(1, cl) + " value unspecified in " + plane_name + " plane canned cycle");
    const bool q_word = bw.has('Q') && bw['Q'].value != -1;
    const bool p_word = bw.has('P') && bw['P'].value != -1;
    // Levels along the tool axis. The initial level is that of the first block of the cycle.
    if (!cycle_il_set_) {
        cycle_il_ = pos_[ax.c];
        cycle_il_set_ = true;
    }
    double old_cc = cycle_il_;
    double a = pos_[ax.a], b = pos_[ax.b], da = 0, db = 0, dr = 0, dt = 0, r, bottom;
    const char la = letters[ax.a], lb = letters[ax.b];
    constexpr double kD2R = 3.14159265358979323846 / 180.0;
    if (st_.incremental) {
        if (bw.has(la)) da = axis_value(bw, ax.a);
        if (bw.has(lb)) db = axis_value(bw, ax.b);
        if (bw.has('@')) dr = bw['@'].value;  // polar (G17): each repeat further out and on
        if (bw.has('^')) dt = bw['^'].value * kD2R;
        r = cyc_.r + old_cc;
        bottom = r + cyc_.z;  // the depth word is measured from R
    } else {
        if (bw.has(la)) a = axis_value(bw, ax.a);
        if (bw.has(lb)) b = axis_value(bw, ax.b);
        if (bw.has_polar()) {  // about the origin, the one not given from the current point
            const double radius = bw.has('@') ? bw['@'].value : std::hypot(pos_[1], pos_[0]);
            const double theta = bw.has('^') ? bw['^'].value * kD2R : std::atan2(pos_[1], pos_[0]);
            a = radius * std::cos(theta);
            b = radius * std::sin(theta);
        }
        r = cyc_.r;
        bottom = cyc_.z;
    }
    if (r < bottom)
        fail(code::cycle_r_below_depth, std::string("R less than ") + static_cast<char>(cl - 'A' + 'a') +
                                        " in cycle in " + plane_name + " plane");
    if (code == G73 || code == G83) {
        if (q_word)
            cyc_.q = bw['Q'].value;
        else if (!continuing)
            fail(code::cycle_q_missing, "Q word missing with " + gname, bw.has('Q') ? bw['Q'].column : 0);
    }
    if (code == G74 || code == G84) {
        if (p_word) cyc_.p = bw['P'].value;  // optional dwell at the bottom
    } else if (code == G82 || code == G86 || code == G88 || code == G89) {
        if (p_word)
            cyc_.p = bw['P'].value;
        else if (!continuing)
            fail(code::cycle_p_missing, "Dwell time p word missing with " + gname);
    }
    if (code == G87) {  // back boring: offsets from the hole and the top of the counterbore (see below)
        const char* names = "IJK";
        for (int n = 0; n < 3; ++n) {
            char c = names[n];
            if (!bw.has(c) && !continuing)
                fail(code::cycle_g87_word_missing, std::string(1, c) + " word missing with g87");
        }
        if (bw.has('I')) cyc_.i = bw['I'].value;
        if (bw.has('J')) cyc_.j = bw['J'].value;
        if (bw.has('K')) cyc_.k = bw['K'].value;
    }

    const double nan = std::nan("");
    auto at = [&](double aa, double bb, double cc) {
        Vec6 p = pos_;
        p[ax.a] = aa;
        p[ax.b] = bb;
        p[ax.c] = cc;
        return p;
    };
    if (old_cc < r) {  // below the R plane: straight up to it first
        straight(MotionKind::rapid, at(pos_[ax.a], pos_[ax.b], r), nan);
        old_cc = r;
    }
    const double clear = st_.retract_initial ? old_cc : r;
    // A feed move of the cycle; under G96 its feed follows the X where it ends, as any move's.
    auto fed = [&](const Vec6& p) { straight(MotionKind::line, p, feed_for(bw, G1, 0, p[0])); };
    const double rapid_delta = st_.inch ? 0.010 : 0.010 * kMmPerInch;  // LinuxCNC's G83_RAPID_DELTA
    for (int rep = 0; rep < repeats; ++rep) {
        if (rep > 0) count_block(bw['L'].column);
        a += da;
        b += db;
        auto polar_step = [&](double more_radius, double more_angle) {  // LinuxCNC's CYCLE_MACRO
            if (b == 0 && a == 0)
                fail(code::polar_coordinates, "Incremental motion with polar coordinates is indeterminate when at the origin");
            const double theta = std::atan2(b, a) + more_angle, radius = std::hypot(b, a) + more_radius;
            a = radius * std::cos(theta);
            b = radius * std::sin(theta);
        };
        if (dr != 0) polar_step(dr, 0.0);
        if (dt != 0) polar_step(0.0, dt);
        // To the hole at the level the tool is at when that is above R, else at the clearance
        // level (LinuxCNC 2.9: after a G99 cycle a G98 one with a lower R moves across at
        // the old R; a tool below R goes diagonally up), then down to R.
        const double level = pos_[ax.c] > r ? pos_[ax.c] : clear;
        straight(MotionKind::rapid, at(a, b, level), nan);
        if (level != r) straight(MotionKind::rapid, at(a, b, r), nan);
        // The control checks the spindle when the cycle itself starts, after the approach.
        if ((code == G86 || code == G87 || code == G88 || code == G74 || code == G84) && spindle().turning == 0)
            fail(code::spindle_not_turning, "Spindle not turning in " + std::string(code == G74 ? "G74" : code == G84 ? "G84" : gname));
        if ((code == G73 || code == G83) && cyc_.q <= 0)
            fail(code::cycle_q_zero, "Negative or zero q value used", bw.has('Q') ? bw['Q'].column : 0);
        if (code == G84 && spindle().turning < 0)
            fail(code::spindle_direction, "Spindle turning counterclockwise in G84");
        if (code == G74 && spindle().turning > 0) fail(code::spindle_direction, "Spindle turning clockwise in G74");
        switch (code) {
            case G74:
            case G84:  // tapping: feed in, reverse the spindle, feed straight out to clearance
                if (code == G84 && st_.plane != Plane::xy && profile_.g84_axes_warning) {
                    // LinuxCNC 2.9 feeds its G84 in G18 / G19 to the plane's coordinates and
                    // the depth in another axis order (its own test records it): the tap
                    // would go elsewhere. toolcomp keeps the tap on the hole's axis and says so.
                    const bool g18 = st_.plane == Plane::zx;
                    const double x = g18 ? bottom : b, y = g18 ? a : bottom, z = g18 ? b : a;
                    char msg[240];
                    std::snprintf(msg, sizeof msg,
                                  "LinuxCNC 2.9 feeds G84 in G%d to X%.4f Y%.4f Z%.4f (the plane's axes out of "
                                  "order); toolcomp returns the tap along the hole's axis",
                                  g18 ? 18 : 19, x, y, z);
                    diags_.push_back({code::g84_off_axis, Severity::warning, msg, {line_, 0, file_name()}});
                }
                fed(at(a, b, bottom));
                fed(at(a, b, clear));
                break;
            case G87: {
                // Back boring: in beside the hole with the spindle oriented, across to the
                // hole's axis at the bottom, feed up to the counterbore top and back, then out
                // the same way. The words go by axis letter (I X, J Y, K Z): in G17 I J are
                // the offset and K the top, in G18 K I and J, in G19 J K and I (LinuxCNC).
                const double word[3] = {cyc_.i, cyc_.j, cyc_.k};
                const double oa = a + word[ax.a], ob = b + word[ax.b];
                const double middle = st_.incremental ? bottom + word[ax.c] : word[ax.c];
                straight(MotionKind::rapid, at(oa, ob, r), nan);
                straight(MotionKind::rapid, at(oa, ob, bottom), nan);
                straight(MotionKind::rapid, at(a, b, bottom), nan);
                fed(at(a, b, middle));
                fed(at(a, b, bottom));
                straight(MotionKind::rapid, at(oa, ob, bottom), nan);
                straight(MotionKind::rapid, at(oa, ob, clear), nan);
                straight(MotionKind::rapid, at(a, b, clear), nan);
                break;
            }
            case G88:
                // Bore, dwell, stop: the operator retracts by hand. The control then takes the
                // tool to be at the clearance level; the path has no move for that.
                fed(at(a, b, bottom));
                dwell(cyc_.p);
                pos_ = at(a, b, clear);
                info(code::manual_retract, "G88: the operator retracts the tool by hand; the next move starts at the clearance level");
                break;
            case G81:
            case G82:
            case G86:
                fed(at(a, b, bottom));
                if (code != G81) dwell(cyc_.p);
                straight(MotionKind::rapid, at(a, b, clear), nan);
                break;
            case G85:
                fed(at(a, b, bottom));
                fed(at(a, b, r));
                straight(MotionKind::rapid, at(a, b, clear), nan);
                break;
            case G89:
                fed(at(a, b, bottom));
                dwell(cyc_.p);
                fed(at(a, b, clear));
                break;
            case G73:
            case G83:
                for (double depth = r - cyc_.q; depth > bottom; depth -= cyc_.q) {
                    // Every peck counts against the block limit: a huge depth with a tiny Q
                    // (or one that no longer changes the depth) stops there, never hangs.
                    count_block(bw['Q'].column);
                    fed(at(a, b, depth));
                    if (code == G83) straight(MotionKind::rapid, at(a, b, r), nan);
                    straight(MotionKind::rapid, at(a, b, depth + rapid_delta), nan);
                }
                fed(at(a, b, bottom));
                straight(MotionKind::rapid, at(a, b, clear), nan);
                break;
            default:
                break;
        }
    }
}

}  // namespace toolcomp::iso
