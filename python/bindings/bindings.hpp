#pragma once
// Declarations shared by the binding files. The binding layer is thin: conversions and
// names only, no logic.
#include <pybind11/pybind11.h>

#include <array>
#include <optional>

#include "toolcomp/geometry/vec.hpp"
#include "toolcomp/tools/tool_table.hpp"

// pydoc::NAME: the docstrings, generated at build time from the /// comments of the headers
// and of the binding files (python/tools/gen_docstrings.py; doc/developing.md).
#include "pydoc.hpp"

namespace py = pybind11;

// What the engine reads with the GIL released is its own copy, taken while the GIL is held:
// another Python thread may change the caller's ToolTable meanwhile (set, remove), and a run
// or a write must see one consistent table, never a vector being resized under it.
inline std::optional<toolcomp::ToolTable> snapshot(const toolcomp::ToolTable* t) {
    return t ? std::optional<toolcomp::ToolTable>(*t) : std::nullopt;
}
inline const toolcomp::ToolTable* ptr(const std::optional<toolcomp::ToolTable>& t) { return t ? &*t : nullptr; }

// run(start=...): (x, y, z) machine coordinates, mm, finite; None: not given.
std::optional<toolcomp::Vec3> start_position(const std::optional<std::array<double, 3>>& xyz);

void bind_errors(py::module_& m);
void bind_program(py::module_& m);
void bind_path(py::module_& m);
void bind_path_text(py::module_& m);
void bind_geometry(py::module_& m);
void bind_run(py::module_& m);
void bind_run_calls(py::module_& m);  // run(), run_file(): after bind_machine (their signatures name Machine)
void bind_machine(py::module_& m);
void bind_stream(py::module_& m);
void bind_tools(py::module_& m);
