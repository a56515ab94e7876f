// LinuxCNC's spindle-synchronised motion (profile.spindle_sync_motion), as its 2.9
// interpreter runs it (interp_convert.cc: convert_straight, convert_threading_cycle,
// threading_pass):
//   * G33 X Z K: a line whose feed is K per spindle revolution; F is not allowed, and the
//     feed rate in force stays for the moves after it;
//   * G33.1 X Y Z K [I]: rigid tapping, in to the point and back out to where it began (the
//     spindle reversed, I times as fast: I below 1 is 1); the program's point stays;
//   * G76 P Z I J K [R Q H E L]: the threading cycle from where the tool is (the drive line),
//     pass by pass: depths J n^(1/R) beyond the thread's crest I while below K, then K
//     (H + 1 times), each infeed shifted along Z by the compound angle Q, with tapers of
//     length E at the entry (L1), the exit (L2) or both (L3).
// Every synchronised move's feed is its lead per revolution times the spindle speed (at the
// move's end X under G96), in mm/min. The passes follow LinuxCNC's arithmetic step by step:
// whether a pass exists depends on an exact comparison.
#include <cmath>

#include "interp.hpp"
#include "toolcomp/program/codes.hpp"
#include "toolcomp/program/text.hpp"

namespace toolcomp::iso {

// LinuxCNC's $ word: the spindle the block's spindle codes act on. toolcomp models a machine
// with one spindle (LinuxCNC's default, [TRAJ]SPINDLES = 1): $0, and $-1 ("all") where
// LinuxCNC allows it; the value is truncated as LinuxCNC stores it in an int. The codes that
// read it are those of LinuxCNC 2.9.0 (the pre-release also refuses it beside G93-G97 alone).
void Interp::spindle_choice(const BlockWords& bw, int motion_to_be) const {
    if (!bw.has('$')) return;
    const int col = bw['$'].column;
    const int sp = bw.m[m_spindle], ov = bw.m[m_override];
    const bool sync = motion_to_be == G33 || motion_to_be == G33_1 || motion_to_be == G76;
    if (!(sp == M3 || sp == M4 || sp == M5 || sp == M19 || ov == M51 || sync || bw.has('S') || bw.g[g_feed_mode] >= 0 ||
          bw.g[g_spindle_mode] >= 0))
        fail(code::spindle_choice,
             "$ (spindle selection) word with no M3, M4, M5, M19, M51, G33, G33.1, G76, G95, G96 or G97 to use it", col);
    const double v = bw['$'].value;
    const int n = std::isfinite(v) && std::fabs(v) < 1e9 ? static_cast<int>(v) : 1000000000;
    const int kSpindles = spindle_count();
    auto check = [&](bool all_allowed, const std::string& message) {
        if (n >= kSpindles || n < (all_allowed ? -1 : 0)) fail(code::spindle_choice, message, col);
    };
    if (bw.g[g_spindle_mode] >= 0) check(false, "Invalid spindle ($) number in Spindle Mode command");
    if (bw.g[g_feed_mode] >= 0) check(false, "Invalid spindle ($) number in Spindle Feed command");
    if (bw.has('S')) check(true, "Invalid spindle ($) number in Spindle speed command");
    if (sp == M3 || sp == M4 || sp == M5)
        check(true, "Spindle ($) number out of range in M" + std::to_string(sp / 10) + " Command");
    if (sp == M19) check(false, "Spindle ($) number out of range in M19 Command");
    if (ov == M51 && (n < 1 || n >= kSpindles)) fail(code::spindle_choice, "Invalid spindle ($) number in M51 command", col);
    if (motion_to_be == G33) check(false, "Invalid spindle ($) number in G33 move");
    if (motion_to_be == G33_1) check(false, "Invalid spindle ($) number in G33.1 move");
    if (motion_to_be == G76) check(false, "Invalid D-number in G76 cycle");
}

// S, G96/G97 and G93-G95 as LinuxCNC 2.9 takes them with $: the spindle mode and the feed
// mode choose the spindle G95 and G33/G76 follow ($n, else spindle 0); S sets spindle $n, all
// of them with $-1, else spindle 0.
void Interp::spindle_words(const BlockWords& bw) {
    const bool dollar = bw.has('$');
    const int n = dollar ? static_cast<int>(bw['$'].value) : 0;  // in range (spindle_choice)
    if (int sm = bw.g[g_spindle_mode]; sm >= 0) {  // G96 (D: its speed limit) / G97
        active_spindle_ = n;
        Spindle& s = spindle();
        s.css = sm == G96;
        if (s.css) s.css_max = bw.has('D') ? std::fabs(bw['D'].value) : 0;  // no D: no limit
    }
    if (bw.g[g_feed_mode] >= 0) active_spindle_ = n;
    if (dollar) {  // G33, G33.1, G76 with $ follow that spindle (the motion only looked up then)
        const int motion = motion_of(bw);
        if (motion == G33 || motion == G33_1 || motion == G76) active_spindle_ = n;
    }
    if (bw.has('S') && bw.g[g_nonmodal] != G50) {  // (G50 S: the spindle clamp of a Fanuc lathe)
        for (int i = 0; i < spindle_count(); ++i)
            if (i == n || (dollar && n == -1)) spindles_[static_cast<std::size_t>(i)].speed = bw['S'].value;
    }
}

// M3, M4, M5, M19 on spindle $n, on all of them with $-1, else on spindle 0; M19 stops all
// and turns spindle $n (else 0) to its angle. (LinuxCNC 2.9.0; from 2.9.1 on M5 without $
// stops all spindles.)
void Interp::spindle_turn(const BlockWords& bw, int code) {
    const bool dollar = bw.has('$');
    const int n = dollar ? static_cast<int>(bw['$'].value) : 0;
    const int turning = code == M3 ? 1 : code == M4 ? -1 : 0;
    const bool all = code == M19 || (dollar && n == -1);
    for (int i = 0; i < spindle_count(); ++i)
        if (all || i == n) spindles_[static_cast<std::size_t>(i)].turning = turning;
    if (code == M19 && bw.has('Q') && bw['Q'].value <= 0.0)
        fail(code::spindle_orient_words, "Q word with M19 requires a value > 0", bw['Q'].column);
}

double Interp::sync_feed(double lead, double x_end) const {
    const double rpm = spindle_rpm(x_end);
    return std::isfinite(rpm) ? lead * scale() * rpm : std::nan("");
}

// LinuxCNC's checks before a synchronised move, in its order.
void Interp::sync_can_start(const BlockWords& bw, const char* what) const {
    const int col = bw.g[g_motion] >= 0 ? bw.g_column[g_motion] : bw.axis_column();
    // Its compensation code knows G0 and G1 only (a radius of 0 passes).
    if (comp_on() && radius_.radius > 0) fail(code::sync_motion_comp, "Bug code not g0 or g1", col);
    if (spindle().turning == 0) {
        if (std::string(what) == "G76")
            fail(code::spindle_not_turning, "Chosen spindle (" + std::to_string(active_spindle_) + ") not turning in G76", col);
        fail(code::spindle_not_turning, std::string("Spindle not turning in ") + what, col);
    }
}

void Interp::sync_line(const BlockWords& bw) {
    sync_can_start(bw, "G33");
    const Vec6 end = find_end(bw);
    straight(MotionKind::line, end, sync_feed(bw['K'].value, end[0]));
}

void Interp::rigid_tap(const BlockWords& bw) {
    sync_can_start(bw, "G33.1");
    const Vec6 end = find_end(bw);
    const double k = bw['K'].value;
    const double reverse = bw.has('I') && bw['I'].value >= 1 ? bw['I'].value : 1.0;
    Vec6 back = pos_;
    back.tail<3>() = end.tail<3>();
    straight(MotionKind::line, end, sync_feed(k, end[0]));
    straight(MotionKind::line, back, sync_feed(k, back[0]) * reverse);
}

void Interp::lcnc_threading(const BlockWords& bw) {
    const int col = bw.g[g_motion] >= 0 ? bw.g_column[g_motion] : bw.axis_column();
    sync_can_start(bw, "G76");
    const Vec6 end = find_end(bw);
    if (end.tail<3>() != pos_.tail<3>()) fail(code::sync_motion_words, "Cannot move rotary axes with G76", col);
    if (comp_on()) fail(code::sync_motion_comp, "Cannot use G76 threading cycle with cutter radius compensation on", col);
    double i = bw['I'].value, j = bw['J'].value, k = bw['K'].value;
    if (i == 0) fail(code::sync_motion_words, "In G76, I must not be 0", col);
    if (j <= 0) fail(code::sync_motion_words, "In G76, J must be greater than 0", col);
    if (k <= j) fail(code::sync_motion_words, "In G76, K must be greater than J", col);
    if (bw.has('H') && bw['H'].value < -1) fail(code::sync_motion_words, "Negative h word used", bw['H'].column);
    // G7: I J K are diameters. G7 switched on in this very block halves them twice, G8 switched
    // on doubles them (LinuxCNC's convert_lathe_diameter_mode scales them as it scales X).
    if (bw.g[g_lathe_diameter] >= 0 && diameter_switched_) {
        const double f = st_.diameter ? 0.25 : 2.0;
        i *= f, j *= f, k *= f;
        diags_.push_back({code::g76_diameter_block, Severity::warning,
                          std::string(st_.diameter ? "G7" : "G8") +
                              " in the block of G76: LinuxCNC scales I J K twice, the thread is cut at I" +
                              shortest_number(i) + " J" + shortest_number(j) + " K" + shortest_number(k) + " (radius)",
                          {line_, col, file_name()}});
    } else if (st_.diameter) {
        i /= 2, j /= 2, k /= 2;
    }
    const bool boring = i > 0.0;
    const double safe_x = pos_[0], start_z = pos_[2];
    const double full_dia_depth = std::fabs(i), start_depth = std::fabs(i) + std::fabs(j);
    const double cut_increment = std::fabs(j), full_threadheight = std::fabs(k);
    const double end_depth = std::fabs(k) + std::fabs(i);
    const double pitch = bw['P'].value;
    double compound = bw.has('Q') ? bw['Q'].value : -1;
    if (compound == -1) compound = 0;
    // LinuxCNC multiplies by pi/180 in long double.
    compound = static_cast<double>(compound * (3.141592653589793238462643383279502884L / 180.0L));
    if (end[2] > start_z) compound = -compound;
    const int spring_cuts = bw.has('H') ? int_value(bw['H'].value) : 0;
    double degression = bw.has('R') ? bw['R'].value : 0.0;
    if (degression < 1.0 || !bw.has('R')) degression = 1.0;
    double taper_dist = bw.has('E') ? bw['E'].value : 0.0;
    if (taper_dist < 0.0) taper_dist = 0.0;
    const double taper_pitch = taper_dist > 0.0 ? pitch * std::hypot(taper_dist, full_threadheight) / taper_dist : pitch;
    if (end[2] > start_z) taper_dist = -taper_dist;
    const int flags = bw.has('L') ? std::max(int_value(bw['L'].value), 0) : 0;
    const bool entry_taper = (flags & 1) != 0, exit_taper = (flags & 2) != 0;
    const double target_z = end[2] + std::fabs(k) * std::tan(compound);

    auto at = [&](double x, double z) {
        Vec6 p = pos_;
        p[0] = x;
        p[1] = pos_[1];
        p[2] = z;
        return p;
    };
    auto rapid = [&](double x, double z) { straight(MotionKind::rapid, at(x, z), std::nan("")); };
    auto feed = [&](double x, double z, double lead) { straight(MotionKind::line, at(x, z), sync_feed(lead, x)); };
    auto pass = [&](double depth, double zoff) {
        const double out = boring ? safe_x + depth - end_depth : safe_x - depth + end_depth;
        const double in = boring ? safe_x + depth : safe_x - depth;
        const double crest = boring ? safe_x + depth - full_threadheight : safe_x - depth + full_threadheight;
        rapid(out, start_z - zoff);  // back
        if (taper_dist != 0 && entry_taper) {
            feed(crest, start_z - zoff, taper_pitch);                   // in
            feed(in, start_z - zoff - taper_dist, taper_pitch);         // angled in
        } else {
            rapid(in, start_z - zoff);                                  // in
        }
        if (taper_dist != 0 && exit_taper) {
            feed(in, target_z - zoff + taper_dist, pitch);              // over
            feed(crest, target_z - zoff, taper_pitch);                  // angled out
        } else {
            feed(in, target_z - zoff, pitch);                           // over
        }
        rapid(out, target_z - zoff);  // out
    };
    int n = 1;
    double depth = start_depth;
    double zoff = (depth - full_dia_depth) * std::tan(compound);
    while (depth < end_depth) {
        pass(depth, zoff);
        depth = full_dia_depth + cut_increment * std::pow(++n, 1.0 / degression);
        zoff = (depth - full_dia_depth) * std::tan(compound);
        count_block(col);  // a pass counts as a block (ControlProfile::block_limit)
    }
    depth = end_depth;
    zoff = (depth - full_dia_depth) * std::tan(compound);
    for (int s = 0; s < spring_cuts + 1; ++s) pass(depth, zoff);
    straight(MotionKind::rapid, end, std::nan(""));
}

}  // namespace toolcomp::iso
