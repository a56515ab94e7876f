// The coordinate transformation cycles (frame.hpp): CYCL DEF 7 DATUM SHIFT, 8 MIRROR IMAGE,
// 10 ROTATION, 11 SCALING, 26 AXIS-SPECIFIC SCALING, 247 DATUM SETTING. Each takes effect
// with its block and stays until reset or redefined. The first line of 7, 8, 10, 11, 26 (7.0
// DATUM SHIFT, ...) names the cycle; the lines after it give its values.
#include <cmath>
#include <string>

#include "interp.hpp"
#include "toolcomp/program/codes.hpp"
#include "toolcomp/program/text.hpp"

namespace toolcomp::heidenhain {

namespace {

constexpr std::string_view kAxis[3] = {"X", "Y", "Z"};
constexpr std::string_view kIncAxis[3] = {"IX", "IY", "IZ"};

bool naming_line(std::span<const Token> t) { return t[2].value == std::floor(t[2].value); }  // 7.0, 8.0, ...

}  // namespace

// The transformations `next` take effect: the tool stays where it is, its position read in
// the new program coordinates. Compensation must be off (R0) and no APPR pending.
void Interp::transform(const Transformations& next_values, int column) {
    Transformations next = next_values;
    next.plane = next.rotation != 0 ? plane_ : transforms_.plane;
    if (next == transforms_) return;
    if (side_ != 0)
        fail(code::comp_plane, "A coordinate transformation with RL/RR active: program R0 before it (toolcomp; the TNC "
                               "cancels radius compensation at CYCL DEF 10)",
             column);
    if (approach_) throw ProgramError(code::approach_without_contour, "APPR needs a contour element after it", {approach_->line, 0, {}});
    settle_pending();
    if (pending_) {
        sink_.push(*pending_);
        pending_.reset();
    }
    const Vec3 at = frame().point(pos_);
    const Frame f(next);
    sink_.set(f);
    transforms_ = next;
    pos_ = f.to_program(at);
}

void Interp::refuse_scaled(const char* what, int column) const {
    if (!frame().isometric())
        fail(code::scaling_refused, std::string(what) + " under scaling (CYCL DEF 11, 26): not supported by toolcomp yet",
             column);
}

// CYCL DEF 7.0 DATUM SHIFT, then 7.1 X.. / 7.2 Y.. / 7.3 Z.. (IX.. adds to the shift in force;
// an axis not named keeps its shift; X+0 takes it back). A row of a datum table (#n) is
// refused: toolcomp reads no datum tables.
void Interp::datum_shift(Tokens t) {
    Transformations next = transforms_;
    for (std::size_t i = 3; i < t.size(); ++i) {
        const Token& k = t[i];
        bool axis = false;
        for (int a = 0; a < 3; ++a) {
            if (k.is(kAxis[a]) && k.has_value) next.shift[a] = k.value, axis = true;
            if (k.is(kIncAxis[a]) && k.has_value) next.shift[a] += k.value, axis = true;
        }
        if (axis || (naming_line(t) && !k.has_value)) continue;  // 7.0 DATUM SHIFT: the cycle's name
        fail(code::unsupported_word,
             (k.key.empty() ? std::string("A number") : k.key.str()) + " in CYCL DEF 7: toolcomp shifts the datum by X, Y, Z values "
                                                         "(IX, IY, IZ); datum tables are not read",
             k.column);
    }
    transform(next, t[0].column);
}

// CYCL DEF 8.1 X Y: the axes named are mirrored about the datum (8.1 alone: none). Mirroring
// the tool axis is refused.
void Interp::mirror_image(Tokens t) {
    if (naming_line(t)) return;
    Transformations next = transforms_;
    next.mirror = {};
    const int tool_axis = axes(plane_).c;
    for (std::size_t i = 3; i < t.size(); ++i) {
        const Token& k = t[i];
        int axis = -1;
        for (int a = 0; a < 3; ++a)
            if (k.is(kAxis[a]) && !k.has_value) axis = a;
        if (axis < 0) fail(code::bad_word, (k.key.empty() ? std::string("A number") : k.key.str()) + " is not read in CYCL DEF 8 (the axes to mirror: X Y)", k.column);
        if (axis == tool_axis) fail(code::unsupported_word, "CYCL DEF 8: mirroring the tool axis is not supported by toolcomp", k.column);
        next.mirror[static_cast<std::size_t>(axis)] = true;
    }
    transform(next, t[0].column);
}

// CYCL DEF 10.1 ROT+35 (IROT: added to the rotation in force; ROT+0: none): about the datum,
// in the working plane, counter-clockwise from its first axis.
void Interp::rotation(Tokens t) {
    if (naming_line(t)) return;
    Transformations next = transforms_;
    const Token* rot = find(t, "ROT");
    const Token* irot = find(t, "IROT");
    if (!rot == !irot || !(rot ? rot : irot)->has_value)
        fail(code::missing_value, "CYCL DEF 10.1 needs ROT or IROT with an angle", t[2].column);
    next.rotation = rot ? rot->value : next.rotation + irot->value;
    for (std::size_t i = 3; i < t.size(); ++i)
        if (&t[i] != rot && &t[i] != irot) fail(code::bad_word, t[i].key + " is not read in CYCL DEF 10", t[i].column);
    transform(next, t[0].column);
}

// CYCL DEF 11.1 SCL 0.75 (SCL 1: none): about the datum, in all three axes (iTNC MP7410 = 0),
// from 0.000001 to 99.999999. Tool radius and length are not scaled.
void Interp::scaling(Tokens t) {
    if (naming_line(t)) return;
    const Token* scl = find(t, "SCL");
    const Token* value = scl && scl->has_value ? scl : nullptr;
    if (scl && !value && scl + 1 < t.data() + t.size() && scl[1].key.empty() && scl[1].has_value) value = scl + 1;  // SCL 0.75
    if (!value) fail(code::missing_value, "CYCL DEF 11.1 needs SCL with a factor", t[2].column);
    if (!(value->value >= 0.000001 && value->value <= 99.999999))
        fail(code::cycle_bad_value, "CYCL DEF 11: the factor SCL is 0.000001 to 99.999999", value->column);
    Transformations next = transforms_;
    next.scale = value->value;
    transform(next, t[0].column);
}

// CYCL DEF 26.1 X1.4 Y0.6 CCX+15 CCY+20: a factor for each axis named (the others 1), about
// the centre CCX / CCY / CCZ.
void Interp::axis_scaling(Tokens t) {
    if (naming_line(t)) return;
    Transformations next = transforms_;
    next.axis_scale = Vec3::Ones();
    next.axis_scale_centre = Vec3::Zero();
    for (std::size_t i = 3; i < t.size(); ++i) {
        const Token& k = t[i];
        bool read = false;
        for (int a = 0; a < 3; ++a) {
            if (k.is(kAxis[a]) && k.has_value) {
                if (!(k.value >= 0.000001 && k.value <= 99.999999))
                    fail(code::cycle_bad_value, "CYCL DEF 26: a factor is 0.000001 to 99.999999", k.column);
                next.axis_scale[a] = k.value, read = true;
            }
            if (k.key.size() == 3 && k.key.starts_with("CC") && k.key[2] == kAxis[a][0] && k.has_value)
                next.axis_scale_centre[a] = k.value, read = true;
        }
        if (!read) fail(code::bad_word, (k.key.empty() ? std::string("A number") : k.key.str()) + " is not read in CYCL DEF 26", k.column);
    }
    transform(next, t[0].column);
}

// CYCL DEF 247 DATUM SETTING Q339=n: preset n of the preset table becomes active, and with it
// no datum shift, mirror image, rotation or scaling. toolcomp reads no preset table: the path
// stays measured from the program's preset, which a note says.
void Interp::datum_setting(Tokens t) {
    const Token* q339 = nullptr;
    for (std::size_t i = 3; i < t.size(); ++i)
        if (t[i].is("Q339")) q339 = &t[i];
    if (!q339 || !q339->has_value) fail(code::cycle_q_missing, "CYCL DEF 247: Q339 missing", t[2].column);
    q_[339] = q339->value;
    diags_.push_back({code::preset_not_modelled, Severity::info,
                      "CYCL DEF 247 DATUM SETTING Q339=" + shortest_number(q339->value) +
                          ": toolcomp reads no preset table; the path stays measured from the program's preset",
                      {line_, t[0].column}});
    transform(Transformations{}, t[0].column);
}

}  // namespace toolcomp::heidenhain
