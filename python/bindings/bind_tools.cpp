// Tool model and tool tables. Value semantics: a Tool or CuttingEdge taken from a table is a
// copy; change it and put it back with ToolTable.set / Tool.set_edge. (References into a
// table would dangle once the table grows.) Errors propagate as C++ toolcomp::Error and are
// translated by bind_errors.
#include "bindings.hpp"

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/operators.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "toolcomp/tools/tool_table.hpp"

using namespace toolcomp;

namespace {

// A read-only float64 (3,) view of three doubles owned by the Python object `owner`.
py::array vec3_view(const double* p, py::handle owner) {
    py::array_t<double> a({py::ssize_t{3}}, {py::ssize_t{sizeof(double)}}, p, owner);
    py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
    return a;
}

std::array<double, 3> to_array3(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

std::optional<TableFormat> format_arg(const std::optional<std::string>& f) {
    if (!f) return std::nullopt;
    return table_format_from_string(*f);
}

}  // namespace

void bind_tools(py::module_& m) {
    py::class_<CuttingEdge>(m, "CuttingEdge", pydoc::CuttingEdge)
        .def(py::init([](int number, const Eigen::Vector3d& length, double radius, double corner_radius,
                         const Eigen::Vector3d& rotary, const Eigen::Vector3d& uvw, const Eigen::Vector3d& length_wear,
                         double radius_wear, double corner_radius_wear, int orientation, double front_angle,
                         double back_angle) {
                 CuttingEdge e;
                 e.number = number;
                 e.length = length;
                 e.radius = radius;
                 e.corner_radius = corner_radius;
                 e.rotary = to_array3(rotary);
                 e.uvw = to_array3(uvw);
                 e.length_wear = length_wear;
                 e.radius_wear = radius_wear;
                 e.corner_radius_wear = corner_radius_wear;
                 e.orientation = orientation;
                 e.front_angle = front_angle;
                 e.back_angle = back_angle;
                 return e;
             }),
             py::kw_only(), py::arg("number") = 1, py::arg("length") = Eigen::Vector3d::Zero().eval(),
             py::arg("radius") = 0.0, py::arg("corner_radius") = 0.0,
             py::arg("rotary") = Eigen::Vector3d::Zero().eval(), py::arg("uvw") = Eigen::Vector3d::Zero().eval(),
             py::arg("length_wear") = Eigen::Vector3d::Zero().eval(), py::arg("radius_wear") = 0.0,
             py::arg("corner_radius_wear") = 0.0, py::arg("orientation") = 0, py::arg("front_angle") = 0.0,
             py::arg("back_angle") = 0.0)
        .def_readwrite("number", &CuttingEdge::number, pydoc::CuttingEdge_number)
        .def_property(
            "length", [](py::object self) { return vec3_view(self.cast<CuttingEdge&>().length.data(), self); },
            [](CuttingEdge& e, const Eigen::Vector3d& v) { e.length = v; }, pydoc::CuttingEdge_length)
        .def_property(
            "length_wear",
            [](py::object self) { return vec3_view(self.cast<CuttingEdge&>().length_wear.data(), self); },
            [](CuttingEdge& e, const Eigen::Vector3d& v) { e.length_wear = v; }, pydoc::CuttingEdge_length_wear)
        .def_property(
            "rotary", [](py::object self) { return vec3_view(self.cast<CuttingEdge&>().rotary.data(), self); },
            [](CuttingEdge& e, const Eigen::Vector3d& v) { e.rotary = to_array3(v); }, pydoc::CuttingEdge_rotary)
        .def_property(
            "uvw", [](py::object self) { return vec3_view(self.cast<CuttingEdge&>().uvw.data(), self); },
            [](CuttingEdge& e, const Eigen::Vector3d& v) { e.uvw = to_array3(v); }, pydoc::CuttingEdge_uvw)
        .def_readwrite("radius", &CuttingEdge::radius, pydoc::CuttingEdge_radius)
        .def_readwrite("corner_radius", &CuttingEdge::corner_radius, pydoc::CuttingEdge_corner_radius)
        .def_readwrite("radius_wear", &CuttingEdge::radius_wear, pydoc::CuttingEdge_radius_wear)
        .def_readwrite("corner_radius_wear", &CuttingEdge::corner_radius_wear, pydoc::CuttingEdge_corner_radius_wear)
        .def_readwrite("orientation", &CuttingEdge::orientation, pydoc::CuttingEdge_orientation)
        .def_readwrite("front_angle", &CuttingEdge::front_angle, pydoc::CuttingEdge_front_angle)
        .def_readwrite("back_angle", &CuttingEdge::back_angle, pydoc::CuttingEdge_back_angle)
        .def_property_readonly("effective_length", &CuttingEdge::effective_length, pydoc::CuttingEdge_effective_length)
        /// @pydoc CuttingEdge.shape
        /// end_mill (R2 = 0), ball (R2 = R) or toroid, from the effective radii
        .def_property_readonly(
            "shape",
            [](const CuttingEdge& e) {
                switch (tool_shape(e)) {
                    case ToolShape::ball: return "ball";
                    case ToolShape::toroid: return "toroid";
                    default: return "end_mill";
                }
            },
            pydoc::CuttingEdge_shape)
        .def_property_readonly("effective_radius", &CuttingEdge::effective_radius, pydoc::CuttingEdge_effective_radius)
        .def_property_readonly("effective_corner_radius", &CuttingEdge::effective_corner_radius,
                               pydoc::CuttingEdge_effective_corner_radius)
        .def(py::self == py::self)
        .def(py::self != py::self)
        .def("__copy__", [](const CuttingEdge& e) { return e; })
        .def("__deepcopy__", [](const CuttingEdge& e, py::dict) { return e; }, py::arg("memo"))
        .def("__repr__", [](const CuttingEdge& e) {
            return "CuttingEdge(number=" + std::to_string(e.number) + ", radius=" +
                   py::repr(py::float_(e.radius)).cast<std::string>() + ", length=(" +
                   py::repr(py::float_(e.length.x())).cast<std::string>() + ", " +
                   py::repr(py::float_(e.length.y())).cast<std::string>() + ", " +
                   py::repr(py::float_(e.length.z())).cast<std::string>() +
                   "), orientation=" + std::to_string(e.orientation) + ")";
        });

    py::class_<Tool>(m, "Tool", pydoc::Tool)
        .def(py::init([](int number, int pocket, std::string name, std::string comment,
                         std::optional<std::vector<CuttingEdge>> edges) {
                 Tool t;
                 t.number = number;
                 t.pocket = pocket;
                 t.name = std::move(name);
                 t.comment = std::move(comment);
                 if (edges) t.edges = std::move(*edges);
                 return t;
             }),
             py::arg("number") = 0, py::kw_only(), py::arg("pocket") = 0, py::arg("name") = "",
             py::arg("comment") = "", py::arg("edges") = py::none())
        .def_readwrite("number", &Tool::number, pydoc::Tool_number)
        .def_readwrite("pocket", &Tool::pocket, pydoc::Tool_pocket)
        .def_readwrite("name", &Tool::name, pydoc::Tool_name)
        .def_readwrite("comment", &Tool::comment, pydoc::Tool_comment)
        .def_property(
            "edges", [](const Tool& t) { return py::tuple(py::cast(t.edges)); },
            [](Tool& t, std::vector<CuttingEdge> edges) { t.edges = std::move(edges); }, pydoc::Tool_edges)
        .def("edge", py::overload_cast<int>(&Tool::edge, py::const_), py::arg("d") = 1,
             py::return_value_policy::copy, pydoc::Tool_edge)
        .def("has_edge", &Tool::has_edge, py::arg("d"), pydoc::Tool_has_edge)
        .def("set_edge", &Tool::set_edge, py::arg("edge"), pydoc::Tool_set_edge)
        .def(py::self == py::self)
        .def(py::self != py::self)
        .def("__copy__", [](const Tool& t) { return t; })
        .def("__deepcopy__", [](const Tool& t, py::dict) { return t; }, py::arg("memo"))
        .def("__repr__", [](const Tool& t) {
            return "Tool(" + std::to_string(t.number) + ", pocket=" + std::to_string(t.pocket) +
                   ", name=" + py::repr(py::str(t.name)).cast<std::string>() +
                   ", comment=" + py::repr(py::str(t.comment)).cast<std::string>() +
                   ", edges=" + std::to_string(t.edges.size()) + ")";
        });

    py::class_<ToolTable>(m, "ToolTable", pydoc::ToolTable)
        .def(py::init([](const std::string& units) { return ToolTable(length_unit_from_string(units)); }),
             py::arg("units") = "mm")
        /// @pydoc ToolTable.read
        /// Read a table; format ('linuxcnc'/'tbl', 'csv', 'json', 'heidenhain'/'t')
        /// from the suffix unless given; units ('mm'/'inch') of the file's lengths (a
        /// JSON file's "units" or a TOOL.T's BEGIN line wins). Only a regular file of
        /// at most max_bytes bytes (default 256 MiB) is read (ToolTableError
        /// 'not_a_regular_file', 'input_too_large').
        .def_static(
            "read",
            [](const std::filesystem::path& path, std::optional<std::string> format, const std::string& units,
               std::uint64_t max_bytes) {
                const auto f = format_arg(format);
                const LengthUnit u = length_unit_from_string(units);
                py::gil_scoped_release nogil;
                return read_tool_table_file(path.string(), f, u, max_bytes);
            },
            py::arg("path"), py::arg("format") = py::none(), py::arg("units") = "mm", py::kw_only(),
            py::arg("max_bytes") = kDefaultMaxTableBytes, pydoc::ToolTable_read)
        /// @pydoc ToolTable.parse
        /// Parse table text.
        .def_static(
            "parse",
            [](const std::string& text, const std::string& format, const std::string& units) {
                const TableFormat f = table_format_from_string(format);
                const LengthUnit u = length_unit_from_string(units);
                py::gil_scoped_release nogil;
                return read_tool_table(text, f, u);
            },
            py::arg("text"), py::arg("format"), py::arg("units") = "mm", pydoc::ToolTable_parse)
        /// @pydoc ToolTable.write
        /// Write the table (temporary file, fsync, rename: the file is always the
        /// complete old or new table); format from the suffix unless given. Unchanged
        /// tools keep their original text. A second writer of the same table meanwhile
        /// raises ToolTableError('table_locked').
        .def(
            "write",
            [](const ToolTable& t, const std::filesystem::path& path, std::optional<std::string> format) {
                const auto f = format_arg(format);
                const ToolTable copy = t;
                {
                    py::gil_scoped_release nogil;
                    write_tool_table_file(copy, path.string(), f);
                }
                t.set_file_stamp(copy.file_stamp());  // what the file on disk now is
            },
            py::arg("path"), py::arg("format") = py::none(), pydoc::ToolTable_write)
        /// @pydoc ToolTable.dumps
        /// The table as text in the given format.
        .def(
            "dumps",
            [](const ToolTable& t, const std::string& format) {
                const TableFormat f = table_format_from_string(format);
                const ToolTable copy = t;
                py::gil_scoped_release nogil;
                return write_tool_table(copy, f);
            },
            py::arg("format"), pydoc::ToolTable_dumps)
        .def("__getitem__", &ToolTable::at, py::arg("number"), py::return_value_policy::copy, pydoc::ToolTable_at)
        /// @pydoc ToolTable.get
        /// a copy of tool `number`, or None
        .def(
            "get", [](const ToolTable& t, int n) -> std::optional<Tool> {
                if (const Tool* p = t.find(n)) return *p;
                return std::nullopt;
            },
            py::arg("number"), pydoc::ToolTable_get)
        .def("__contains__", &ToolTable::contains, py::arg("number"))
        .def("__len__", &ToolTable::size)
        /// @pydoc ToolTable.__iter__
        /// iterate over copies of the tools, in file order
        .def("__iter__", [](const ToolTable& t) { return py::iter(py::cast(t.tools())); }, pydoc::ToolTable___iter__)
        .def_property_readonly("tools", [](const ToolTable& t) { return py::tuple(py::cast(t.tools())); },
                               pydoc::ToolTable_tools)
        /// @pydoc ToolTable.numbers
        /// the tool numbers, in file order (a list)
        .def_property_readonly("numbers",
                               [](const ToolTable& t) {
                                   py::list out;
                                   for (const Tool& tool : t.tools()) out.append(tool.number);
                                   return out;
                               },
                               pydoc::ToolTable_numbers)
        .def("set", &ToolTable::set, py::arg("tool"), pydoc::ToolTable_set)
        .def("remove", &ToolTable::remove, py::arg("number"), pydoc::ToolTable_remove)
        .def_property(
            "units", [](const ToolTable& t) { return std::string(to_string(t.units())); },
            [](ToolTable& t, const std::string& u) { t.set_units(length_unit_from_string(u)); }, pydoc::ToolTable_units)
        /// @pydoc ToolTable.format
        /// the format the table was read from, or None
        .def_property_readonly(
            "format",
            [](const ToolTable& t) -> std::optional<std::string> {
                if (auto f = t.source_format()) return std::string(to_string(*f));
                return std::nullopt;
            },
            pydoc::ToolTable_format)
        .def("__copy__", [](const ToolTable& t) { return t; })
        .def("__deepcopy__", [](const ToolTable& t, py::dict) { return t; }, py::arg("memo"))
        .def("__repr__", [](const ToolTable& t) {
            return "ToolTable(" + std::to_string(t.size()) + " tools, units='" + std::string(to_string(t.units())) +
                   "')";
        });
}
