#pragma once
// Sinumerik toolholder with orientation capability ($TC_CARRn[m], spec §3.6) and the
// equivalent generic 5-axis transformation data (TRAFO5 types 24 and 56, spec §3.7).
//
// Conventions and choices:
// * Angles in degrees, positive by the right-hand rule about the axis vector (= clockwise
//   looking along the vector). rotate_about_axis() is Rodrigues' formula; the axis is normalised and a
//   zero axis gives the identity (spec: with v1 = v2 = 0, l1 and l2 simply add).
// * Effective angle of axis i = alpha_i + offset_i ($TC_CARR24/25) [U]; Hirth data, software
//   limits, names and user data are stored but not used.
// * Offset vectors point from the tool tip towards the holder reference (spec §3.6).
// * resulting_tool_length():
//     T: L = l1 + Rot(v1,a1)(l2 + Rot(v2,a2)(l3 + L_tool))           (l4 ignored)
//     M: L = l1 + Rot(v1,a1)(l2 + L_tool)  — our reading of "M: l1 and l2": the head carries
//        only v1; l3, l4 and v2 belong to the table [U].
//     P: L = L_tool (the tool length is not influenced).
// * table_zero_offset(): shift of the workpiece zero point by the table rotation.
//     P: Rot(v1,a1)(l3 + Rot(v2,a2) l4) - (l3 + l4); v1 is the outer (carrying) axis, l3 the
//        vector between the axes, l4 from the 2nd axis to the zero point; l2 is constant and
//        cancels [U]. With one axis in use this is Rot(v,a) l4 - l4 (spec's verified example).
//     M: Rot(v2,a2) l4 - l4 (the table axis only) [U].   T: zero.
// * An invalid kinematic type throws CompensationError("toolholder_bad_kinematic_type"),
//   message citing alarm 14153.
#include <array>
#include <string>
#include <string_view>

#include "toolcomp/geometry/vec.hpp"

namespace toolcomp {

/// Rodrigues rotation, right-hand rule, degrees; a zero axis gives v
Vec3 rotate_about_axis(const Vec3& v, const Vec3& axis, double angle_deg);

/// Toolholder with orientation capability ($TC_CARRn[m]); angles in degrees
struct Toolholder {
    /// $TC_CARR1..3 (a copy on read; assign a new vector)
    Vec3 l1 = Vec3::Zero(), l2 = Vec3::Zero(), l3 = Vec3::Zero(), l4 = Vec3::Zero();
    /// $TC_CARR7..9
    Vec3 v1 = Vec3::Zero(), v2 = Vec3::Zero();
    /// $TC_CARR13
    double alpha1 = 0, alpha2 = 0;
    /// $TC_CARR21
    std::string axis1, axis2;         // $TC_CARR21/22 (identifiers only)
    char kind = 'T';                  // $TC_CARR23: 'T', 'P', 'M'
    /// $TC_CARR24
    double offset1 = 0, offset2 = 0;
    /// $TC_CARR26..29 (stored, not used)
    std::array<double, 4> hirth{};
    /// $TC_CARR30..33 (stored, not used)
    std::array<double, 4> limits{};
    /// $TC_CARR34
    std::string name;
    /// $TC_CARR35..40
    std::array<double, 6> user{};

    // $TC_CARRn = value for the numeric fields n = 1..20, 24..33, 35..40; 41..65 (fine
    // offsets) are not modelled. Throws CompensationError("toolholder_bad_field") otherwise.
    /// $TC_CARRn = value for n = 1..20, 24..33, 35..40
    void set(int n, double value);
    // The text fields 21, 22, 23 (kinematic type, case-insensitive) and 34.
    /// $TC_CARRn = text for n = 21, 22, 23, 34
    void set_text(int n, std::string_view value);

    /// alpha1 + offset1
    double angle1() const { return alpha1 + offset1; }
    /// alpha2 + offset2
    double angle2() const { return alpha2 + offset2; }
};

// Throws CompensationError (alarm 14153) unless kind is T, P or M.
void check_kinematic_type(char kind);

Vec3 resulting_tool_length(const Toolholder& h, const Vec3& tool_length);
Vec3 table_zero_offset(const Toolholder& h);

// ---- generic 5-axis transformation data ---------------------------------------------------
// Seed (W1 manual): type 24 uses BASE_TOOL, JOINT_OFFSET and MD24558 (printed there as
// PART_OFFSET, but 24558 is the number of JOINT_OFFSET_PART: we read it as JOINT_OFFSET_PART);
// type 56 uses BASE_TOOL and JOINT_OFFSET and corresponds to kinematic type M. JOINT_OFFSET
// is l1 alone, JOINT_OFFSET_PART is l3 (zero = the old behaviour). Our mapping, the same for
// both types so that the vectors used match the seed's table (T: l1 l2 l3; M: l1 l2):
//   l1 = JOINT_OFFSET, l2 = BASE_TOOL, l3 = JOINT_OFFSET_PART, l4 = PART_OFFSET,
//   v1 = AXIS1, v2 = AXIS2, type 24 -> 'T', type 56 -> 'M' [U for type 24].
/// Generic 5-axis transformation data (TRAFO_TYPE 24 or 56)
struct Trafo5Data {
    /// MD24100 TRAFO_TYPE_n: 24 or 56
    int type = 24;
    /// MD24550 TRAFO5_BASE_TOOL
    Vec3 base_tool = Vec3::Zero();
    /// MD24560 TRAFO5_JOINT_OFFSET
    Vec3 joint_offset = Vec3::Zero();
    /// MD24558 TRAFO5_JOINT_OFFSET_PART
    Vec3 joint_offset_part = Vec3::Zero();
    /// TRAFO5_PART_OFFSET
    Vec3 part_offset = Vec3::Zero();
    /// TRAFO5_AXIS1
    Vec3 axis1 = Vec3::Zero(), axis2 = Vec3::Zero();
};

// The equivalent toolholder at axis positions a1, a2 (degrees). Throws
// CompensationError("trafo5_bad_type") for types other than 24 and 56, and "4342" (alarm
// 4342) for an axis of zero length, parallel axes or a vector that is not a number.
Toolholder to_toolholder(const Trafo5Data& t, double a1_deg, double a2_deg);

// The tool length through the machine data directly (type 24: J + R1(B + R2(JP + L));
// type 56: J + R1(B + L)); equals resulting_tool_length(to_toolholder(t, a1, a2), L). The
// same errors as to_toolholder.
Vec3 trafo5_tool_length(const Trafo5Data& t, double a1_deg, double a2_deg, const Vec3& tool_length);

}  // namespace toolcomp
