// A Path's segments as CSV rows (see path_text.hpp).
#include <algorithm>
#include <cmath>
#include <string>

#include "fixed_text.hpp"
#include "toolcomp/path_text.hpp"

namespace toolcomp {

namespace {
constexpr const char* kKindName[4] = {"rapid", "line", "arc_cw", "arc_ccw"};

// ",v" with 6 decimals; NaN (a line's centre, a rapid's feed) an empty field.
void field(std::string& out, double v) {
    out += ',';
    if (!std::isnan(v)) text::append(out, text::fixed(v, 6, /*trim=*/false));
}
}  // namespace

const char* csv_header() {
    return "index,kind,line,tool,start_x,start_y,start_z,end_x,end_y,end_z,center_x,center_y,center_z,feed,side,"
           "generated,tool_offset_x,tool_offset_y,tool_offset_z,a,b,c\r\n";
}

void csv_rows(const Path& path, std::size_t begin, std::size_t end, std::size_t first_index, std::string& out) {
    end = std::min(end, path.size());
    if (begin >= end) return;
    const std::span<const double> starts = path.starts(), centers = path.centers(), feeds = path.feeds();
    out.reserve(out.size() + 200 * (end - begin));
    for (std::size_t i = begin; i < end; ++i) {
        text::append_int(out, first_index + (i - begin));
        out += ',';
        const unsigned k = path.kind[i];
        if (k < 4)
            out += kKindName[k];
        else
            text::append_int(out, k);
        out += ',';
        text::append_int(out, path.line[i]);
        out += ',';
        text::append_int(out, path.tool(i));
        for (const double* row : {starts.data() + 3 * i, path.end.data() + 3 * i, centers.data() + 3 * i})
            for (int c = 0; c < 3; ++c) field(out, row[c]);
        field(out, feeds[i]);
        out += ',';
        text::append_int(out, static_cast<int>(path.side[i]));
        out += path.generated[i] ? ",1" : ",0";
        for (int c = 0; c < 3; ++c) field(out, path.tool_offset(i, c));
        for (int c = 0; c < 3; ++c) field(out, path.abc(i, c));
        out += "\r\n";
    }
}

}  // namespace toolcomp
