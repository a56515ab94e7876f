#pragma once
// Reading and spelling the numbers of tool-table files (private to cpp/src/tools).
#include <string>
#include <string_view>

namespace toolcomp::tables {

// Strict decimal: [+-] digits [. digits] | [+-] . digits, optional exponent. No inf/nan/hex.
bool parse_decimal(std::string_view s, double& out);
// Strict integer: [+-] digits, fitting an int.
bool parse_integer(std::string_view s, int& out);

// The file text of a model value (mm or degrees) stored in a file whose unit is
// `mm_per_unit` mm. The text always reads back to exactly `model` when such a text exists.
// LinuxCNC style: "%+f" (LinuxCNC's own writer), more decimals if needed; zero is "0".
std::string spell_linuxcnc(double model, double mm_per_unit);
// Shortest round-trip spelling ("10", "0.25", "1e-07"), for CSV and JSON.
std::string spell_shortest(double model, double mm_per_unit);

std::string trim(std::string_view s);
std::string to_lower(std::string_view s);

}  // namespace toolcomp::tables
