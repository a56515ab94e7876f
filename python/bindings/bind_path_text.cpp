// The Path's text writers (path_text.hpp) for toolcomp.export and the command line's CSV:
// private functions of _core, the GIL released while they write.
#include "bindings.hpp"

#include <string>

#include "toolcomp/path_text.hpp"

using namespace toolcomp;

void bind_path_text(py::module_& m) {
    m.def(
        "_gcode_text",
        [](const Path& p, const std::string& dialect, int digits, bool comments, bool tool_length) {
            GcodeStyle style;
            if (dialect == "linuxcnc")
                style.target = GcodeStyle::Target::linuxcnc;
            else if (dialect == "fanuc")
                style.target = GcodeStyle::Target::fanuc;
            else if (dialect == "grbl")
                style.target = GcodeStyle::Target::grbl;
            else
                throw py::value_error("unknown export dialect '" + dialect + "' (expected one of linuxcnc, fanuc, grbl)");
            style.digits = digits;
            style.comments = comments;
            style.tool_length = tool_length;
            std::string text;
            {
                py::gil_scoped_release nogil;
                text = gcode_text(p, style);
            }
            return py::str(text);
        },
        py::arg("path"), py::arg("dialect"), py::arg("digits"), py::arg("comments"), py::arg("tool_length"));
    m.def(
        "_csv_rows",
        [](const Path& p, std::size_t begin, std::size_t end, std::size_t first_index) {
            std::string text;
            {
                py::gil_scoped_release nogil;
                csv_rows(p, begin, end, first_index, text);
            }
            return py::str(text);
        },
        py::arg("path"), py::arg("begin"), py::arg("end"), py::arg("first_index"));
    m.attr("_csv_header") = py::str(csv_header());
}
