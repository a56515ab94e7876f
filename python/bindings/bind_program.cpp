#include "bindings.hpp"

#include <pybind11/stl.h>

#include "toolcomp/run.hpp"

using namespace toolcomp;

void bind_program(py::module_& m) {
    py::class_<Program, std::shared_ptr<Program>>(
        m, "Program", pydoc::Program)
        /// @pydoc Program.read
        /// Read a part program; the dialect comes from the suffix unless given.
        /// strict=False keeps the blocks before a syntax error and raises it when a run
        /// reaches that line. Only a regular file of at most max_bytes bytes (default 2
        /// GiB) is read, its size checked before reading (ParseError
        /// 'not_a_regular_file' for a FIFO, device or directory; 'input_too_large'); a
        /// line longer than max_line_length bytes (default 1 MiB) raises ParseError
        /// 'line_too_long' with its line, whatever strict is.
        .def_static(
            "read",
            [](const py::object& path_like, std::optional<std::string> dialect, bool strict, std::uint64_t max_bytes,
               std::size_t max_line_length) {
                std::string path = py::module_::import("os").attr("fspath")(path_like).cast<std::string>();
                std::optional<Dialect> d;
                if (dialect) d = dialect_from_name(*dialect);
                py::gil_scoped_release nogil;
                return std::make_shared<Program>(read_program(path, d, strict, {max_bytes, max_line_length}));
            },
            py::arg("path"), py::arg("dialect") = py::none(), py::arg("strict") = true, py::kw_only(),
            py::arg("max_bytes") = kDefaultMaxProgramBytes, py::arg("max_line_length") = kDefaultMaxLineLength,
            pydoc::Program_read)
        /// @pydoc Program.check_file
        /// Read a program file through as Program.read(strict=True) does, without
        /// keeping it: returns its number of blocks, or raises its first syntax error,
        /// wherever it is (also after M2/M30). The file is read a piece at a time, in
        /// bounded memory and without a size limit (as iter_run reads it).
        .def_static(
            "check_file",
            [](const py::object& path_like, std::optional<std::string> dialect, std::size_t max_line_length) {
                std::string path = py::module_::import("os").attr("fspath")(path_like).cast<std::string>();
                std::optional<Dialect> d;
                if (dialect) d = dialect_from_name(*dialect);
                py::gil_scoped_release nogil;
                return check_program_file(path, d, {kDefaultMaxProgramBytes, max_line_length});
            },
            py::arg("path"), py::arg("dialect") = py::none(), py::kw_only(),
            py::arg("max_line_length") = kDefaultMaxLineLength, pydoc::Program_check_file)
        /// @pydoc Program.parse
        /// Parse program text in the given dialect. A line longer than max_line_length
        /// bytes (default 1 MiB) raises ParseError 'line_too_long' with its line,
        /// whatever strict is.
        .def_static(
            "parse",
            [](const std::string& text, const std::string& dialect, std::string name, bool strict,
               std::size_t max_line_length) {
                Dialect d = dialect_from_name(dialect);
                py::gil_scoped_release nogil;
                return std::make_shared<Program>(parse_program(text, d, std::move(name), strict, max_line_length));
            },
            py::arg("text"), py::arg("dialect") = "linuxcnc", py::arg("name") = "<string>", py::arg("strict") = true,
            py::kw_only(), py::arg("max_line_length") = kDefaultMaxLineLength, pydoc::Program_parse)
        .def_readonly("name", &Program::name, pydoc::Program_name)
        .def_property_readonly("dialect", [](const Program& p) { return std::string(dialect_name(p.dialect)); },
                               pydoc::Program_dialect)
        .def_property_readonly("word_count", &Program::word_count, pydoc::Program_word_count)
        .def_property_readonly("syntax_error", [](const Program& p) { return p.syntax_error; },
                               pydoc::Program_syntax_error)
        .def("__len__", &Program::size, pydoc::Program_size)
        .def("__repr__", [](const Program& p) {
            return "Program(name='" + p.name + "', dialect='" + std::string(dialect_name(p.dialect)) +
                   "', blocks=" + std::to_string(p.size()) + ")";
        });
    /// @pydoc dialect_of_file
    /// The dialect a program file is read in: `dialect` if given, else from its suffix
    /// (ParseError otherwise).
    m.def(
        "dialect_of_file",
        [](const std::string& path, std::optional<std::string> dialect) {
            std::optional<Dialect> d;
            if (dialect) d = dialect_from_name(*dialect);
            return std::string(dialect_name(dialect_of_file(path, d)));
        },
        py::arg("path"), py::arg("dialect") = py::none(), pydoc::dialect_of_file);
    /// @pydoc dialect_table
    /// The dialects toolcomp reads: [{'name': 'linuxcnc', 'suffixes': ['.ngc']}, ...], from
    /// the engine's table.
    m.def(
        "dialect_table",
        [] {
            py::list rows;
            for (const DialectNames& r : dialect_names()) {
                py::list suffixes;
                for (std::string_view s : r.suffixes)
                    if (!s.empty()) suffixes.append(py::str("." + std::string(s)));
                py::dict d;
                d["name"] = std::string(r.name);
                d["suffixes"] = suffixes;
                rows.append(d);
            }
            return rows;
        },
        pydoc::dialect_table);
}
