#pragma once
// CSV tool table (RFC 4180 quoting, comma separated, LF or CRLF).
//
// The first row that is not blank and not a '#' comment is the header. Column names are
// matched case-insensitively after trimming:
//   tool (required), edge, pocket, name, x, y, z, a, b, c, u, v, w,
//   diameter | radius, corner_radius, x_wear, y_wear, z_wear, diameter_wear | radius_wear,
//   corner_radius_wear, front_angle, back_angle, orientation, comment
// Any other column is kept as it is (and written back), but not converted to other formats.
// One row per cutting edge: rows with the same tool and different `edge` (default 1) are
// edges of one tool; pocket/name/comment must agree between them. Empty cells mean 0 / "".
// Lengths are in the table's unit, angles in degrees.
// Canonical header (when writing a table that did not come from CSV):
//   tool,edge,pocket,name,x,y,z,a,b,c,u,v,w,diameter,corner_radius,x_wear,y_wear,z_wear,
//   diameter_wear,corner_radius_wear,front_angle,back_angle,orientation,comment
#include "toolcomp/tools/tool_table.hpp"

namespace toolcomp {

ToolTable read_csv_table(std::string_view text, LengthUnit units);
std::string write_csv_table(const ToolTable& table);

}  // namespace toolcomp
