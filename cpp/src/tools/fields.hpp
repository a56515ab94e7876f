#pragma once
// The named fields of the CSV columns and JSON keys (private to cpp/src/tools).
#include "toolcomp/tools/tool.hpp"

#include <string_view>
#include <vector>

namespace toolcomp::tables {

enum class Field {
    tool, edge, pocket, name, comment,
    x, y, z, a, b, c, u, v, w,
    diameter, radius, corner_radius,
    x_wear, y_wear, z_wear, diameter_wear, radius_wear, corner_radius_wear,
    front_angle, back_angle, orientation
};

enum class FieldKind { integer, length, angle, text };

struct FieldInfo {
    Field id;
    std::string_view name;  // lower case, as written in canonical files
    FieldKind kind;
    bool edge_level;        // belongs to a cutting edge (else to the tool)
    // Fields that store the same model value (diameter and radius): same slot number.
    int slot;
};

// nullptr when the (already lower-cased, trimmed) name is not a known field.
const FieldInfo* find_field(std::string_view name);
const FieldInfo& field_info(Field f);
// Edge-level fields in canonical order: x y z a b c u v w diameter corner_radius x_wear
// y_wear z_wear diameter_wear corner_radius_wear front_angle back_angle orientation.
const std::vector<Field>& canonical_edge_fields();

// Model value of a numeric edge field: mm or degrees (diameter = 2 radius); integer
// fields (edge, orientation) as double.
double get_edge_number(const CuttingEdge& e, Field f);
void set_edge_number(CuttingEdge& e, Field f, double v);

}  // namespace toolcomp::tables
