// PathStream: a run's compensated path in chunks (the iterator behind toolcomp.iter_run).
#include "bindings.hpp"

#include <chrono>

#include <pybind11/stl.h>

#include "toolcomp/stream.hpp"

using namespace toolcomp;

namespace {
StreamOptions stream_options(bool strict, bool block_delete, std::optional<ControlProfile> profile,
                             std::vector<std::string> search_path, std::map<int, double> parameters,
                             std::size_t chunk, std::size_t piece_bytes, std::uint64_t max_bytes,
                             std::size_t max_line_length, bool follow_links, const std::optional<Machine>& machine,
                             const std::optional<std::array<double, 3>>& start) {
    StreamOptions o;
    o.run.start = start_position(start);
    if (machine) o.run.machine = std::make_shared<const Machine>(*machine);
    o.run.follow_links = follow_links;
    o.run.strict = strict;
    o.run.block_delete = block_delete;
    o.run.profile = std::move(profile);
    o.run.search_path = std::move(search_path);
    o.run.parameters = std::move(parameters);
    o.chunk = chunk;
    o.piece_bytes = piece_bytes;
    o.read.max_bytes = max_bytes;
    o.read.max_line_length = max_line_length;
    return o;
}
}  // namespace

void bind_stream(py::module_& m) {
    py::class_<PathStream, std::shared_ptr<PathStream>>(
        m, "PathStream", pydoc::PathStream)
        .def("__iter__", [](std::shared_ptr<PathStream> self) { return self; })
        .def("__next__",
             [](PathStream& s) {
                 // Waits in slices, so that Ctrl-C (KeyboardInterrupt) is seen while a chunk is made.
                 for (;;) {
                     bool ready;
                     {
                         py::gil_scoped_release nogil;
                         ready = s.wait_for(std::chrono::milliseconds(50));
                     }
                     if (ready) break;
                     if (PyErr_CheckSignals() != 0) throw py::error_already_set();
                 }
                 std::optional<Path> p;
                 {
                     py::gil_scoped_release nogil;
                     p = s.next();
                 }
                 if (!p) throw py::stop_iteration();
                 return std::make_shared<Path>(std::move(*p));
             })
        .def("close", [](PathStream& s) {
            py::gil_scoped_release nogil;
            s.close();
        }, pydoc::PathStream_close)
        .def("__enter__", [](std::shared_ptr<PathStream> self) { return self; })
        .def("__exit__", [](PathStream& s, py::args) {
            py::gil_scoped_release nogil;
            s.close();
        })
        .def_property_readonly("diagnostics", &PathStream::diagnostics, pydoc::PathStream_diagnostics)
        .def_property_readonly("blocks", &PathStream::blocks, pydoc::PathStream_blocks)
        .def_property_readonly("blocks_read", &PathStream::blocks_read, pydoc::PathStream_blocks_read)
        .def_property_readonly("dialect", [](const PathStream& s) { return std::string(dialect_name(s.dialect())); },
                               pydoc::PathStream_dialect)
        .def_property_readonly("programmed_segments", &PathStream::programmed_segments,
                               pydoc::PathStream_programmed_segments)
        .def_property_readonly("files", &PathStream::files, pydoc::PathStream_files);

    /// @pydoc iter_run_file
    /// A PathStream over a program file (see toolcomp.iter_run).
    m.def(
        "iter_run_file",
        [](const std::string& path, std::optional<std::string> dialect, const ToolTable* tools, bool strict,
           bool block_delete, std::optional<ControlProfile> profile, std::vector<std::string> search_path,
           std::map<int, double> parameters, std::size_t chunk, std::size_t piece_bytes, std::uint64_t max_bytes,
           std::size_t max_line_length, bool follow_links, std::optional<Machine> machine,
           std::optional<std::array<double, 3>> start) {
            std::optional<Dialect> d;
            if (dialect) d = dialect_from_name(*dialect);
            return std::make_shared<PathStream>(path, d, snapshot(tools),
                                                stream_options(strict, block_delete, std::move(profile),
                                                               std::move(search_path), std::move(parameters), chunk,
                                                               piece_bytes, max_bytes, max_line_length, follow_links,
                                                               machine, start));
        },
        py::arg("path"), py::arg("dialect"), py::arg("tools"), py::arg("strict"), py::arg("block_delete"),
        py::arg("profile"), py::arg("search_path"), py::arg("parameters"), py::arg("chunk"), py::arg("piece_bytes"),
        py::arg("max_bytes"), py::arg("max_line_length"), py::arg("follow_links") = false,
        py::arg("machine") = py::none(), py::arg("start") = py::none(), pydoc::iter_run_file);
    /// @pydoc iter_run_program
    /// A PathStream over a parsed Program (see toolcomp.iter_run).
    m.def(
        "iter_run_program",
        [](std::shared_ptr<Program> program, const ToolTable* tools, bool strict, bool block_delete,
           std::optional<ControlProfile> profile, std::vector<std::string> search_path,
           std::map<int, double> parameters, std::size_t chunk, std::uint64_t max_bytes, std::size_t max_line_length,
           bool follow_links, std::optional<Machine> machine, std::optional<std::array<double, 3>> start) {
            return std::make_shared<PathStream>(std::shared_ptr<const Program>(std::move(program)), snapshot(tools),
                                                stream_options(strict, block_delete, std::move(profile),
                                                               std::move(search_path), std::move(parameters), chunk,
                                                               kPieceBytes, max_bytes, max_line_length, follow_links,
                                                               machine, start));
        },
        py::arg("program"), py::arg("tools"), py::arg("strict"), py::arg("block_delete"), py::arg("profile"),
        py::arg("search_path"), py::arg("parameters"), py::arg("chunk"),
        py::arg("max_bytes") = kDefaultMaxProgramBytes, py::arg("max_line_length") = kDefaultMaxLineLength,
        py::arg("follow_links") = false, py::arg("machine") = py::none(), py::arg("start") = py::none(),
        pydoc::iter_run_program);
}
