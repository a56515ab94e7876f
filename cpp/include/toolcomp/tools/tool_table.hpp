#pragma once
// A tool table: the tools (mm, degrees), the length unit of the file it came from, and the
// file's own text so that writing it back changes only what was changed.
//
// Lossless contract: read → write in the same format and unit, with no tool changed, gives
// the input byte for byte (comments, blank lines, word/column/key order, number spelling,
// CRLF, unknown CSV columns and JSON keys). A changed tool is rewritten in the format's
// canonical spelling (keeping its word/key order where possible), a removed tool's line or
// object disappears, a new tool is appended. Writing another format, or changing `units`,
// writes the canonical form of that format.
#include "toolcomp/program/input_limits.hpp"
#include "toolcomp/tools/table_format.hpp"
#include "toolcomp/tools/tool.hpp"
#include "toolcomp/tools/units.hpp"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace toolcomp {

namespace detail {
// What a format reader remembers about the file text (defined per format in cpp/src/tools).
struct TableSource {
    virtual ~TableSource() = default;
    virtual TableFormat format() const = 0;
    LengthUnit units = LengthUnit::mm;
};
}  // namespace detail

/// Tool table; reads and writes LinuxCNC .tbl, CSV, JSON and Heidenhain TOOL.T losslessly.
/// Tools are stored in mm and degrees; `units` is the unit of the file.
class ToolTable {
public:
    ToolTable() = default;
    explicit ToolTable(LengthUnit units) : units_(units) {}

    const Tool* find(int number) const;
    // Mutable access; keep the number unchanged (use remove + set to renumber).
    Tool* find(int number);
    // Throws ToolTableError("table_no_such_tool") when absent.
    /// a copy of tool `number`; raises ToolTableError when absent
    const Tool& at(int number) const;
    bool contains(int number) const { return find(number) != nullptr; }
    // Insert, or replace the tool with the same number (keeps its place in the file).
    // Validates with validate_tool().
    /// insert, or replace the tool with the same number
    void set(Tool t);
    // Removes the tool if present; returns whether it was.
    /// remove a tool; returns whether it was there
    bool remove(int number);
    /// a tuple of copies of the tools, in file order
    const std::vector<Tool>& tools() const { return tools_; }
    std::size_t size() const { return tools_.size(); }
    bool empty() const { return tools_.empty(); }

    // The length unit of the file: numbers are converted from/to it on read/write.
    /// length unit of the file: 'mm' or 'inch' (changing it rewrites every tool on write)
    LengthUnit units() const { return units_; }
    void set_units(LengthUnit u) { units_ = u; }

    // The format the table was read from; empty for a table built in code.
    std::optional<TableFormat> source_format() const {
        return source_ ? std::optional<TableFormat>(source_->format()) : std::nullopt;
    }

    // Internal, used by the format readers/writers: the original text of the file.
    const detail::TableSource* source() const { return source_.get(); }
    void set_source(std::shared_ptr<const detail::TableSource> s) { source_ = std::move(s); }

    // Internal, used by the file reader and writer: the file the table was read from as it was
    // then (or as this table last wrote it), so that a write over that file changed since by
    // anyone else is refused.
    struct FileStamp {
        std::string path;  // with links resolved
        std::uint64_t dev = 0, ino = 0, size = 0;
        std::int64_t mtime_ns = 0;
        friend bool operator==(const FileStamp&, const FileStamp&) = default;
    };
    const std::optional<FileStamp>& file_stamp() const { return stamp_; }
    void set_file_stamp(std::optional<FileStamp> s) const { stamp_ = std::move(s); }

private:
    std::vector<Tool> tools_;
    // tool number -> position in tools_: find() and set() in constant time, so reading and
    // writing a table of n tools is O(n), not O(n^2) (20000 tools: 0.12 s -> ms).
    std::unordered_map<int, std::size_t> index_;
    LengthUnit units_ = LengthUnit::mm;
    std::shared_ptr<const detail::TableSource> source_;
    mutable std::optional<FileStamp> stamp_;
};

// Parse a table. `units` is the unit of the lengths in the text (a JSON file's own
// "units" key takes precedence). Throws ToolTableError with the 1-based line/column.
ToolTable read_tool_table(std::string_view text, TableFormat format, LengthUnit units = LengthUnit::mm);
// Format a table (see the lossless contract above).
std::string write_tool_table(const ToolTable& table, TableFormat format);

// The format is taken from the suffix when not given. Only a regular file of at most
// `max_bytes` is read: ToolTableError "not_a_regular_file" / "input_too_large" otherwise.
ToolTable read_tool_table_file(const std::string& path, std::optional<TableFormat> format = std::nullopt,
                               LengthUnit units = LengthUnit::mm, std::uint64_t max_bytes = kDefaultMaxTableBytes);
// Writes a temporary file in the same directory (".<name>.tmp"), fsyncs it and renames it
// over `path`, so the file on disk is always the complete old or the complete new table,
// even if the process dies (it keeps the old file's permissions). Writers hold an exclusive
// flock() on "<path>.lock" (removed when done); a second writer of the same table meanwhile
// fails with ToolTableError("table_locked"). Reading takes no lock and never writes.
void write_tool_table_file(const ToolTable& table, const std::string& path,
                           std::optional<TableFormat> format = std::nullopt);

}  // namespace toolcomp
