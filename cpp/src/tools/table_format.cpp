#include "toolcomp/tools/table_format.hpp"
#include "toolcomp/program/codes.hpp"

#include "toolcomp/program/diagnostic.hpp"
#include "toolcomp/program/text.hpp"


namespace toolcomp {

namespace {
std::string lower(std::string_view s) {
    std::string r;
    for (char c : s) r += ascii_lower(c);
    return r;
}
}  // namespace

std::string_view to_string(TableFormat f) {
    switch (f) {
        case TableFormat::linuxcnc: return "linuxcnc";
        case TableFormat::csv: return "csv";
        case TableFormat::json: return "json";
        case TableFormat::heidenhain: return "heidenhain";
        case TableFormat::sinumerik: return "sinumerik";
    }
    return "?";
}

TableFormat table_format_from_string(std::string_view s) {
    const std::string f = lower(s);
    if (f == "linuxcnc" || f == "tbl") return TableFormat::linuxcnc;
    if (f == "csv") return TableFormat::csv;
    if (f == "json") return TableFormat::json;
    if (f == "heidenhain" || f == "t") return TableFormat::heidenhain;
    if (f == "sinumerik" || f == "ini") return TableFormat::sinumerik;
    throw ToolTableError(code::table_unknown_format,
                         "unknown tool table format '" + std::string(s) + "' (use linuxcnc, csv, json, heidenhain or sinumerik)");
}

TableFormat table_format_from_path(const std::string& path) {
    const auto slash = path.find_last_of("/\\");
    const auto dot = path.find_last_of('.');
    if (dot != std::string::npos && (slash == std::string::npos || dot > slash)) {
        const std::string ext = lower(std::string_view(path).substr(dot + 1));
        if (ext == "tbl") return TableFormat::linuxcnc;
        if (ext == "csv") return TableFormat::csv;
        if (ext == "json") return TableFormat::json;
        if (ext == "t") return TableFormat::heidenhain;
        if (ext == "ini") return TableFormat::sinumerik;
    }
    throw ToolTableError(code::table_unknown_format,
                         "cannot tell the tool table format from the name '" + path +
                             "' (suffix .tbl, .csv, .json, .t or .ini, or pass the format)");
}

}  // namespace toolcomp
