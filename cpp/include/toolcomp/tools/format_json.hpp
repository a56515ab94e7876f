#pragma once
// JSON tool table:
//   {
//     "units": "mm",                      optional: "mm" | "inch"; else the caller's unit
//     "tools": [
//       {"tool": 1, "pocket": 1, "name": "...", "diameter": 10, "z": 25, "comment": "..."},
//       {"tool": 2, "edges": [{"edge": 1, "radius": 2}, {"edge": 2, "radius": 2.5}]}
//     ]
//   }
// Tool keys: tool (int, required), pocket (int), name, comment (strings), and either the
// keys of one cutting edge directly in the tool object or "edges": [edge objects].
// Edge keys: edge (int, default 1), x y z a b c u v w, diameter | radius, corner_radius,
// x_wear y_wear z_wear, diameter_wear | radius_wear, corner_radius_wear, front_angle,
// back_angle (numbers), orientation (int 0..9). Missing keys are 0. Other keys (at any
// level) are kept when written back as JSON. Lengths in the file's unit, angles in degrees.
#include "toolcomp/tools/tool_table.hpp"

namespace toolcomp {

ToolTable read_json_table(std::string_view text, LengthUnit units);
std::string write_json_table(const ToolTable& table);

}  // namespace toolcomp
