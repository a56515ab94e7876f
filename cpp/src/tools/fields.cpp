#include "fields.hpp"

#include <array>

namespace toolcomp::tables {

namespace {
using K = FieldKind;
constexpr std::array<FieldInfo, 26> kFields{{
    {Field::tool, "tool", K::integer, false, 0},
    {Field::edge, "edge", K::integer, true, 1},
    {Field::pocket, "pocket", K::integer, false, 2},
    {Field::name, "name", K::text, false, 3},
    {Field::comment, "comment", K::text, false, 4},
    {Field::x, "x", K::length, true, 5},
    {Field::y, "y", K::length, true, 6},
    {Field::z, "z", K::length, true, 7},
    {Field::a, "a", K::angle, true, 8},
    {Field::b, "b", K::angle, true, 9},
    {Field::c, "c", K::angle, true, 10},
    {Field::u, "u", K::length, true, 11},
    {Field::v, "v", K::length, true, 12},
    {Field::w, "w", K::length, true, 13},
    {Field::diameter, "diameter", K::length, true, 14},
    {Field::radius, "radius", K::length, true, 14},
    {Field::corner_radius, "corner_radius", K::length, true, 15},
    {Field::x_wear, "x_wear", K::length, true, 16},
    {Field::y_wear, "y_wear", K::length, true, 17},
    {Field::z_wear, "z_wear", K::length, true, 18},
    {Field::diameter_wear, "diameter_wear", K::length, true, 19},
    {Field::radius_wear, "radius_wear", K::length, true, 19},
    {Field::corner_radius_wear, "corner_radius_wear", K::length, true, 20},
    {Field::front_angle, "front_angle", K::angle, true, 21},
    {Field::back_angle, "back_angle", K::angle, true, 22},
    {Field::orientation, "orientation", K::integer, true, 23},
}};

// Names of lathe offset pages (Fanuc offset screen, 9/Series geometry and wear tables) for
// the same fields: an offset number is a tool entry, the nose radius a radius, the tip a
// tool orientation.
struct Alias {
    std::string_view name;
    Field field;
};
constexpr std::array<Alias, 4> kAliases{{
    {"offset", Field::tool},
    {"nose_radius", Field::radius},
    {"tip", Field::orientation},
    {"nose_radius_wear", Field::radius_wear},
}};
}  // namespace

const FieldInfo* find_field(std::string_view name) {
    for (const auto& f : kFields)
        if (f.name == name) return &f;
    for (const auto& a : kAliases)
        if (a.name == name) return &field_info(a.field);
    return nullptr;
}

const FieldInfo& field_info(Field f) { return kFields[static_cast<std::size_t>(f)]; }

const std::vector<Field>& canonical_edge_fields() {
    static const std::vector<Field> fields{
        Field::x, Field::y, Field::z, Field::a, Field::b, Field::c, Field::u, Field::v, Field::w,
        Field::diameter, Field::corner_radius, Field::x_wear, Field::y_wear, Field::z_wear,
        Field::diameter_wear, Field::corner_radius_wear, Field::front_angle, Field::back_angle,
        Field::orientation};
    return fields;
}

double get_edge_number(const CuttingEdge& e, Field f) {
    switch (f) {
        case Field::edge: return e.number;
        case Field::x: return e.length.x();
        case Field::y: return e.length.y();
        case Field::z: return e.length.z();
        case Field::a: return e.rotary[0];
        case Field::b: return e.rotary[1];
        case Field::c: return e.rotary[2];
        case Field::u: return e.uvw[0];
        case Field::v: return e.uvw[1];
        case Field::w: return e.uvw[2];
        case Field::diameter: return 2 * e.radius;
        case Field::radius: return e.radius;
        case Field::corner_radius: return e.corner_radius;
        case Field::x_wear: return e.length_wear.x();
        case Field::y_wear: return e.length_wear.y();
        case Field::z_wear: return e.length_wear.z();
        case Field::diameter_wear: return 2 * e.radius_wear;
        case Field::radius_wear: return e.radius_wear;
        case Field::corner_radius_wear: return e.corner_radius_wear;
        case Field::front_angle: return e.front_angle;
        case Field::back_angle: return e.back_angle;
        case Field::orientation: return e.orientation;
        default: return 0;
    }
}

void set_edge_number(CuttingEdge& e, Field f, double v) {
    switch (f) {
        case Field::edge: e.number = static_cast<int>(v); break;
        case Field::x: e.length.x() = v; break;
        case Field::y: e.length.y() = v; break;
        case Field::z: e.length.z() = v; break;
        case Field::a: e.rotary[0] = v; break;
        case Field::b: e.rotary[1] = v; break;
        case Field::c: e.rotary[2] = v; break;
        case Field::u: e.uvw[0] = v; break;
        case Field::v: e.uvw[1] = v; break;
        case Field::w: e.uvw[2] = v; break;
        case Field::diameter: e.radius = v / 2; break;
        case Field::radius: e.radius = v; break;
        case Field::corner_radius: e.corner_radius = v; break;
        case Field::x_wear: e.length_wear.x() = v; break;
        case Field::y_wear: e.length_wear.y() = v; break;
        case Field::z_wear: e.length_wear.z() = v; break;
        case Field::diameter_wear: e.radius_wear = v / 2; break;
        case Field::radius_wear: e.radius_wear = v; break;
        case Field::corner_radius_wear: e.corner_radius_wear = v; break;
        case Field::front_angle: e.front_angle = v; break;
        case Field::back_angle: e.back_angle = v; break;
        case Field::orientation: e.orientation = static_cast<int>(v); break;
        default: break;
    }
}

}  // namespace toolcomp::tables
