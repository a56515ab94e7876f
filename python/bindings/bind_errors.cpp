// Diagnostics, and C++ toolcomp::Error translated to the Python classes of toolcomp._errors.
#include "bindings.hpp"

#include <pybind11/typing.h>

#include "toolcomp/program/codes.hpp"
#include "toolcomp/program/diagnostic.hpp"

using namespace toolcomp;

namespace {
// Messages quote program text, which need not be UTF-8 (a Latin-1 comment, a stray byte):
// undecodable bytes become U+FFFD instead of a UnicodeDecodeError in place of the error.
py::str text(const std::string& s) {
    return py::reinterpret_steal<py::str>(PyUnicode_DecodeUTF8(s.data(), static_cast<Py_ssize_t>(s.size()), "replace"));
}

const char* severity_name(Severity s) {
    switch (s) {
        case Severity::info: return "info";
        case Severity::warning: return "warning";
        default: return "error";
    }
}
Severity severity_from(const std::string& s) {
    if (s == "info") return Severity::info;
    if (s == "warning") return Severity::warning;
    return Severity::error;
}
const char* class_name(ErrorKind k) {
    switch (k) {
        case ErrorKind::parse: return "ParseError";
        case ErrorKind::program: return "ProgramError";
        case ErrorKind::compensation: return "CompensationError";
        case ErrorKind::tool_table: return "ToolTableError";
        default: return "Error";
    }
}
}  // namespace

void bind_errors(py::module_& m) {
    py::class_<Diagnostic>(m, "Diagnostic", pydoc::Diagnostic)
        .def(py::init([](std::string code, const std::string& severity, std::string message, int line, int column,
                         std::string file) {
                 return Diagnostic{std::move(code), severity_from(severity), std::move(message), {line, column, std::move(file)}};
             }),
             py::arg("code"), py::arg("severity"), py::arg("message"), py::arg("line") = 0, py::arg("column") = 0,
             py::arg("file") = std::string())
        .def_readonly("code", &Diagnostic::code, pydoc::Diagnostic_code)
        .def_property_readonly("severity", [](const Diagnostic& d) { return severity_name(d.severity); },
                               pydoc::Diagnostic_severity)
        .def_property_readonly("message", [](const Diagnostic& d) { return text(d.message); },
                      pydoc::Diagnostic_message)
        /// @pydoc Diagnostic.line
        /// source line, 1-based; 0 when not tied to a line
        .def_property_readonly("line", [](const Diagnostic& d) { return d.pos.line; }, pydoc::Diagnostic_line)
        /// @pydoc Diagnostic.column
        /// source column, 1-based; 0 for the whole line
        .def_property_readonly("column", [](const Diagnostic& d) { return d.pos.column; }, pydoc::Diagnostic_column)
        /// @pydoc Diagnostic.file
        /// the called program or subprogram file the line is in; None for the main program
        .def_property_readonly(
            "file",
            [](const Diagnostic& d) -> py::typing::Optional<py::str> {
                return d.pos.file.empty() ? py::none() : py::object(text(d.pos.file));
            },
            pydoc::Diagnostic_file)
        .def("__repr__", [](const Diagnostic& d) {
            return "Diagnostic(code='" + d.code + "', severity='" + severity_name(d.severity) + "', message=" +
                   py::repr(text(d.message)).cast<std::string>() + ", line=" + std::to_string(d.pos.line) +
                   ", column=" + std::to_string(d.pos.column) + ")";
        })
        .def("__eq__", [](const Diagnostic& a, const Diagnostic& b) {
            return a.code == b.code && a.severity == b.severity && a.message == b.message &&
                   a.pos.line == b.pos.line && a.pos.column == b.pos.column && a.pos.file == b.pos.file;
        });

    /// @pydoc diagnostic_codes
    /// The catalogue of diagnostic codes: [{'code', 'kind' (the Error class), 'severity',
    /// 'alarm', 'text'}, ...]
    m.def(
        "diagnostic_codes",
        [] {
            py::list rows;
            for (const CodeInfo& c : code_catalogue()) {
                py::dict d;
                d["code"] = c.code;
                d["kind"] = c.kind == ErrorKind::generic ? "Error" : class_name(c.kind);
                d["severity"] = severity_name(c.severity);
                d["alarm"] = c.alarm;
                d["text"] = c.text;
                rows.append(d);
            }
            return rows;
        },
        pydoc::diagnostic_codes);

    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const Error& e) {
            py::object cls = py::module_::import("toolcomp._errors").attr(class_name(e.kind()));
            py::object exc = e.file().empty() ? cls(text(e.what()), e.code(), e.line(), e.column())
                                              : cls(text(e.what()), e.code(), e.line(), e.column(), text(e.file()));
            PyErr_SetObject(cls.ptr(), exc.ptr());
        }
    });
}
