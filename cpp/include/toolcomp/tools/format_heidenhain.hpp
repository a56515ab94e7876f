#pragma once
// Heidenhain tool table TOOL.T (TNC 426 layout), fixed-width columns:
//
//   BEGIN TOOL .T MM
//   T    NAME             L           R           R2          DL      DR      DR2     ...  DOC   PLC
//   1    SCHAFTFRAESER_10 +95.25      +5          +0          +0      -0.02   +0      ...  TEXT  %00000000
//   [END]
//
// Reading
// * Line 1 is the BEGIN line: first word BEGIN; the words before the unit (spaces removed)
//   must end in ".T" (so TOOL_P.TCH or a program is refused: "heidenhain_not_tool_table").
//   A last word MM or INCH gives the unit of every length in the file and wins over the
//   caller's unit; without one the caller's unit is used. No BEGIN: "heidenhain_missing_begin".
// * Line 2 is the header: the column titles are the runs of non-blank characters (blank =
//   space or tab). Column i's field on every row spans from the character column where
//   title i starts up to (not including) the column where title i+1 starts; the first field
//   also takes anything left of the first title, the last field runs to the end of the line.
//   A row shorter than the header has empty fields. A field's value is its text with the
//   surrounding blanks removed, so values may be left- or right-aligned inside the field.
//   Columns are counted in characters: a valid UTF-8 sequence is one character, any other
//   byte (e.g. Latin-1 "Ä") is one character, a tab is one character.
//   The header needs a T column ("heidenhain_missing_header"); titles are matched
//   case-insensitively and may not repeat ("heidenhain_duplicate_column").
// * Every non-blank line between the header and the line "[END]" is one tool. Blank lines
//   are kept as they are. "[END]" is required (a truncated transfer must not lose tools
//   silently: "heidenhain_missing_end", reported one line past the end); after it only blank
//   lines may follow ("heidenhain_text_after_end").
// * Mapping: T -> Tool::number (a whole number >= 0; an indexed tool like "5.2" is refused
//   with "heidenhain_tool_index_unsupported"; empty: "heidenhain_missing_tool"; repeated:
//   "heidenhain_duplicate_tool"), NAME -> name, DOC -> comment, L -> edge length z,
//   R -> radius, R2 -> corner_radius, DL -> length_wear z, DR -> radius_wear,
//   DR2 -> corner_radius_wear. Numbers: [+-]digits[.digits] (an exponent is tolerated);
//   an empty field is 0; anything else is "heidenhain_bad_number". Lengths are converted
//   from the file unit to mm. Every other column (LCUTS, ANGLE, TL, RT, TIME1, TIME2,
//   CUR.TIME, PLC, the TT columns, TYPE, ..., and unknown titles) is not interpreted and is
//   kept verbatim per row.
// * Errors are ToolTableError with the 1-based line and character column (of the value, or
//   of its field when the value is empty).
//
// Writing (lossless contract of tool_table.hpp)
// * A table read from TOOL.T, written in the same unit: every line is written back as it
//   was, except: a removed tool's row disappears; a changed tool's row is rebuilt from its
//   old fields, where only the mapped fields whose value changed get new text; a new tool
//   gets a row just before "[END]" (T and the mapped columns filled, the others empty,
//   padded to the header line's length), with the file's line ending.
// * A rewritten value keeps the alignment of the old value (right-aligned when the old text
//   had more blanks before than after it, else it keeps its start; an empty field is filled
//   from its start) and must leave at least one blank before the next column; else
//   "heidenhain_value_too_wide" (the last column has no limit).
// * Canonical numbers (TNC style): a sign always ("+0", "+5", "+0.05", "-0.02"), fixed
//   point, no exponent, the fewest decimals that read back to exactly the model value.
//   So a value entered with 4 decimals is written with at most 4.
// * A table from another format, or with a changed unit, is written in the canonical
//   layout: "BEGIN TOOL .T MM" (or INCH), the TNC 426 columns
//   T NAME L R R2 DL DR DR2 LCUTS ANGLE TL RT TIME1 TIME2 CUR.TIME DOC PLC, each at least
//   as wide as the TNC's and widened to fit the longest value, unmapped columns empty,
//   every line padded to the full width, CRLF line endings, "[END]" last. The columns the
//   model does not map are then lost (as are unknown columns of CSV/JSON when converting
//   to TOOL.T, and TOOL.T's own unmapped columns when converting to other formats).
// * What TOOL.T cannot hold is refused ("heidenhain_unrepresentable"; checked for changed
//   and new tools, and for every tool of a canonical write): more than one
//   cutting edge or an edge number other than 1, X/Y length or wear, A B C / U V W offsets,
//   an orientation or front/back angles, a line break in NAME or DOC, or a non-zero value
//   (non-empty text) for a mapped column the file's header does not have. The pocket number
//   is not a TOOL.T column (the TNC keeps pockets in TOOL_P.TCH): it is dropped.
#include <optional>
#include <string>
#include <string_view>

#include "toolcomp/tools/tool_table.hpp"

namespace toolcomp {

ToolTable read_heidenhain_table(std::string_view text, LengthUnit units);
std::string write_heidenhain_table(const ToolTable& table);

// The text of tool `number`'s field in the TOOL.T column `title` (matched case-insensitively;
// for the columns the model does not map: TL, RT, TIME1, ...) as read, without the blanks
// around it; nullopt when the table was not read from TOOL.T, or has no such column or row.
std::optional<std::string> heidenhain_field(const ToolTable& table, int number, std::string_view title);

}  // namespace toolcomp
