// The TNC's drilling cycles 200 DRILLING, 201 REAMING and 207 RIGID TAPPING: CYCL DEF stores
// the cycle with its Q parameters (which are Q parameters of the program from then on), CYCL
// CALL and M99 (at the end of its block) run it where the tool stands. Along the tool axis,
// from the surface S = Q203 (from the datum): the set-up clearance S + Q200, the depth S +
// Q201 (negative: into the workpiece), the 2nd set-up clearance S + Q204; the cycle ends at
// the higher of the two clearances.
#include <cmath>
#include <string>

#include "interp.hpp"
#include "toolcomp/program/codes.hpp"

namespace toolcomp::heidenhain {

namespace {

// The parameters each cycle needs, in the order the TNC writes them.
const std::vector<int>& needed(int cycle) {
    static const std::vector<int> k200{200, 201, 206, 202, 203, 204}, k201{200, 201, 206, 203, 204},
        k207{200, 201, 239, 203, 204};
    return cycle == 200 ? k200 : cycle == 201 ? k201 : k207;
}

}  // namespace

void Interp::define_drilling(Tokens t, int number) {
    CycleDef def;
    def.number = number;
    for (std::size_t i = 3; i < t.size(); ++i) {
        const Token& k = t[i];
        if (k.key.size() < 2 || k.key[0] != 'Q' || k.key.find_first_not_of("0123456789", 1) != std::string::npos) continue;
        const int n = std::stoi(k.key.substr(1));
        if (k.has_value) def.q[n] = k.value;
        else if (k.text == "MAX" || k.text == "FMAX") def.q[n] = INFINITY;
        else fail(code::unsupported_word, "Q" + std::to_string(n) + "=" + k.text + " is not supported by toolcomp", k.column);
    }
    for (int n : needed(number))
        if (!def.q.count(n))
            fail(code::cycle_q_missing, "CYCL DEF " + std::to_string(number) + ": Q" + std::to_string(n) + " missing",
                 t[2].column);
    for (const auto& [n, v] : def.q)
        if (std::isfinite(v)) q_[n] = v;  // the cycle's parameters are the program's Q parameters too
    cycle_def_ = std::move(def);
}

void Interp::call_cycle(int column) {
    if (!cycle_def_) fail(code::unsupported_block, "CYCL CALL without a cycle defined (CYCL DEF)", column);
    const CycleDef& d = *cycle_def_;
    auto q = [&](int n) { return d.q.at(n); };
    const std::string name = "CYCL DEF " + std::to_string(d.number);
    if (side_ != 0) fail(code::comp_canned_cycle, name + " called with RL/RR: the cycle needs R0", column);
    const int c = axes(plane_).c;
    const double depth = q(201);
    if (depth == 0) return;  // the TNC does not run the cycle
    if (depth > 0)
        fail(code::cycle_bad_value,
             name + ": the depth Q201 is positive: the TNC stops (or, with displayDepthErr off, drills from below the "
                    "surface); toolcomp refuses it",
             column);
    const double unit_feed = prog_.inch ? 2.54 : 1.0;  // mm/min per program feed unit
    const double surface = q(203) + datum_shift_[c], clear = surface + q(200), bottom = surface + depth;
    const double end_height = surface + std::max(q(200), q(204));
    auto move = [&](double z, double feed) {  // along the tool axis
        Vec3 e = pos_;
        e[c] = z;
        if (e == pos_) return;
        Motion m = motion_to(std::isfinite(feed) ? MotionKind::line : MotionKind::rapid, e);
        m.feed = std::isfinite(feed) ? feed : std::nan("");
        put(m);
        pos_ = e;
    };
    move(clear, INFINITY);
    if (d.number == 200) {
        if (!(q(202) > 0)) fail(code::cycle_bad_value, name + ": the plunging depth Q202 must be above 0", column);
        const double feed = q(206) * unit_feed;
        double at = surface;
        for (std::size_t n = 0;; ++n) {
            if (n > 1000000) fail(code::cycle_bad_value, name + ": more than a million pecks", column);
            at = std::max(at - q(202), bottom);
            move(at, feed);
            if (at == bottom) break;
            move(clear, INFINITY);               // chips out
            move(at + q(200), INFINITY);         // back down, the set-up clearance above the last depth
        }
    } else if (d.number == 201) {
        move(bottom, q(206) * unit_feed);
        const double back = d.q.count(208) ? q(208) : 0;
        move(clear, back == 0 ? q(206) * unit_feed : back * unit_feed);
    } else {  // 207: in and out synchronised with the spindle, a pitch a revolution
        if (speed_ <= 0) fail(code::zero_spindle_speed, name + " needs the spindle speed S", column);
        const double feed = std::fabs(q(239)) * speed_;
        if (!(feed > 0)) fail(code::cycle_bad_value, name + ": the thread pitch Q239 must not be 0", column);
        move(bottom, feed);
        move(clear, feed);
    }
    move(std::max(end_height, pos_[c]), INFINITY);
}

}  // namespace toolcomp::heidenhain
