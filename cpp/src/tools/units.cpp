#include "toolcomp/tools/units.hpp"
#include "toolcomp/program/codes.hpp"

#include "toolcomp/program/diagnostic.hpp"
#include "toolcomp/program/text.hpp"


namespace toolcomp {

double mm_per_unit(LengthUnit u) { return u == LengthUnit::inch ? 25.4 : 1.0; }

std::string_view to_string(LengthUnit u) { return u == LengthUnit::inch ? "inch" : "mm"; }

LengthUnit length_unit_from_string(std::string_view s) {
    std::string low;
    for (char c : s) low += ascii_lower(c);
    if (low == "mm") return LengthUnit::mm;
    if (low == "inch" || low == "in") return LengthUnit::inch;
    throw ToolTableError(code::table_bad_units, "unknown length unit '" + std::string(s) + "' (use \"mm\" or \"inch\")");
}

}  // namespace toolcomp
