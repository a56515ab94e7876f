#pragma once
// The control dialects toolcomp reads, their names and file suffixes.
#include <optional>
#include <string>
#include <string_view>

namespace toolcomp {

enum class Dialect { linuxcnc, fanuc, sinumerik, heidenhain, rockwell };

std::string_view dialect_name(Dialect d);
// The word-address dialects the ISO front end reads (LinuxCNC, Fanuc, Rockwell).
inline bool is_iso(Dialect d) { return d == Dialect::linuxcnc || d == Dialect::fanuc || d == Dialect::rockwell; }
// Parses "linuxcnc", "fanuc", ...; throws ParseError("unknown_dialect") otherwise.
Dialect dialect_from_name(std::string_view name);
// .ngc linuxcnc, .nc/.tap fanuc, .mpf/.spf sinumerik, .h heidenhain; nullopt when unknown.
std::optional<Dialect> dialect_from_suffix(std::string_view path);
// The dialect of a program file: `given`, else from the suffix; else ParseError("unknown_dialect").
Dialect dialect_of_file(std::string_view path, std::optional<Dialect> given);

}  // namespace toolcomp
