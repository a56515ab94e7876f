// Toolholder with orientation capability and TRAFO5 equivalence (spec §3.6, §3.7);
// conventions in toolholder.hpp.
#include "toolcomp/compensation/toolholder.hpp"
#include "toolcomp/program/codes.hpp"

#include <cmath>
#include <Eigen/Geometry>

#include "toolcomp/program/diagnostic.hpp"
#include "toolcomp/program/text.hpp"

namespace toolcomp {

namespace {

[[noreturn]] void bad_field(int n, const char* why) {
    throw CompensationError(code::toolholder_bad_field, "$TC_CARR" + std::to_string(n) + ": " + why);
}

}  // namespace

Vec3 rotate_about_axis(const Vec3& v, const Vec3& axis, double angle_deg) {
    const double n = axis.norm();
    if (n == 0) return v;
    const Vec3 k = axis / n;
    const double a = angle_deg * kPi / 180.0;
    const double c = std::cos(a), s = std::sin(a);
    return v * c + k.cross(v) * s + k * k.dot(v) * (1.0 - c);
}

void check_kinematic_type(char kind) {
    if (kind != 'T' && kind != 'P' && kind != 'M')
        throw CompensationError(code::toolholder_bad_kinematic_type,
                                std::string("alarm 14153: invalid kinematic type '") + kind +
                                    "' in $TC_CARR23 (expected T, P or M)");
}

void Toolholder::set(int n, double value) {
    auto put = [&](Vec3& v, int first) { v[n - first] = value; };
    if (n >= 1 && n <= 3) put(l1, 1);
    else if (n >= 4 && n <= 6) put(l2, 4);
    else if (n >= 7 && n <= 9) put(v1, 7);
    else if (n >= 10 && n <= 12) put(v2, 10);
    else if (n == 13) alpha1 = value;
    else if (n == 14) alpha2 = value;
    else if (n >= 15 && n <= 17) put(l3, 15);
    else if (n >= 18 && n <= 20) put(l4, 18);
    else if (n == 24) offset1 = value;
    else if (n == 25) offset2 = value;
    else if (n >= 26 && n <= 29) hirth[static_cast<std::size_t>(n - 26)] = value;
    else if (n >= 30 && n <= 33) limits[static_cast<std::size_t>(n - 30)] = value;
    else if (n >= 35 && n <= 40) user[static_cast<std::size_t>(n - 35)] = value;
    else if (n >= 21 && n <= 34) bad_field(n, "is a text field (use set_text)");
    else bad_field(n, "is not a modelled toolholder parameter (1..40)");
}

void Toolholder::set_text(int n, std::string_view value) {
    switch (n) {
        case 21: axis1 = std::string(value); break;
        case 22: axis2 = std::string(value); break;
        case 34: name = std::string(value); break;
        case 23: {
            const char k = value.size() == 1 ? ascii_upper(value[0])
                                             : '?';
            check_kinematic_type(k);
            kind = k;
            break;
        }
        default: bad_field(n, "is not a text field (21, 22, 23, 34)");
    }
}

Vec3 resulting_tool_length(const Toolholder& h, const Vec3& tool_length) {
    check_kinematic_type(h.kind);
    switch (h.kind) {
        case 'T':
            return h.l1 + rotate_about_axis(h.l2 + rotate_about_axis(h.l3 + tool_length, h.v2, h.angle2()),
                                            h.v1, h.angle1());
        case 'M': return h.l1 + rotate_about_axis(h.l2 + tool_length, h.v1, h.angle1());
        default: return tool_length;  // 'P'
    }
}

Vec3 table_zero_offset(const Toolholder& h) {
    check_kinematic_type(h.kind);
    switch (h.kind) {
        case 'P': {
            const Vec3 moved = rotate_about_axis(h.l3 + rotate_about_axis(h.l4, h.v2, h.angle2()), h.v1, h.angle1());
            return moved - (h.l3 + h.l4);
        }
        case 'M': return rotate_about_axis(h.l4, h.v2, h.angle2()) - h.l4;
        default: return Vec3::Zero();  // 'T'
    }
}

namespace {
// Alarm 4342: machine data the control refuses for the transformation (a rotary axis of no
// direction, two parallel axes, a value that is not a number).
void check_trafo5(const Trafo5Data& t) {
    auto bad = [](const std::string& what) {
        throw CompensationError(code::alarm_4342, "4342 Invalid machine data for the 5-axis transformation: " + what);
    };
    for (const Vec3* v : {&t.base_tool, &t.joint_offset, &t.joint_offset_part, &t.part_offset, &t.axis1, &t.axis2})
        if (!v->allFinite()) bad("a vector is not a number");
    if (t.axis1.norm() == 0) bad("TRAFO5_AXIS1 is zero");
    if (t.axis2.norm() == 0) bad("TRAFO5_AXIS2 is zero");
    if (t.axis1.normalized().cross(t.axis2.normalized()).norm() < 1e-9) bad("TRAFO5_AXIS1 and TRAFO5_AXIS2 are parallel");
}
}  // namespace

Toolholder to_toolholder(const Trafo5Data& t, double a1_deg, double a2_deg) {
    Toolholder h;
    if (t.type == 24) h.kind = 'T';
    else if (t.type == 56) h.kind = 'M';
    else
        throw CompensationError(code::trafo5_bad_type, "TRAFO_TYPE " + std::to_string(t.type) +
                                                       " has no toolholder equivalent here (24 or 56)");
    check_trafo5(t);
    h.l1 = t.joint_offset;
    h.l2 = t.base_tool;
    h.l3 = t.joint_offset_part;
    h.l4 = t.part_offset;
    h.v1 = t.axis1;
    h.v2 = t.axis2;
    h.alpha1 = a1_deg;
    h.alpha2 = a2_deg;
    return h;
}

Vec3 trafo5_tool_length(const Trafo5Data& t, double a1_deg, double a2_deg, const Vec3& tool_length) {
    if (t.type == 24 || t.type == 56) check_trafo5(t);
    if (t.type == 24) {
        const Vec3 inner = rotate_about_axis(t.joint_offset_part + tool_length, t.axis2, a2_deg);
        return t.joint_offset + rotate_about_axis(t.base_tool + inner, t.axis1, a1_deg);
    }
    if (t.type == 56) return t.joint_offset + rotate_about_axis(t.base_tool + tool_length, t.axis1, a1_deg);
    throw CompensationError(code::trafo5_bad_type, "TRAFO_TYPE " + std::to_string(t.type) + " is not 24 or 56");
}

}  // namespace toolcomp
