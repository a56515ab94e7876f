// The 840D's drilling cycles (see siemens_drilling.hpp), as the 840D's own cycle programs
// (the SW6 CYCLE81-CYCLE84 subprograms) make their moves; doc/sinumerik.md, "Drilling
// cycles", has the worked numbers and the choices where the manuals leave a detail open.
#include "siemens_drilling.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <optional>

#include "toolcomp/program/codes.hpp"
#include "toolcomp/program/text.hpp"
#include "turning_roughing.hpp"  // CycleError, MoveLimit

namespace toolcomp::cycles::siemens {

namespace {

constexpr std::size_t kMaxStrokes = 1'000'000;

using Args = std::function<double(std::size_t)>;

double sign(double v) { return static_cast<double>((v > 0) - (v < 0)); }

// Where a cycle's parameter list keeps the sl extensions GMODE, DMODE, AMODE (they follow
// the SW6 parameters), and the AMODE values whose meaning is the SW6 cycle's.
struct Layout {
    std::size_t sw6;  // SW6 parameters; GMODE, DMODE, AMODE at sw6, sw6 + 1, sw6 + 2
    std::vector<double> amodes;
};

const std::map<std::string, Layout>& layouts() {
    static const std::map<std::string, Layout> l{
        {"CYCLE81", {5, {0, 10}}},  {"CYCLE82", {6, {0, 10}}},
        {"CYCLE83", {17, {0, 1001110}}},
        // sl: _PITA (the pitch's unit, where SW6 has _PTAB), _PTAB, _PTABA follow the SW6 18
        {"CYCLE84", {21, {0, 1001002, 1002002}}},
        {"CYCLE840", {17, {0}}},    {"CYCLE85", {8, {0, 10}}},  {"CYCLE86", {11, {0, 10}}},
        {"CYCLE87", {6, {0, 10}}},  {"CYCLE88", {7, {0, 10}}},  {"CYCLE89", {6, {0, 10}}}};
    return l;
}

[[noreturn]] void refuse(const char* code, const std::string& message) { throw CycleError{code, message}; }

// The planes of a cycle's first five parameters.
struct Planes {
    double rtp, rfp, dp;
    double d;       // +1: drilling towards the axis's minus side
    double safety;  // RFP + SDIS towards the retraction side
};

// The planes, or nothing when RFP = DP (the cycle makes no move).
std::optional<Planes> planes(const Args& arg) {
    const double rtp = arg(0), rfp = arg(1), sdis = std::fabs(arg(2)), dpr = std::fabs(arg(4));
    double dp = arg(3);
    if (dpr != 0) {
        if (rtp == rfp) refuse(code::alarm_61101, "61101 Reference plane defined incorrectly");
        dp = rfp - sign(rtp - rfp) * dpr;
    }
    if (rfp == dp) return std::nullopt;
    const double d = sign(rfp - dp);
    if (rtp != rfp && sign(rtp - rfp) != d) refuse(code::alarm_61101, "61101 Reference plane defined incorrectly");
    return Planes{rtp, rfp, dp, d, rfp + d * sdis};
}

class Moves {
public:
    explicit Moves(std::size_t max_moves) : max_(max_moves) {}
    void put(double to, Feed how, double feed = 0, double a = 0, double b = 0) {
        if (out.size() >= max_) throw MoveLimit{};
        out.push_back({to, how, feed, a, b});
    }
    std::vector<Step> out;

private:
    std::size_t max_;
};

// CYCLE81 / CYCLE82 (the dwell at the depth is not a move): G0 to the safety plane, G1 to
// the depth at the caller's feed, G0 to the retraction plane. The first G0 is made even where
// the tool already stands below the safety plane: it moves up to it.
void drill(const Planes& p, const Setting& s, Moves& m) {
    m.put(p.safety, Feed::rapid);
    m.put(p.dp, Feed::programmed, s.feed);
    m.put(p.rtp, Feed::rapid);
}

// The first drilling depth of CYCLE83: FDPR (relative) wins over FDEP; on the far side of
// the final depth it is the final depth; on the retraction side of RFP alarm 61107.
double first_depth(const Planes& p, double fdep, double fdpr) {
    fdpr = std::fabs(fdpr);
    if (fdpr != 0) fdep = p.rfp - p.d * fdpr;
    if (fdep != p.rfp && sign(p.rfp - fdep) != p.d) refuse(code::alarm_61107, "61107 First drilling depth defined incorrectly");
    if (p.d * (fdep - p.dp) < 0) fdep = p.dp;
    return fdep;
}

// CYCLE83's next target after `cur`: DAM > 0 takes DAM off each stroke (not below DAM) and
// leaves the last strokes so that none is shorter than about DAM; DAM < 0 multiplies the
// stroke by |DAM| (not below _MDEP); DAM = 0 keeps the first stroke. The literal rules of the
// 840D's cycle, with their halvings near the bottom.
class Strokes {
public:
    Strokes(const Planes& p, double first, double dam, double mdep)
        : p_(p), dam_(dam), mdep_(mdep), stroke_(std::fabs(p.rfp - first)) {
        if (dam_ == 0) {
            dam_ = -1;
            mdep_ = stroke_;
        }
    }
    double next(double cur) {
        const double mid = (cur + p_.dp) / 2;
        if (dam_ < 0) {
            stroke_ = std::max(stroke_ * std::fabs(dam_), mdep_);
            const double nxt = cur - p_.d * stroke_;
            if (p_.d * (nxt - p_.dp) < 0) return p_.dp;
            return p_.d * (nxt - p_.dp) < mdep_ ? mid : nxt;
        }
        stroke_ = std::max(stroke_ - dam_, dam_);
        const double rest = std::fabs(cur - p_.dp);
        if (rest - stroke_ >= dam_) return rest > 2 * dam_ ? cur - p_.d * stroke_ : rest > dam_ ? mid : p_.dp;
        if (rest > stroke_) return rest > 2 * dam_ ? p_.dp + p_.d * dam_ : mid;
        return p_.dp;
    }

private:
    Planes p_;
    double dam_, mdep_, stroke_;
};

// CYCLE83(RTP, RFP, SDIS, DP, DPR, FDEP, FDPR, DAM, DTB, DTS, FRF, VARI, _AXN, _MDEP, _VRT,
// _DTD, _DIS1): the first stroke at FRF x F (FRF outside (0.001, 1]: 1; below 0.001, as an
// omitted FRF: 0.001, as the 840D's cycle does), then strokes as Strokes gives them. VARI 0
// (chip breaking): after each stroke G0 back by _VRT (<= 0: 1 mm). VARI 1 (swarf removal):
// G0 to the safety plane, G0 down again to v above the depth reached (_DIS1, or 0.6 mm up to
// a depth of 30 mm, depth / 50 beyond, at most 7 mm).
void deep_hole(const Planes& p, const Args& arg, const Setting& s, Moves& m) {
    const double vari = arg(11);
    if (vari != 0 && vari != 1) refuse(code::alarm_61002, "61002 Machining type defined incorrectly: VARI " + shortest_number(vari));
    const double frf_in = std::fabs(arg(10));
    const double frf = frf_in > 0.001 && frf_in <= 1 ? frf_in : frf_in < 0.001 ? 0.001 : 1.0;
    const double mm = 1 / s.unit;  // one millimetre in program units
    const double vrt = arg(14) > 0 ? arg(14) : mm;
    double cur = first_depth(p, arg(5), arg(6));
    Strokes strokes(p, cur, arg(7), arg(13));
    if (s.from != p.safety) m.put(p.safety, Feed::rapid);
    double k = frf;
    for (std::size_t n = 0;; ++n) {
        m.put(cur, Feed::programmed, k * s.feed);
        k = 1;
        if (cur == p.dp) break;
        const double nxt = strokes.next(cur);
        if (!(p.d * (cur - nxt) > 0) || n > kMaxStrokes)
            refuse(code::cycle_bad_value, "CYCLE83: the strokes do not reach the final depth (FDEP / FDPR, DAM and _MDEP)");
        if (vari == 1) {
            m.put(p.safety, Feed::rapid);
            const double depth = std::fabs(p.rfp - cur);
            const double v = arg(16) > 0 ? arg(16) : depth <= 30 * mm ? 0.6 * mm : std::min(depth / 50, 7 * mm);
            m.put(cur + p.d * v, Feed::rapid);
        } else {
            m.put(cur + p.d * vrt, Feed::rapid);
        }
        cur = nxt;
    }
    m.put(p.rtp, Feed::rapid);
}

// The ISO metric coarse pitches of the sizes CYCLE84's MPIT names (M3 ... M48), mm.
double metric_coarse_pitch(double size) {
    static const std::map<double, double> pitch{
        {3, 0.5},  {4, 0.7},  {5, 0.8},  {6, 1},    {8, 1.25}, {10, 1.5}, {12, 1.75}, {14, 2},   {16, 2},   {18, 2.5}, {20, 2.5},
        {22, 2.5}, {24, 3},   {27, 3},   {30, 3.5}, {33, 3.5}, {36, 4},   {39, 4},    {42, 4.5}, {45, 4.5}, {48, 5}};
    const auto it = pitch.find(size);
    return it == pitch.end() ? 0 : it->second;
}

// The thread's pitch in program units per revolution: PIT in the unit _PTAB / _PITA names
// (0: the program's, 1: mm, 2: threads per inch, 3: inch), or the metric size MPIT.
[[noreturn]] void wrong_pitch(const std::string& name, const std::string& what) {
    refuse(code::alarm_61001, "61001 Thread pitch wrong (" + name + ": " + what + ")");
}

double thread_pitch(const std::string& name, double mpit, double pit, double ptab, const Setting& s) {
    const bool inch = s.unit != 1;
    const double in = 25.4 / s.unit;  // one inch in program units
    auto wrong = [&](const std::string& what) { wrong_pitch(name, what); };
    if (ptab == 0) {
        if (pit == 0 && mpit == 0) wrong("neither PIT nor MPIT");
        if (mpit == 0) return std::fabs(pit);
        const double p = metric_coarse_pitch(std::fabs(mpit));
        if (p == 0) wrong("MPIT " + shortest_number(mpit) + " is not a metric size M3 ... M48");
        if (pit != 0 && std::fabs(pit) != p) wrong("PIT differs from the pitch of MPIT");
        return inch ? p / 25.4 : p;
    }
    if (pit == 0) wrong("PIT is 0");
    if (ptab == 1) return std::fabs(pit) / s.unit;
    if (ptab == 2) return in / std::fabs(pit);
    if (ptab == 3) return std::fabs(pit) * in;
    wrong_pitch(name, "_PTAB " + shortest_number(ptab));
}

// CYCLE84(RTP, RFP, SDIS, DP, DPR, DTB, SDAC, MPIT, PIT, POSS, SST, SST1, _AXN, _PTAB,
// _TECHNO, _VARI, _DAM, _VRT): rigid tapping, the feed the pitch times the speed (SST in,
// SST1 out; 0: SST). G0 to the safety plane (where the tool is not there), in to DP and out
// to the safety plane; _VARI 1 / 2 in strokes of _DAM (0: |DP|), backing off by _VRT (1) or out to the safety plane and in again to _VRT above (2).
void rigid_tapping(const Planes& p, const Args& arg, const Setting& s, Moves& m) {
    const double vari = std::fmod(arg(15), 10);
    if (vari < 0 || vari > 2 || vari != std::floor(vari))
        refuse(code::alarm_61002, "61002 Machining type defined incorrectly: _VARI " + shortest_number(arg(15)));
    const double pitch = thread_pitch("CYCLE84", arg(7), arg(8), arg(13), s);
    const double sst = arg(10), sst1 = arg(11) > 0 ? arg(11) : sst;
    if (!(sst > 0)) refuse(code::cycle_bad_value, "CYCLE84: the tapping speed SST must be above 0");
    const double in = pitch * sst * s.unit, out = pitch * sst1 * s.unit;  // mm/min
    if (s.from != p.safety) m.put(p.safety, Feed::rapid);
    if (vari == 0) {
        m.put(p.dp, Feed::per_minute, in);
    } else {
        const double dam = arg(16) != 0 ? std::fabs(arg(16)) : std::fabs(arg(3));
        const double vrt = arg(17) > 0 ? arg(17) : 1 / s.unit;
        double cur = p.rfp - p.d * dam;
        if (p.d * (cur - p.dp) < 0) refuse(code::alarm_61809, "61809 Drilling position not permissible");
        for (std::size_t n = 0;; ++n) {
            m.put(cur, Feed::per_minute, in);
            if (cur == p.dp) break;
            // strokes of _DAM; the last two share what is left when it is under two strokes
            const double rest = std::fabs(cur - p.dp);
            const double nxt = rest >= 2 * dam ? cur - p.d * dam : rest > dam ? (cur + p.dp) / 2 : p.dp;
            if (!(p.d * (cur - nxt) > 0) || n > kMaxStrokes)
                refuse(code::cycle_bad_value, "CYCLE84: the strokes do not reach the final depth (_DAM)");
            if (vari == 2) {
                m.put(p.safety, Feed::per_minute, out);
                m.put(cur + p.d * vrt, Feed::per_minute, out);
            } else {
                m.put(cur + p.d * vrt, Feed::per_minute, out);
            }
            cur = nxt;
        }
    }
    m.put(p.safety, Feed::per_minute, out);
    m.put(p.rtp, Feed::rapid);
}

// CYCLE840(RTP, RFP, SDIS, DP, DPR, DTB, SDR, SDAC, ENC, MPIT, PIT, _AXN, _PTAB, _TECHNO):
// tapping with a compensating chuck: in to DP and out to the safety plane at the feed the
// pitch (MPIT / PIT) times the spindle's speed gives, or without a pitch at the caller's F.
void chuck_tapping(const Planes& p, const Args& arg, const Setting& s, double speed, Moves& m) {
    m.put(p.safety, Feed::rapid);
    if (arg(9) != 0 || arg(10) != 0) {
        const double pitch = thread_pitch("CYCLE840", arg(9), arg(10), arg(12), s);
        if (!(speed > 0)) refuse(code::cycle_bad_value, "CYCLE840: the feed is the pitch times the spindle speed, and S is 0");
        m.put(p.dp, Feed::per_minute, pitch * speed * s.unit);
        m.put(p.safety, Feed::per_minute, pitch * speed * s.unit);
    } else {
        m.put(p.dp, Feed::programmed, s.feed);
        m.put(p.safety, Feed::programmed, s.feed);
    }
    m.put(p.rtp, Feed::rapid);
}

void spindle_direction(const std::string& name, double sdir) {
    if (sdir != 3 && sdir != 4) refuse(code::alarm_61102, "61102 No spindle direction programmed (" + name + ": SDIR " + shortest_number(sdir) + ")");
}

// The boring cycles: G0 to the safety plane, G1 to the depth, then out:
// CYCLE85(..., DTB, FFR, RFF)  in at FFR, out to the safety plane at RFF, G0 to RTP;
// CYCLE86(..., DTB, SDIR, RPA, RPO, RPAP, POSS)  oriented stop, G0 lift-off by RPA, RPO in the
//   plane and RPAP along the axis, G0 to the safety plane, G0 to RTP and the hole's centre;
// CYCLE87(..., SDIR) / CYCLE88(..., DTB, SDIR)  spindle and program stop (M5 M0), G0 to RTP;
// CYCLE89(..., DTB)  out to the safety plane at the feed it went in, G0 to RTP.
void boring(const std::string& name, const Planes& p, const Args& arg, const Setting& s, Moves& m) {
    if (name == "CYCLE86" || name == "CYCLE88") spindle_direction(name, arg(6));
    if (name == "CYCLE87") spindle_direction(name, arg(5));
    m.put(p.safety, Feed::rapid);
    if (name == "CYCLE85") {
        m.put(p.dp, Feed::programmed, arg(6) * s.feed_unit);
        m.put(p.safety, Feed::programmed, arg(7) * s.feed_unit);
    } else if (name == "CYCLE86") {
        m.put(p.dp, Feed::programmed, s.feed);
        const double a = arg(7), b = arg(8), up = p.dp + arg(9);
        m.put(up, Feed::rapid, 0, a, b);
        m.put(p.safety, Feed::rapid, 0, a, b);
    } else if (name == "CYCLE89") {
        m.put(p.dp, Feed::programmed, s.feed);
        m.put(p.safety, Feed::programmed, s.feed);
    } else {
        m.put(p.dp, Feed::programmed, s.feed);
    }
    m.put(p.rtp, Feed::rapid);
}

}  // namespace

bool is_drilling_cycle(const std::string& name) { return layouts().count(name) != 0; }

std::size_t parameter_count(const std::string& name) { return layouts().at(name).sw6 + 3; }

int drilling_axis(const std::string& name, const std::vector<double>& args) {
    if (name != "CYCLE83" && name != "CYCLE84" && name != "CYCLE840") return 0;
    const std::size_t at = name == "CYCLE840" ? 11 : 12;
    const double axn = at < args.size() ? args[at] : 0;
    return axn == 1 ? 1 : axn == 2 ? 2 : 0;
}

std::vector<Step> drilling(const std::string& name, const std::vector<double>& args, const Setting& s) {
    const Args arg = [&](std::size_t i) { return i < args.size() ? args[i] : 0.0; };
    const Layout& l = layouts().at(name);
    if (arg(l.sw6) != 0) refuse(code::unsupported_word, name + " with GMODE " + shortest_number(arg(l.sw6)) + " is not supported by toolcomp");
    if (arg(l.sw6 + 1) != 0) refuse(code::unsupported_word, name + " with DMODE " + shortest_number(arg(l.sw6 + 1)) + " is not supported by toolcomp");
    if (std::find(l.amodes.begin(), l.amodes.end(), arg(l.sw6 + 2)) == l.amodes.end())
        refuse(code::unsupported_word, name + " with AMODE " + shortest_number(arg(l.sw6 + 2)) + " is not supported by toolcomp");
    const std::optional<Planes> p = planes(arg);
    Moves m(s.max_moves);
    if (!p) return {};
    if (name == "CYCLE81" || name == "CYCLE82") drill(*p, s, m);
    else if (name == "CYCLE83") deep_hole(*p, arg, s, m);
    else if (name == "CYCLE84") rigid_tapping(*p, arg, s, m);
    else if (name == "CYCLE840") chuck_tapping(*p, arg, s, s.speed, m);
    else boring(name, *p, arg, s, m);
    return std::move(m.out);
}

}  // namespace toolcomp::cycles::siemens
