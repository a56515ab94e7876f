#include "toolcomp/tools/tool_table.hpp"
#include "toolcomp/program/codes.hpp"

#include "toolcomp/program/diagnostic.hpp"
#include "toolcomp/tools/format_csv.hpp"
#include "toolcomp/tools/format_heidenhain.hpp"
#include "toolcomp/tools/format_json.hpp"
#include "toolcomp/tools/format_linuxcnc.hpp"
#include "toolcomp/tools/format_sinumerik.hpp"

#include <algorithm>

namespace toolcomp {

const Tool* ToolTable::find(int number) const {
    const auto it = index_.find(number);
    return it == index_.end() ? nullptr : &tools_[it->second];
}

Tool* ToolTable::find(int number) {
    return const_cast<Tool*>(static_cast<const ToolTable&>(*this).find(number));
}

const Tool& ToolTable::at(int number) const {
    if (const Tool* t = find(number)) return *t;
    throw ToolTableError(code::table_no_such_tool, "no tool T" + std::to_string(number) + " in the tool table");
}

void ToolTable::set(Tool t) {
    validate_tool(t);
    if (Tool* old = find(t.number)) {
        *old = std::move(t);
    } else {
        index_.emplace(t.number, tools_.size());
        tools_.push_back(std::move(t));
    }
}

bool ToolTable::remove(int number) {
    const auto it = index_.find(number);
    if (it == index_.end()) return false;
    const std::size_t pos = it->second;
    index_.erase(it);
    tools_.erase(tools_.begin() + static_cast<std::ptrdiff_t>(pos));
    for (std::size_t i = pos; i < tools_.size(); ++i) index_[tools_[i].number] = i;
    return true;
}

ToolTable read_tool_table(std::string_view text, TableFormat format, LengthUnit units) {
    switch (format) {
        case TableFormat::linuxcnc: return read_linuxcnc_table(text, units);
        case TableFormat::csv: return read_csv_table(text, units);
        case TableFormat::json: return read_json_table(text, units);
        case TableFormat::heidenhain: return read_heidenhain_table(text, units);
        case TableFormat::sinumerik: return read_sinumerik_table(text, units);
    }
    throw ToolTableError(code::table_unknown_format, "unknown tool table format");
}

std::string write_tool_table(const ToolTable& table, TableFormat format) {
    switch (format) {
        case TableFormat::linuxcnc: return write_linuxcnc_table(table);
        case TableFormat::csv: return write_csv_table(table);
        case TableFormat::json: return write_json_table(table);
        case TableFormat::heidenhain: return write_heidenhain_table(table);
        case TableFormat::sinumerik: return write_sinumerik_table(table);
    }
    throw ToolTableError(code::table_unknown_format, "unknown tool table format");
}

}  // namespace toolcomp
