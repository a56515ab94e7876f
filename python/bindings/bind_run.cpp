#include "bindings.hpp"

#include <pybind11/stl.h>

#include <pybind11/numpy.h>

#include "toolcomp/compensation/three_d.hpp"
#include "toolcomp/run.hpp"
#include "toolcomp/tools/tool_table.hpp"

using namespace toolcomp;

void bind_run(py::module_& m) {
    py::enum_<LengthAxes>(m, "LengthAxes")
        .value("all", LengthAxes::all)
        .value("z_only", LengthAxes::z_only)
        .value("plane_normal", LengthAxes::plane_normal);

    py::enum_<EntryStyle>(m, "EntryStyle")
        .value("perpendicular_to_entry", EntryStyle::perpendicular_to_entry)
        .value("perpendicular_to_next", EntryStyle::perpendicular_to_next)
        .value("around_start_when_behind", EntryStyle::around_start_when_behind);
    py::enum_<ExitStyle>(m, "ExitStyle")
        .value("perpendicular_to_last", ExitStyle::perpendicular_to_last)
        .value("corner_with_exit", ExitStyle::corner_with_exit);
    py::enum_<OutsideCorner>(m, "OutsideCorner")
        .value("arc", OutsideCorner::arc)
        .value("intersection", OutsideCorner::intersection)
        .value("extension", OutsideCorner::extension);
    py::enum_<GougeReaction>(m, "GougeReaction")
        .value("error", GougeReaction::error)
        .value("skip", GougeReaction::skip)
        .value("report", GougeReaction::report);
    py::enum_<NonPlaneReaction>(m, "NonPlaneReaction")
        .value("error", NonPlaneReaction::error)
        .value("overcut", NonPlaneReaction::overcut);

    py::class_<RadiusRules>(m, "RadiusRules", "How a control applies cutter radius compensation.")
        .def_readwrite("yz_plane", &RadiusRules::yz_plane)
        .def_readwrite("entry", &RadiusRules::entry)
        .def_readwrite("entry_arc", &RadiusRules::entry_arc)
        .def_readwrite("exit", &RadiusRules::exit)
        .def_readwrite("tip_convention", &RadiusRules::tip_convention)
        .def_readwrite("extension_min_length", &RadiusRules::extension_min_length, "mm")
        .def_readwrite("ct_radius_on_contour", &RadiusRules::ct_radius_on_contour)
        .def_readwrite("lct_tangency_tool_space", &RadiusRules::lct_tangency_tool_space)
        .def_readwrite("exit_must_be_straight", &RadiusRules::exit_must_be_straight)
        .def_readwrite("entry_length_check", &RadiusRules::entry_length_check)
        .def_readwrite("outside_corner", &RadiusRules::outside_corner)
        .def_readwrite("corner_limit", &RadiusRules::corner_limit, "radians")
        .def_readwrite("disc", &RadiusRules::disc, "Sinumerik DISC, 0..100")
        .def_readwrite("side_change", &RadiusRules::side_change)
        .def_readwrite("corner_tolerance", &RadiusRules::corner_tolerance, "radians")
        .def_property(
            "arc_sweep_tolerance",
            [](const RadiusRules& r) { return std::make_pair(r.arc_sweep_tolerance[0], r.arc_sweep_tolerance[1]); },
            [](RadiusRules& r, std::pair<double, double> v) {
                r.arc_sweep_tolerance[0] = v.first;
                r.arc_sweep_tolerance[1] = v.second;
            },
            "radians, (mm programs, inch programs)")
        .def_readwrite("max_non_plane_moves", &RadiusRules::max_non_plane_moves)
        .def_readwrite("non_plane_reaction", &RadiusRules::non_plane_reaction)
        .def_readwrite("lookahead", &RadiusRules::lookahead)
        .def_readwrite("gouge", &RadiusRules::gouge);

    py::enum_<TipConvention>(m, "TipConvention")
        .value("linuxcnc", TipConvention::linuxcnc)
        .value("fanuc", TipConvention::fanuc);
    py::enum_<Machine>(m, "Machine").value("mill", Machine::mill).value("lathe", Machine::lathe);

    py::class_<ControlProfile>(m, "ControlProfile")
        .def(py::init([](const std::string& dialect, const std::string& machine) {
                 if (machine != "mill" && machine != "lathe") throw py::value_error("machine must be 'mill' or 'lathe'");
                 return profile_for(dialect_from_name(dialect), machine == "lathe" ? Machine::lathe : Machine::mill);
             }),
             py::arg("dialect") = "linuxcnc", py::arg("machine") = "mill")
        .def_readonly("machine", &ControlProfile::machine)
        .def_readwrite("x_diameter", &ControlProfile::x_diameter)
        .def_readwrite("incremental_uw", &ControlProfile::incremental_uw)
        .def_readwrite("t_offsets", &ControlProfile::t_offsets)
        .def_readwrite("t_format", &ControlProfile::t_format)
        .def_readwrite("wear_sign", &ControlProfile::wear_sign)
        .def_readwrite("name", &ControlProfile::name)
        .def_readwrite("startup_inch", &ControlProfile::startup_inch)
        .def_readwrite("block_limit", &ControlProfile::block_limit, "blocks a program may execute (loops count)")
        .def_readwrite("length_axes", &ControlProfile::length_axes)
        .def_readwrite("length_subtract_word", &ControlProfile::length_subtract_word)
        .def_readwrite("radius", &ControlProfile::radius)
        .def("__repr__", [](const ControlProfile& p) { return "ControlProfile('" + p.name + "')"; });

    py::class_<Result, std::shared_ptr<Result>>(m, "Result")
        .def_property_readonly("ok", &Result::ok)
        .def_readonly("diagnostics", &Result::diagnostics)
        .def_property_readonly("nominal",
                               [](std::shared_ptr<Result> r) { return std::shared_ptr<Path>(r, &r->nominal); })
        .def_property_readonly("path", [](std::shared_ptr<Result> r) { return std::shared_ptr<Path>(r, &r->path); })
        .def_readonly("blocks", &Result::blocks)
        .def_property_readonly(
            "blank",
            [](const Result& r) -> py::object {
                if (!r.blank) return py::none();
                auto t = [](const Vec3& v) { return py::make_tuple(v.x(), v.y(), v.z()); };
                return py::make_tuple(t(r.blank->min), t(r.blank->max));
            },
            "the workpiece blank the program declares (Heidenhain BLK FORM), ((min), (max)) in mm, or None")
        .def("__repr__", [](const Result& r) {
            return "Result(ok=" + std::string(r.ok() ? "True" : "False") + ", segments=" +
                   std::to_string(r.path.size()) + ", diagnostics=" + std::to_string(r.diagnostics.size()) + ")";
        });

    m.def(
        "compensate_3d",
        [](py::array_t<double, py::array::c_style | py::array::forcecast> points,
           py::array_t<double, py::array::c_style | py::array::forcecast> normals, std::optional<py::array_t<double, py::array::c_style | py::array::forcecast>> tool_axes,
           double R, double R2, double DR, double DR2, const py::object& out) {
            auto shape_ok = [](const py::array& a) { return a.ndim() == 2 && a.shape(1) == 3; };
            if (!shape_ok(points) || !shape_ok(normals) || normals.shape(0) != points.shape(0))
                throw py::value_error("points and normals must be (N, 3) arrays of the same length");
            if (tool_axes && (!shape_ok(*tool_axes) || tool_axes->shape(0) != points.shape(0)))
                throw py::value_error("tool_axes must be an (N, 3) array like points");
            if (!(R >= 0) || !(R2 >= 0) || R2 > R) throw py::value_error("need 0 <= R2 <= R");
            const auto n = static_cast<std::size_t>(points.shape(0));
            // The result goes into `out` itself (no hidden copy), or a new array.
            py::array result = out.is_none() ? py::array(py::array_t<double>({points.shape(0), py::ssize_t(3)}))
                                             : out.cast<py::array>();
            if (!result.dtype().is(py::dtype::of<double>()) || !(result.flags() & py::array::c_style) ||
                !result.writeable() || !shape_ok(result) || static_cast<std::size_t>(result.shape(0)) != n)
                throw py::value_error("out must be a writeable C-contiguous float64 array of shape (N, 3)");
            const double* p = points.data();
            const double* q = normals.data();
            const double* t = tool_axes ? tool_axes->data() : nullptr;
            double* o = static_cast<double*>(result.mutable_data());
            {
                py::gil_scoped_release nogil;
                compensate_3d(p, q, t, n, DR, DR2, o);
            }
            return result;
        },
        py::arg("points"), py::arg("normals"), py::arg("tool_axes") = py::none(), py::kw_only(), py::arg("R"),
        py::arg("R2"), py::arg("DR") = 0.0, py::arg("DR2") = 0.0, py::arg("out") = py::none(),
        "3D tool compensation of CAM tool datum points along surface normals: PT + DR2*N - (DR - DR2)*w "
        "(the same code as Heidenhain LN blocks). Arrays are (N, 3) float64; C-contiguous input is not "
        "copied, and `out` (which may be `points`) receives the result.");

    m.def(
        "run",
        [](const Program& program, const ToolTable* tools, bool strict, bool block_delete,
           std::optional<ControlProfile> profile, py::object progress, std::size_t progress_every) {
            RunOptions o;
            o.strict = strict;
            o.block_delete = block_delete;
            o.profile = std::move(profile);
            o.progress_every = progress_every;
            if (!progress.is_none())
                o.progress = [&progress](std::size_t n) {
                    py::gil_scoped_acquire gil;
                    progress(n);  // a Python exception (Ctrl-C) stops the run
                };
            py::gil_scoped_release nogil;
            return std::make_shared<Result>(run(program, tools, o));
        },
        py::arg("program"), py::arg("tools") = nullptr, py::arg("strict") = true, py::arg("block_delete") = false,
        py::arg("profile") = py::none(), py::arg("progress") = py::none(), py::arg("progress_every") = 1 << 16);
}
