// The TNC's cycles (CYCL DEF, CYCL CALL): 7 DATUM SHIFT, 9 DWELL, 32 TOLERANCE, and the
// drilling cycles 200 DRILLING, 201 REAMING and 207 RIGID TAPPING: CYCL DEF stores a drilling
// cycle with its Q parameters (which are Q parameters of the program from then on), CYCL
// CALL and M99 (at the end of its block) run it where the tool stands. Along the tool axis,
// from the surface S = Q203 (from the datum): the set-up clearance S + Q200, the depth S +
// Q201 (negative: into the workpiece), the 2nd set-up clearance S + Q204; the cycle ends at
// the higher of the two clearances.
#include <cmath>
#include <string>

#include "interp.hpp"
#include "toolcomp/program/codes.hpp"
#include "toolcomp/program/text.hpp"

namespace toolcomp::heidenhain {

namespace {

// The parameters each cycle needs, in the order the TNC writes them.
const std::vector<int>& needed(int cycle) {
    static const std::vector<int> k200{200, 201, 206, 202, 203, 204}, k201{200, 201, 206, 203, 204},
        k207{200, 201, 239, 203, 204};
    return cycle == 200 ? k200 : cycle == 201 ? k201 : k207;
}

}  // namespace

// CYCL DEF 32 TOLERANCE (32.0, 32.1 T.., 32.2 HSC-MODE TA): a tolerance of the executed
// path, accepted with a note; every other cycle is refused by its number.
void Interp::cycle(Tokens t) {
    const bool def = t.size() >= 3 && t[1].is("DEF") && t[2].key.empty() && t[2].has_value;
    if (def && t[2].value >= 7 && t[2].value < 8) return datum_shift(t);
    if (def && (t[2].value == 200 || t[2].value == 201 || t[2].value == 207))
        return define_drilling(t, static_cast<int>(t[2].value));
    if (def && t[2].value >= 9 && t[2].value < 10) return;  // DWELL TIME: no motion
    if (t.size() >= 2 && t[1].is("CALL") && std::all_of(t.begin() + 2, t.end(), [](const Token& k) { return k.is("M"); })) {
        modal_words(t, 2);  // CYCL CALL M3 ...
        cycle_call_pending_ = false;
        return call_cycle(t[0].column);
    }
    if (def && t[2].value >= 32 && t[2].value < 33) {
        if (!tolerance_noted_)
            diags_.push_back({code::blending_not_modelled, Severity::info,
                              "CYCL DEF 32 TOLERANCE is a tolerance of the executed path: toolcomp returns the "
                              "programmed path",
                              {line_, t[0].column}});
        tolerance_noted_ = true;
        return;
    }
    std::string what = "CYCL";
    for (std::size_t i = 1; i < t.size() && (t[i].key.empty() ? t[i].has_value : !t[i].has_value && t[i].key[0] != 'Q'); ++i)
        what += " " + (t[i].key.empty() ? shortest_number(t[i].value) : t[i].key);  // CYCL DEF 205 UNIVERSAL PECKING
    fail(code::unsupported_block, what + " is not supported by toolcomp yet", t[0].column);
}

// CYCL DEF 7.0 DATUM SHIFT, then 7.1 X.. / 7.2 Y.. / 7.3 Z.. (IX.. adds to the shift in force;
// an axis not named keeps its shift; X+0 takes it back). A row of a datum table (#n) is
// refused: toolcomp reads no datum tables.
void Interp::datum_shift(Tokens t) {
    static constexpr std::string_view names[3] = {"X", "Y", "Z"};
    static constexpr std::string_view inc[3] = {"IX", "IY", "IZ"};
    for (std::size_t i = 3; i < t.size(); ++i) {
        const Token& k = t[i];
        bool axis = false;
        for (int a = 0; a < 3; ++a) {
            if (k.is(names[a]) && k.has_value) datum_shift_[a] = k.value, axis = true;
            if (k.is(inc[a]) && k.has_value) datum_shift_[a] += k.value, axis = true;
        }
        if (axis) continue;
        if (t[2].value == 7 && !k.has_value) continue;  // 7.0 DATUM SHIFT: the cycle's name
        fail(code::unsupported_word,
             std::string(k.key.empty() ? "#" : k.key) + " in CYCL DEF 7: toolcomp shifts the datum by X, Y, Z values "
                                                         "(IX, IY, IZ); datum tables are not read",
             k.column);
    }
}

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
