#pragma once
// The length unit a tool-table file is written in. The model is always millimetres.
#include <string>
#include <string_view>

namespace toolcomp {

enum class LengthUnit { mm, inch };

// Millimetres per file unit: 1 for mm, 25.4 for inch.
double mm_per_unit(LengthUnit u);
// "mm" / "inch".
std::string_view to_string(LengthUnit u);
// Accepts "mm", "inch", "in" (case-insensitive); throws ToolTableError("table_bad_units").
LengthUnit length_unit_from_string(std::string_view s);

}  // namespace toolcomp
