#pragma once
// The control dialects toolcomp reads, their names and file suffixes.
#include <optional>
#include <string>
#include <string_view>

namespace toolcomp {

enum class Dialect { linuxcnc, fanuc, sinumerik, heidenhain, rockwell };

std::string_view dialect_name(Dialect d);
// Parses "linuxcnc", "fanuc", ...; throws ParseError("unknown_dialect") otherwise.
Dialect dialect_from_name(std::string_view name);
// .ngc linuxcnc, .nc/.tap fanuc, .mpf/.spf sinumerik, .h heidenhain; nullopt when unknown.
std::optional<Dialect> dialect_from_suffix(std::string_view path);

}  // namespace toolcomp
