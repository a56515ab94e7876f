// The TNC's cycles (CYCL DEF, CYCL CALL): the transformations 7, 8, 10, 11, 26, 247
// (interp_transform.cpp), 9 DWELL, 19 WORKING PLANE (interp_plane.cpp), 32 TOLERANCE, the old
// 1 PECKING and 17 RIGID TAPPING, the drilling cycles 200, 201, 203, 205, 207 and 208 BORE
// MILLING. CYCL DEF stores a machining cycle with its Q parameters
// (which are Q parameters of the program from then on); CYCL CALL, M99 (at the end of its
// block) and M89 (after every positioning block until cancelled) run it where the tool
// stands; CYCL CALL POS, CYCL CALL PAT and the pattern cycles 220 / 221 run it elsewhere
// (interp_patterns.cpp). The moves along the tool axis are cycles/tnc_drilling.cpp's.
#include <cmath>
#include <string>

#include "../../cycles/tnc_drilling.hpp"
#include "../../cycles/turning_roughing.hpp"  // CycleError
#include "interp.hpp"
#include "toolcomp/geometry/arc.hpp"
#include "toolcomp/program/codes.hpp"
#include "toolcomp/program/text.hpp"

namespace toolcomp::heidenhain {

namespace {

bool in(const Token& k, double from, double to) { return k.key.empty() && k.has_value && k.value >= from && k.value < to; }

// The numbered line of an old cycle's definition: 1.3 -> 3 (0 for 1.0, the cycle's name).
int sub_number(double v) { return static_cast<int>(std::lround((v - std::floor(v)) * 10)); }

}  // namespace

// CYCL DEF 9.1 DWELL 1.5 (V.ZEIT in the German dialogue): no motion; the seconds count in the
// run's time.
void Interp::dwell(Tokens t) {
    if (t[2].value == std::floor(t[2].value)) return;  // 9.0 names the cycle
    for (std::size_t i = 3; i < t.size(); ++i)
        if (t[i].has_value) {
            dwell_seconds_ += std::max(0.0, t[i].value);
            return;
        }
}

void Interp::cycle(Tokens t) {
    const bool def = t.size() >= 3 && t[1].is("DEF");
    if (t.size() >= 2 && t[1].is("CALL")) return cycle_call(t);
    if (def && in(t[2], 7, 8)) return datum_shift(t);
    if (def && in(t[2], 8, 9)) return mirror_image(t);
    if (def && in(t[2], 10, 11)) return rotation(t);
    if (def && in(t[2], 11, 12)) return scaling(t);
    if (def && in(t[2], 26, 27)) return axis_scaling(t);
    if (def && in(t[2], 9, 10)) return dwell(t);
    if (def && in(t[2], 19, 20)) return working_plane(t);
    if (def && in(t[2], 32, 33)) {
        if (!tolerance_noted_)
            diags_.push_back({code::blending_not_modelled, Severity::info,
                              "CYCL DEF 32 TOLERANCE is a tolerance of the executed path: toolcomp returns the "
                              "programmed path",
                              {line_, t[0].column}});
        tolerance_noted_ = true;
        return;
    }
    if (def && (in(t[2], 1, 2) || in(t[2], 17, 18))) return define_old_cycle(t);
    if (def && t[2].key.empty() && t[2].has_value) {
        const double n = t[2].value;
        if (machine_ && n == std::floor(n) && machine_->cycle(static_cast<int>(n))) return builder_cycle(t);
        if (cycles::tnc::is_drilling(static_cast<int>(n)) || n == 208) return define_machining(t, static_cast<int>(n));
        if (n == 220 || n == 221) return pattern_cycle(t, static_cast<int>(n));
        if (n == 247) return datum_setting(t);
    }
    std::string what = "CYCL";
    for (std::size_t i = 1; i < t.size() && (t[i].key.empty() ? t[i].has_value : !t[i].has_value && t[i].key[0] != 'Q'); ++i)
        what += " " + (t[i].key.empty() ? shortest_number(t[i].value) : t[i].key.str());  // CYCL DEF 251 RECTANGULAR POCKET
    fail(code::unsupported_block, what + " is not supported by toolcomp yet", t[0].column);
}

// CYCL CALL [M..], CYCL CALL POS X.. Y.. Z.. [F|FMAX] [M..], CYCL CALL PAT [F|FMAX] [M..]: a
// call ends a modal call (M89).
void Interp::cycle_call(Tokens t) {
    modal_call_ = false;
    if (t.size() >= 3 && t[2].is("POS")) return call_at_position(t);
    if (t.size() >= 3 && t[2].is("PAT")) return call_pattern(t);
    for (std::size_t i = 2; i < t.size(); ++i)
        if (!t[i].is("M")) fail(code::bad_word, t[i].key + " is not read in CYCL CALL blocks", t[i].column);
    modal_words(t, 2);  // CYCL CALL M3 ...
    cycle_call_pending_ = false;
    call_cycle(t[0].column);
}

// A builder cycle of the machine (CYCL DEF 392 ATC on DMG machines): its Q parameters are the
// program's; it does not move the tool.
void Interp::builder_cycle(Tokens t) {
    for (const auto& [n, v] : cycle_parameters(t))
        if (std::isfinite(v)) q_[n] = v;
}

// The Q parameters of a cycle's definition (Q200=+2 ...; Q208=MAX or FMAX: +inf), by number.
// The words of the cycle's name pass (DRILLING, BOHREN, ...); a value outside a Q parameter,
// or a keyword toolcomp does not read (FAUTO, PREDEF), is refused.
std::map<int, double> Interp::cycle_parameters(Tokens t) const {
    std::map<int, double> q;
    for (std::size_t i = 3; i < t.size(); ++i) {
        const Token& k = t[i];
        const bool parameter = k.key.size() >= 2 && k.key[0] == 'Q' && k.key.find_first_not_of("0123456789", 1) == std::string::npos;
        if (!parameter) {
            if (k.has_value || k.key.empty())
                fail(code::bad_word, (k.key.empty() ? std::string("A number") : k.key.str()) + " is not read in a cycle definition",
                     k.column);
            continue;
        }
        const int n = std::stoi(k.key.substr(1));
        if (k.has_value) q[n] = k.value;
        else if (k.text == "MAX" || k.text == "FMAX") q[n] = INFINITY;
        else fail(code::unsupported_word, "Q" + std::to_string(n) + "=" + k.text + " is not supported by toolcomp", k.column);
    }
    return q;
}

// A machining cycle: its Q parameters, the ones it needs checked.
void Interp::define_machining(Tokens t, int number) {
    CycleDef def;
    def.number = number;
    def.q = cycle_parameters(t);
    for (int n : cycles::tnc::required_q(number))
        if (!def.q.count(n))
            fail(code::cycle_q_missing, "CYCL DEF " + std::to_string(number) + ": Q" + std::to_string(n) + " missing",
                 t[2].column);
    for (const auto& [n, v] : def.q)
        if (std::isfinite(v)) q_[n] = v;  // the cycle's parameters are the program's Q parameters too
    cycle_def_ = std::move(def);
    modal_call_ = false;  // a new machining cycle ends M89
}

// CYCL DEF 1.0 PECKING / 17.0 RIGID TAPPING starts the definition; its numbered lines (1.1
// SET UP 2, 1.2 DEPTH -15, ...: the value is the line's number, whatever the dialog's word)
// complete it.
void Interp::define_old_cycle(Tokens t) {
    const int number = static_cast<int>(t[2].value), sub = sub_number(t[2].value);
    const int last = number == 1 ? 5 : 3;
    if (sub == 0) {
        cycle_def_ = CycleDef{number, {}};
        modal_call_ = false;
        return;
    }
    if (!cycle_def_ || cycle_def_->number != number || sub > last)
        fail(code::unsupported_block, "CYCL DEF " + shortest_number(t[2].value) + " without CYCL DEF " +
                                          std::to_string(number) + ".0 before it",
             t[2].column);
    const Token* value = nullptr;
    for (std::size_t i = 3; i < t.size(); ++i)
        if (t[i].has_value) value = &t[i];
    if (!value) fail(code::cycle_q_missing, "CYCL DEF " + shortest_number(t[2].value) + " needs a value", t[2].column);
    cycle_def_->q[sub] = value->value;
}

void Interp::call_cycle(int column, double surface_shift, std::optional<double> end_height) {
    if (!cycle_def_) fail(code::unsupported_block, "CYCL CALL without a cycle defined (CYCL DEF)", column);
    const CycleDef& d = *cycle_def_;
    const std::string name = "CYCL DEF " + std::to_string(d.number);
    if (side_ != 0) fail(code::comp_canned_cycle, name + " called with RL/RR: the cycle needs R0", column);
    const int c = axes(plane_).c;
    cycles::tnc::Setting s;
    s.from = pos_[c];
    s.feed_unit = prog_.inch ? 2.54 : 1.0;  // mm/min per program feed unit
    s.unit = unit_;
    s.speed = speed_;
    s.max_moves = profile_.block_limit - std::min(executed_, profile_.block_limit);
    std::vector<cycles::tnc::AxialMove> moves;
    try {
        if (d.number == 1 || d.number == 17) {
            for (int n = 1; n <= (d.number == 1 ? 5 : 3); ++n)
                if (!d.q.count(n))
                    fail(code::cycle_q_missing, name + "." + std::to_string(n) + " missing", column);
            moves = d.number == 1 ? cycles::tnc::pecking_1(d.q, s) : cycles::tnc::tapping_17(d.q, s);
        } else {
            const double depth = d.q.at(201);
            if (depth == 0) return;  // the TNC does not run the cycle
            if (depth > 0)
                fail(code::cycle_bad_value,
                     name + ": the depth Q201 is positive: the TNC stops (or, with displayDepthErr off, drills from "
                            "below the surface); toolcomp refuses it",
                     column);
            s.surface = d.q.at(203) + surface_shift;
            if (d.number == 208) {
                refuse_scaled("CYCL DEF 208", column);
                count_moves(6, column);
                return bore_milling(cycles::tnc::bore_milling(d.q, s, radius_), end_height);
            }
            moves = cycles::tnc::drilling(d.number, d.q, s);
            if (end_height) moves.back().to = *end_height;
        }
    } catch (const cycles::MoveLimit&) {
        block_limit_exceeded(column);
    } catch (const cycles::CycleError& e) {
        fail(e.code, e.message, column);
    }
    count_moves(moves.size(), column);
    for (const auto& m : moves) axis_move(m.to, m.feed);
}

void Interp::count_moves(std::size_t moves, int column) {
    executed_ += moves;
    if (executed_ > profile_.block_limit) block_limit_exceeded(column);
}

void Interp::block_limit_exceeded(int column) const {
    fail(code::block_limit, "More than " + std::to_string(profile_.block_limit) +
                                " blocks executed, cycle moves included: an endless loop? (ControlProfile.block_limit)",
         column);
}

// A straight move of a cycle to `e` at `feed` mm/min (+inf: FMAX); none where the tool is.
void Interp::straight_to(const Vec3& e, double feed) {
    if (e == pos_) return;
    Motion m = motion_to(std::isfinite(feed) ? MotionKind::line : MotionKind::rapid, e);
    m.feed = std::isfinite(feed) ? feed : std::nan("");
    put(m);
    pos_ = e;
}

void Interp::axis_move(double to, double feed) {
    Vec3 e = pos_;
    e[axes(plane_).c] = to;
    straight_to(e, feed);
}

// 208: down to the set-up clearance; a half circle out to the helix's start (at angle 0 from
// the centre, the helix's sense); the helix to the depth; a full circle there; back to the
// centre; out to the end height at FMAX.
void Interp::bore_milling(const cycles::tnc::BoreMilling& b, std::optional<double> end_height) {
    const int c = axes(plane_).c;
    axis_move(b.top, INFINITY);
    if (b.radius == 0) {
        axis_move(b.bottom, b.feed);
    } else {
        const Vec2 centre = plane2(pos_);
        const MotionKind sense = b.dir > 0 ? MotionKind::arc_ccw : MotionKind::arc_cw;
        auto arc = [&](const Vec2& to, const Vec2& about, double height, std::int32_t turns) {
            Vec3 e = with_plane(pos_, to);
            e[c] = height;
            Motion m = motion_to(sense, e);
            m.feed = b.feed;
            m.center = with_plane(pos_, about);
            m.turns = turns;
            put(m);
            pos_ = e;
        };
        const Vec2 start = centre + Vec2(b.radius, 0);
        arc(start, centre + Vec2(b.radius / 2, 0), b.top, 0);
        // The helix: whole turns, and what is left of the last one.
        const double whole = std::floor(b.turns + 1e-9), rest = b.turns - whole;
        const double angle = b.dir * 2 * kPi * (rest < 1e-9 ? 0 : rest);
        const auto turns = static_cast<std::int32_t>(rest < 1e-9 ? whole - 1 : whole);
        const Vec2 end = centre + b.radius * Vec2(std::cos(angle), std::sin(angle));
        arc(end, centre, b.bottom, std::max(turns, 0));
        arc(end, centre, b.bottom, 0);  // the full circle at the depth
        plane_move(centre, b.feed);
    }
    axis_move(end_height.value_or(b.end), INFINITY);
}

}  // namespace toolcomp::heidenhain
