#pragma once
// The control dialects toolcomp reads, their names and file suffixes (the rows of the
// dialect table, cpp/src/dialects/table.cpp).
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace toolcomp {

enum class Dialect { linuxcnc, fanuc, sinumerik, heidenhain, rockwell };

std::string_view dialect_name(Dialect d);
// The dialects toolcomp reads, in the order of the dialect table: name and file suffixes
// (lower case, without the dot; "" unused).
struct DialectNames {
    Dialect dialect;
    std::string_view name;
    std::array<std::string_view, 2> suffixes;
};
std::vector<DialectNames> dialect_names();
// Whether a lone CR (a run of CRs not followed by LF) ends a line, each CR one, as LF does
// ("\r\n" and "\r\r\n" are one line end everywhere). LinuxCNC reads a line up to LF only: a
// file with CR line ends is one long line there (checked against rs274). The other
// dialects' files come from editors and DNC programs that write CR, LF or CRLF.
bool cr_ends_line(Dialect d);
// Parses "linuxcnc", "fanuc", ...; throws ParseError("unknown_dialect") otherwise.
Dialect dialect_from_name(std::string_view name);
// .ngc linuxcnc, .nc/.tap fanuc, .mpf/.spf sinumerik, .h heidenhain; nullopt when unknown.
std::optional<Dialect> dialect_from_suffix(std::string_view path);
// The dialect of a program file: `given`, else from the suffix; else ParseError("unknown_dialect").
Dialect dialect_of_file(std::string_view path, std::optional<Dialect> given);

}  // namespace toolcomp
