#pragma once
// Declarations shared by the binding files. The binding layer is thin: conversions and
// names only, no logic.
#include <pybind11/pybind11.h>

namespace py = pybind11;

void bind_errors(py::module_& m);
void bind_program(py::module_& m);
void bind_path(py::module_& m);
void bind_path_text(py::module_& m);
void bind_geometry(py::module_& m);
void bind_run(py::module_& m);
void bind_stream(py::module_& m);
void bind_tools(py::module_& m);
