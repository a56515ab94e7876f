// One Sinumerik block, step by step in the control's order: its G functions by group and
// its keywords (one function of a group per block, alarm 12190 otherwise), units first (the
// block's own values follow them), feed and speed, the tool (T, M6, D), plane and
// dimensions, the radius compensation request, frames and work offsets, the motion (or G4),
// the words left unused, stop and end. Each step is one call below.
#include <cmath>

#include "codes.hpp"
#include "interp.hpp"
#include "toolcomp/program/codes.hpp"
#include "toolcomp/program/int_value.hpp"

namespace toolcomp::sinumerik {

namespace {

bool is_frame_word(const std::string& k) {
    return k == "TRANS" || k == "ATRANS" || k == "ROT" || k == "AROT" || k == "SCALE" || k == "ASCALE" ||
           k == "MIRROR" || k == "AMIRROR";
}

}  // namespace

void Interp::execute(BlockData& b, int first_column) {
    BlockCodes c = g_functions(b);
    keyword_functions(b, c, first_column);
    if (c.units >= 0) {
        st_.inch = c.units == G70 || c.units == G700;
        st_.inch_feed = c.units == G700;
    }
    set_feed_and_speed(b, c);
    if (b.has('T')) select_tool(b);
    m_functions(b, c);
    tool_change(b, c, first_column);
    set_plane_and_dimensions(b, c, first_column);
    set_radius_comp(b, c, first_column);
    frame_functions(b, c, first_column);
    const bool moved = motion(b, c, first_column);
    check_unused_words(b, moved);
    stop_and_end(b, c);
}

// ---- what the block selects ---------------------------------------------------------------

BlockCodes Interp::g_functions(const BlockData& b) {
    BlockCodes c;
    auto setg = [&](int& slot, int g, int column) {
        if (slot >= 0 && slot != g)
            fail(code::alarm_12190, "12190 G functions G" + std::to_string(slot) + " and G" + std::to_string(g) +
                              " of the same group in one block", column);
        slot = g;
    };
    for (auto [g, column] : b.g) {
        switch (g) {
            case G0: case G1: case G2: case G3: setg(c.motion, g, column); break;
            case G17: case G18: case G19: setg(c.plane, g, column); break;
            case G40: case G41: case G42: setg(c.comp, g, column); break;
            case G450: case G451: setg(c.corner, g, column); break;
            case G90: case G91: setg(c.dist, g, column); break;
            case G70: case G71: case G700: case G710: setg(c.units, g, column); break;
            case G4: case G9: case G53: case G153: case G25: case G26: case G58: case G59: setg(c.nonmodal, g, column); break;
            case G500: case G54: case G55: case G56: case G57: setg(c.workoffset, g, column); break;
            case G94: case G95: case G96: case G97: setg(c.feedmode, g, column); break;
            case G60: case G64: case G601: case G602: case G603: break;
            case G641: case G642: case G643: case G644: case G645: blending_note(g, column); break;
            default:
                if (g >= G505 && g <= G599) {
                    setg(c.workoffset, g, column);
                    break;
                }
                fail(code::unsupported_g_code, "G" + std::to_string(g) + " is not supported by toolcomp", column);
        }
    }
    c.machine = c.nonmodal == G53 || c.nonmodal == G153;
    return c;
}

// G641-G645 round the corners within a tolerance of the executed path: said once a run.
void Interp::blending_note(int g, int column) {
    if (warned_blending_) return;
    info(code::blending_not_modelled, "G" + std::to_string(g) +
         " corner rounding is a tolerance of the executed path; toolcomp returns the programmed path", column);
    warned_blending_ = true;
}

// CIP, CT, SUPA and the frame instruction of the block (one).
void Interp::keyword_functions(const BlockData& b, BlockCodes& c, int first_column) const {
    for (const auto& [k, column] : b.keywords) {
        if (k == "CIP") c.cip = true;
        else if (k == "CT") c.ct = true;
        else if (k == "SUPA") c.machine = true;
        else if (is_frame_word(k)) {
            if (!c.frame_word.empty()) fail(code::alarm_12190, "12190 Two frame instructions in one block", column);
            c.frame_word = k;
            c.frame_column = column;
        }
    }
    if ((c.cip || c.ct) && c.motion >= 0)
        fail(code::alarm_12190, "12190 CIP/CT and G" + std::to_string(c.motion) + " in one block", first_column);
    if (c.cip && c.ct) fail(code::alarm_12190, "12190 CIP and CT in one block", first_column);
}

// M0/M1 stop, M2/M30 end, M17 return, M6 tool change.
void Interp::m_functions(const BlockData& b, BlockCodes& c) const {
    for (auto [m, column] : b.m) {
        if (m == M6) c.m6 = true;
        else if (m == M0 || m == M1) c.stop = true;
        else if (m == M2 || m == M30) c.end = true;
        else if (m == M17) c.sub_end = true;
        else if (m < 0) fail(code::unsupported_m_code, "M" + std::to_string(m) + " is not an M function", column);
    }
}

// ---- the steps -------------------------------------------------------------------------------

// F, LIMS=, the feed mode and S: G96's S is the cutting speed (m/min), else rev/min; G97
// keeps the speed G96 had reached where the tool stands. Under G4, F and S are its time.
void Interp::set_feed_and_speed(const BlockData& b, const BlockCodes& c) {
    if (b.has('F') && c.nonmodal != G4) feed_ = b['F'].v * (st_.inch_feed ? kMmPerInch : 1.0);
    if (b.lims.set) {
        if (!(b.lims.v > 0)) fail(code::unused_word, "LIMS= is the spindle speed limit of G96 (rev/min): above 0", b.lims.column);
        lims_ = b.lims.v;
    }
    if (c.feedmode == G97 && st_.feed_mode == G96) {
        const double rpm = css_speed(pos_.x());
        if (std::isfinite(rpm)) speed_ = rpm;
        st_.feed_mode = G95;
    } else if (c.feedmode >= 0 && c.feedmode != G97) {
        st_.feed_mode = c.feedmode;
    }
    if (b.has('S') && c.nonmodal != G4) {
        if (b['S'].v < 0) fail(code::negative_spindle_speed, "Negative spindle speed S", b['S'].column);
        (st_.feed_mode == G96 ? cutting_speed_ : speed_) = b['S'].v;
    }
}

// M6 (never under radius compensation), then D: the edge.
void Interp::tool_change(const BlockData& b, const BlockCodes& c, int first_column) {
    if (c.m6) {
        if (st_.side != 0) fail(code::alarm_10750, "10750 Tool change with active TRC", first_column);
        change_tool();
    }
    if (b.has('D')) {
        const Value& d = b['D'];
        if (d.v != std::floor(d.v) || d.v < 0 || d.v > 32000) fail(code::alarm_17180, "17180 Illegal D number", d.column);
        select_edge(int_value(d.v), d.column);
    }
}

// G17-G19, G90/G91, DIAMON/DIAMOF/DIAM90, NORM/KONT, CDON/CDOF, G450/G451, DISC=, OFFN=,
// TCARR=.
void Interp::set_plane_and_dimensions(const BlockData& b, const BlockCodes& c, int first_column) {
    if (c.plane >= 0) {
        const Plane p = c.plane == G17 ? Plane::xy : c.plane == G18 ? Plane::zx : Plane::yz;
        if (p != st_.plane && st_.side != 0)
            fail(code::alarm_10757, "10757 Change of the compensation plane with active TRC", first_column);
        st_.plane = p;
        update_tool_offset();
    }
    if (c.dist >= 0) st_.incremental = c.dist == G91;
    for (const auto& [k, column] : b.keywords) {
        if (k == "DIAMON") st_.diameter = true, diam90_ = false;
        else if (k == "DIAMOF") st_.diameter = false, diam90_ = false;
        else if (k == "DIAM90") st_.diameter = false, diam90_ = true;
        else if (k == "NORM") st_.entry = EntryStyle::perpendicular_to_next;
        else if (k == "KONT") st_.entry = EntryStyle::around_start_when_behind;
        else if (k == "CDON") st_.gouge = GougeReaction::skip;
        else if (k == "CDOF" || k == "CDOF2") st_.gouge = GougeReaction::error;
        // TCOABS: the holder angles $TC_CARR13/14 are the only source toolcomp models (TCOFR is refused).
    }
    if (c.corner >= 0) st_.outside = c.corner == G450 ? OutsideCorner::arc : OutsideCorner::intersection;
    if (b.disc.set) {
        if (b.disc.v < 0 || b.disc.v > 100) fail(code::alarm_14800, "14800 DISC value outside 0..100", b.disc.column);
        st_.disc = b.disc.v;
    }
    if (b.offn.set) st_.offn = b.offn.v * unit();
    if (b.tcarr.set) {
        if (!(b.tcarr.v >= 0 && b.tcarr.v <= 99999))
            fail(code::alarm_14153, "14153 TCARR= toolholder number out of range", b.tcarr.column);
        tcarr_ = int_value(b.tcarr.v);
        update_tool_offset();
    }
}

// G40/G41/G42: selected and deselected in a straight block only.
void Interp::set_radius_comp(const BlockData& b, const BlockCodes& c, int first_column) {
    if (c.comp < 0) return;
    const int side = c.comp == G41 ? 1 : c.comp == G42 ? -1 : 0;
    const bool circle = c.motion == G2 || c.motion == G3 || c.cip || c.ct;
    if (side != 0 && tool_ == 0)
        fail(code::alarm_10750, "10750 Tool radius compensation activated without a tool number", first_column);
    if (side != 0 && d_ == 0)
        diags_.push_back({code::comp_d0, Severity::warning,
                          "G" + std::to_string(c.comp) + " with D0: no tool radius compensation", {line_, first_column}});
    if (side != 0 && (circle || (c.motion < 0 && st_.motion >= G2)) && st_.side == 0)
        fail(code::alarm_10753, "10753 TRC selection only possible in a linear block", first_column);
    // G40 in a block that moves on a circle; G40 alone takes effect with the next move
    const bool moves = b.has('X') || b.has('Y') || b.has('Z');
    if (side == 0 && st_.side != 0 && (circle || (c.motion < 0 && moves && st_.motion >= G2)))
        fail(code::alarm_10754, "10754 TRC deselection only possible in a linear block", first_column);
    if (side == 0 && st_.side != 0) sink_.control({ControlKind::radius_off, line_, Vec3::Zero(), file()});
    st_.side = side;
}

// G500, G54..G57, G505..G599: the settable frame of that number ($P_UIFR[n], neutral until
// the program writes it: see interpreter.hpp); G58/G59 and the frame instructions, each in a
// block of its own.
void Interp::frame_functions(const BlockData& b, const BlockCodes& c, int first_column) {
    if (c.workoffset >= 0)
        select_settable(c.workoffset == G500 ? 0 : c.workoffset < G500 ? c.workoffset - G53 : c.workoffset - G500);
    if (c.nonmodal == G58 || c.nonmodal == G59) {
        if (!c.frame_word.empty() || c.motion >= 0)
            fail(code::alarm_12190, "12190 G" + std::to_string(c.nonmodal) + " must be programmed in a block of its own", first_column);
        programmable_offset(b, c.nonmodal, first_column);
    } else if (!c.frame_word.empty()) {
        if (c.motion >= 0)
            fail(code::alarm_12190, "12190 " + c.frame_word + " must be programmed in a block of its own", c.frame_column);
        frame_statement(b, c.frame_word, c.frame_column);
    } else if (b.rpl.set) {
        fail(code::syntax_error, "RPL= without ROT or AROT", b.rpl.column);
    }
}

// The motion mode, then G4 or the block's move. True when the block moved.
bool Interp::motion(const BlockData& b, const BlockCodes& c, int first_column) {
    if (c.motion >= 0) st_.motion = c.motion;
    if (c.cip) st_.motion = CIP;
    if (c.ct) st_.motion = CT;
    const bool axes = b.has('X') || b.has('Y') || b.has('Z');
    const bool rotary = b.has('A') || b.has('B') || b.has('C');
    const bool data_axes = !c.frame_word.empty() || c.nonmodal == G25 || c.nonmodal == G26 || c.nonmodal == G58 ||
                           c.nonmodal == G59;
    const bool arc_words = b.has('I') || b.has('J') || b.has('K') || b.cr.set || b.ar.set || b.i1.set || b.j1.set ||
                           b.k1.set || b.turn.set;
    if (arc_words && st_.motion < G2)
        fail(code::unused_word, "I, J, K, CR=, AR=, I1=, TURN= need G2, G3, CIP or CT", first_column);
    if (c.nonmodal == G4) {
        dwell(b, c, first_column);
        return false;
    }
    if (data_axes || !(axes || rotary || (st_.motion >= G2 && arc_words))) return false;
    corner_request(b, first_column);
    const std::array<double, 3> abc = rotary_targets(b);
    if (st_.motion >= G2) {
        if (c.machine) fail(code::g53_motion, "G53/G153/SUPA only with G0 or G1", first_column);
        const Vec3 e = end_point(b, false);
        abc_ = abc;
        arc(b, e);
    } else {
        const Vec3 e = end_point(b, c.machine);
        const Vec3 out = c.machine ? Vec3(e - work_origin_) : actual_.apply(e) + zero_shift_;
        abc_ = abc;
        if (st_.motion == G1 && !(feed_ > 0)) fail(code::alarm_10860, "10860 No feedrate programmed", first_column);
        Motion m = motion_(st_.motion == G0 ? MotionKind::rapid : MotionKind::line, out);
        if (c.machine) m.radius = RadiusRequest{};
        const Vec2 d = in_plane((c.machine ? actual_.invert(out - zero_shift_) : e) - program_pos(), st_.plane);
        if (d.norm() > 1e-12) last_tangent_ = d.normalized();
        pos_ = out;
        ++moves_;
        sink_.push(m);
    }
    return true;
}

// A, B, C of the block: absolute, incremental, or (DC, ACP, ACN) on a modulo axis.
std::array<double, 3> Interp::rotary_targets(const BlockData& b) const {
    std::array<double, 3> abc = abc_;
    for (int i = 0; i < 3; ++i) {
        const Value& v = b[static_cast<char>('A' + i)];
        double& a = abc[static_cast<std::size_t>(i)];
        if (!v.set) continue;
        if (v.mod >= 3) a = modulo_target(a, v);
        else a = (v.mod == 2 || (v.mod == 0 && st_.incremental)) ? a + v.v : v.v;
    }
    return abc;
}

// G4 F (seconds) or S (revolutions of the spindle at its speed; none counted when it
// stands), in a block of its own: axis words beside it would be a move the control does not
// make.
void Interp::dwell(const BlockData& b, const BlockCodes& c, int first_column) {
    if (!b.has('F') && !b.has('S'))
        fail(code::dwell_missing, "G4 needs the dwell time F (seconds) or S (revolutions)", first_column);
    for (const char a : {'X', 'Y', 'Z', 'A', 'B', 'C'})
        if (b.has(a)) fail(code::alarm_12190, "12190 G4 must be programmed in a block of its own", b[a].column);
    if (c.motion >= 0) fail(code::alarm_12190, "12190 G4 must be programmed in a block of its own", first_column);
    const double seconds = b.has('F') ? b['F'].v : speed_ > 0 ? b['S'].v * 60 / speed_ : 0;
    dwell_seconds_ += std::max(0.0, seconds);
}

// RND=, CHF=, CHR= without a move; the addresses toolcomp does not run; N not first.
void Interp::check_unused_words(const BlockData& b, bool moved) const {
    if ((b.rnd.set || b.chf.set || b.chr.set) && !moved)
        fail(code::corner_without_element, "RND=, CHF= and CHR= go with a path move in their block",
             (b.rnd.set ? b.rnd : b.chf.set ? b.chf : b.chr).column);
    for (const char l : {'U', 'V', 'W', 'O', 'Q', 'E'})
        if (b.has(l)) fail(code::unsupported_word, std::string(1, l) + " words are not supported by toolcomp", b[l].column);
    if (b.has('N')) fail(code::syntax_error, "12080 Syntax error: a block number N must begin the block", b['N'].column);
}

// M0/M1; M2/M30 end the main program; M2/M30, M17 and RET return from a subprogram (M17 /
// RET in a main program end it too).
void Interp::stop_and_end(const BlockData& b, const BlockCodes& c) {
    if (c.stop) sink_.control({ControlKind::stop, line_, Vec3::Zero(), file()});
    const bool ret_word = b.keyword("RET");
    if (c.end && stack_.size() == 1) {
        sink_.control({ControlKind::program_end, line_, Vec3::Zero(), file()});
        st_.side = 0;
        ended_ = true;
        return;
    }
    if (!(c.end || c.sub_end || ret_word)) return;
    if (stack_.size() == 1) {
        if (c.sub_end || ret_word) {
            sink_.control({ControlKind::program_end, line_, Vec3::Zero(), file()});
            ended_ = true;
        }
        return;
    }
    Context& ctx = stack_.back();
    ctx.pc = ctx.prog->blocks().size();  // ret() at the next step
}

}  // namespace toolcomp::sinumerik
