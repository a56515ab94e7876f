// The working plane and the tool's reference: CYCL DEF 19 WORKING PLANE and the PLANE
// functions, FUNCTION TCPM. A tilted plane needs the machine's kinematics, which toolcomp
// does not model yet: a tilt is refused; the untilted plane (every angle 0, or the reset) is
// taken, and the rotary axis positions the TNC computes for it (Q120 A, Q121 B, Q122 C, which
// programs position their axes with: L A+Q120 C+Q122) are 0. FUNCTION TCPM is M128's function.
#include <cmath>
#include <string>

#include "interp.hpp"
#include "toolcomp/program/codes.hpp"
#include "toolcomp/program/text.hpp"

namespace toolcomp::heidenhain {

namespace {

std::string tilt(const std::string& what, const Token& k) {
    return what + " with a tilt (" + k.key + shortest_number(k.value) +
           "): tilted working planes are not supported by toolcomp yet";
}

}  // namespace

void Interp::untilted_plane() {
    for (int n : {120, 121, 122}) control_q_[n] = 0;
}

// CYCL DEF 19.0 WORKING PLANE, 19.1 A.. B.. C.. [F..|FMAX] [MB..]
void Interp::working_plane(Tokens t) {
    for (std::size_t i = 3; i < t.size(); ++i) {
        const Token& k = t[i];
        if (k.is("A") || k.is("B") || k.is("C")) {
            if (k.has_value && k.value != 0) fail(code::unsupported_block, tilt("CYCL DEF 19", k), k.column);
        } else if (!(k.is("F") || k.is("FMAX") || k.is("MB") || (!k.has_value && t[2].value == 19))) {
            fail(code::bad_word, (k.key.empty() ? std::string("A number") : k.key.str()) + " is not read in CYCL DEF 19", k.column);
        }
    }
    untilted_plane();
}

// PLANE SPATIAL / PROJECTED / EULER / RELATIV / AXIAL / VECTOR with the angles (or vectors)
// of no tilt, PLANE RESET; then STAY, or MOVE / TURN (which turn the rotary axes: only where
// they stand at 0 already), SEQ, TABLE ROT / COORD ROT.
void Interp::plane_function(Tokens t) {
    if (t.size() < 2) fail(code::missing_value, "PLANE needs a function (SPATIAL, RESET, ...)", t[0].column);
    const std::string kind = t[1].key;
    static const std::vector<std::string_view> angles{"SPA", "SPB", "SPC", "PROPR", "PROMIN", "PROROT",
                                                      "EULPR", "EULNU", "EULROT", "A", "B", "C"};
    static const std::vector<std::string_view> after{"STAY", "MOVE", "TURN", "DIST", "F", "FMAX", "MB", "SEQ",
                                                     "TABLE", "COORD", "ROT"};
    if (kind == "POINTS")
        fail(code::unsupported_block, "PLANE POINTS is not supported by toolcomp yet", t[1].column);
    if (kind != "RESET" && kind != "SPATIAL" && kind != "PROJECTED" && kind != "EULER" && kind != "RELATIV" &&
        kind != "AXIAL" && kind != "VECTOR")
        fail(code::bad_word, "PLANE " + kind + " is not a PLANE function", t[1].column);
    Vec3 base = Vec3::Zero(), normal = Vec3::Zero();
    bool turns = false;
    for (std::size_t i = 2; i < t.size(); ++i) {
        const Token& k = t[i];
        if (std::find(angles.begin(), angles.end(), k.key) != angles.end() && kind != "RESET" && kind != "VECTOR") {
            if (!k.has_value) fail(code::missing_value, k.key + " needs a value", k.column);
            if (k.value != 0) fail(code::unsupported_block, tilt("PLANE " + kind, k), k.column);
        } else if (kind == "VECTOR" && k.key.size() == 2 && (k.key[0] == 'B' || k.key[0] == 'N') && k.key[1] >= 'X' &&
                   k.key[1] <= 'Z' && k.has_value) {
            (k.key[0] == 'B' ? base : normal)[k.key[1] - 'X'] = k.value;
        } else if (std::find(after.begin(), after.end(), k.key) != after.end()) {
            turns |= k.is("MOVE") || k.is("TURN");
        } else {
            fail(code::bad_word, (k.key.empty() ? std::string("A number") : k.key.str()) + " is not read in PLANE " + kind,
                 k.column);
        }
    }
    if (kind == "VECTOR") {  // untilted: the base vector along +X, the normal along +Z
        const bool along = base.norm() > 0 && normal.norm() > 0 && base.normalized().isApprox(Vec3::UnitX(), 1e-12) &&
                           normal.normalized().isApprox(Vec3::UnitZ(), 1e-12);
        if (!along)
            fail(code::unsupported_block, "PLANE VECTOR with a tilt: tilted working planes are not supported by toolcomp yet",
                 t[1].column);
    }
    if (turns && (abc_[0] != 0 || abc_[1] != 0 || abc_[2] != 0))
        fail(code::unsupported_block,
             "PLANE " + kind + " MOVE / TURN would turn the rotary axes back to 0: not supported by toolcomp yet (STAY "
                               "and L A.. C.. are)",
             t[1].column);
    untilted_plane();
}

// FUNCTION TCPM [F TCP|F CONT] [AXIS POS] [PATHCTRL AXIS|VECTOR] [REFPNT TIP-TIP]: M128's
// function (the tool tip follows the program while rotary axes turn); FUNCTION RESET TCPM: M129.
void Interp::function_block(Tokens t) {
    if (t.size() >= 3 && t[1].is("RESET") && t[2].is("TCPM")) {
        m128_ = false;
        return;
    }
    if (t.size() < 2 || !t[1].is("TCPM")) {
        const std::string what = t.size() >= 2 ? t[1].key.str() : std::string();
        fail(code::unsupported_block, "FUNCTION " + what + " is not supported by toolcomp yet", t[0].column);
    }
    for (std::size_t i = 2; i < t.size(); ++i) {
        const Token& k = t[i];
        const std::string_view next = i + 1 < t.size() ? std::string_view(t[i + 1].key) : std::string_view();
        if (k.is("F") && !k.has_value && (next == "TCP" || next == "CONT")) ++i;
        else if (k.is("AXIS") && next == "POS") ++i;
        else if (k.is("PATHCTRL") && (next == "AXIS" || next == "VECTOR")) ++i;
        else if (k.is("REFPNT") && next == "TIP-TIP") ++i;
        else if ((k.is("AXIS") && next == "SPAT") || (k.is("REFPNT") && !next.empty()))
            fail(code::unsupported_word, "FUNCTION TCPM " + k.key + " " + std::string(next) +
                                             " is not supported by toolcomp (rotary words are axis positions, the "
                                             "reference the tool tip)",
                 k.column);
        else
            fail(code::bad_word, (k.key.empty() ? std::string("A number") : k.key.str()) + " is not read in FUNCTION TCPM",
                 k.column);
    }
    m128_ = true;
}

}  // namespace toolcomp::heidenhain
