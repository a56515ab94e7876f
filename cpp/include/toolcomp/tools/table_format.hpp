#pragma once
// Which file format a tool table is stored in.
#include <string>
#include <string_view>

namespace toolcomp {

enum class TableFormat { linuxcnc, csv, json, heidenhain, sinumerik };

// "linuxcnc" / "csv" / "json" / "heidenhain".
std::string_view to_string(TableFormat f);
// Accepts "linuxcnc", "tbl", "csv", "json", "heidenhain", "t" (case-insensitive); throws
// ToolTableError("table_unknown_format").
TableFormat table_format_from_string(std::string_view s);
// From the file suffix (.tbl, .csv, .json, .t, case-insensitive); throws
// ToolTableError("table_unknown_format").
TableFormat table_format_from_path(const std::string& path);

}  // namespace toolcomp
