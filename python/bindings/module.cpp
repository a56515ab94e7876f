// toolcomp._core: the compiled core. The public API is the pure-Python package `toolcomp`,
// which re-exports these names.
#include "bindings.hpp"

#include "toolcomp/motion/motion.hpp"

void bind_sinumerik(py::module_& m);  // bind_sinumerik.cpp: the submodule _core.sinumerik

/// @pydoc _core
/// toolcomp core: CNC program interpreter and tool compensation engine
PYBIND11_MODULE(_core, m) {
    m.doc() = pydoc::_core;
    m.attr("__version__") = TOOLCOMP_VERSION;
    m.attr("RAPID") = static_cast<int>(toolcomp::MotionKind::rapid);
    m.attr("LINE") = static_cast<int>(toolcomp::MotionKind::line);
    m.attr("ARC_CW") = static_cast<int>(toolcomp::MotionKind::arc_cw);
    m.attr("ARC_CCW") = static_cast<int>(toolcomp::MotionKind::arc_ccw);
    bind_errors(m);
    bind_tools(m);
    bind_program(m);
    bind_path(m);
    bind_path_text(m);
    bind_geometry(m);
    bind_run(m);
    bind_machine(m);
    bind_run_calls(m);
    bind_stream(m);
    bind_sinumerik(m);
}
