// Sinumerik 840D tool data, GETTCOR and toolholders: the submodule toolcomp._core.sinumerik
// (re-exported as toolcomp.sinumerik). Thin: conversions and names only; every computation and
// every check is in cpp/include/toolcomp/tools/sinumerik_*.hpp and compensation/toolholder.hpp.
// C++ toolcomp::Error is translated by bind_errors (ToolTableError, CompensationError).
//
// Conventions of the Python API:
// * Planes are given as 17, 18, 19 (G17 = XY, G18 = ZX, G19 = YZ) or the strings "G17",
//   "G18", "G19" (case-insensitive); anything else raises ValueError.
// * Vectors are float64 numpy arrays of shape (3,) in geometry-axis order X, Y, Z.
// * Edge.dp / .ecp / .scp are writable float64 (25,) views: index i holds $TC_DP(i+1).
#include "bindings.hpp"

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "toolcomp/compensation/toolholder.hpp"
#include "toolcomp/program/diagnostic.hpp"
#include "toolcomp/tools/sinumerik_edge.hpp"
#include "toolcomp/tools/sinumerik_gettcor.hpp"
#include "toolcomp/tools/sinumerik_settcor.hpp"
#include "toolcomp/tools/sinumerik_lentoax.hpp"

using namespace toolcomp;
using namespace toolcomp::sinumerik;

namespace {

// A writable float64 (n,) view of doubles owned by the Python object `owner`.
py::array array_view(double* p, py::ssize_t n, py::handle owner) {
    return py::array_t<double>({n}, {py::ssize_t{sizeof(double)}}, p, owner);
}

void assign25(std::array<double, 25>& dst, const std::array<double, 25>& src) { dst = src; }

Plane plane_from_int(int g) {
    switch (g) {
        case 17: return Plane::xy;
        case 18: return Plane::zx;
        case 19: return Plane::yz;
        default: throw py::value_error("plane must be 17, 18, 19 or 'G17', 'G18', 'G19'");
    }
}

Plane plane_arg(const py::handle& p) {
    if (py::isinstance<py::str>(p)) {
        std::string s = p.cast<std::string>();
        if (s.size() == 3 && (s[0] == 'G' || s[0] == 'g')) {
            if (s.substr(1) == "17") return Plane::xy;
            if (s.substr(1) == "18") return Plane::zx;
            if (s.substr(1) == "19") return Plane::yz;
        }
        throw py::value_error("plane must be 17, 18, 19 or 'G17', 'G18', 'G19', not '" + s + "'");
    }
    if (py::isinstance<py::int_>(p) && !py::isinstance<py::bool_>(p)) return plane_from_int(p.cast<int>());
    throw py::type_error("plane must be an int (17, 18, 19) or a str ('G17', 'G18', 'G19')");
}

int plane_number(Plane p) {
    switch (p) {
        case Plane::zx: return 18;
        case Plane::yz: return 19;
        default: return 17;
    }
}

std::string repr_float(double v) { return py::repr(py::float_(v)).cast<std::string>(); }

std::string repr_vec(const Vec3& v) {
    return "(" + repr_float(v.x()) + ", " + repr_float(v.y()) + ", " + repr_float(v.z()) + ")";
}

std::string read_text(const std::filesystem::path& path) {
    std::ifstream f(path, std::ios::binary);
    if (!f) throw ToolTableError("file_not_found", "Cannot open tool data file '" + path.string() + "'");
    std::ostringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

py::tuple gettcor_result(int status, const std::array<double, 11>& len) {
    return py::make_tuple(status, py::array_t<double>(py::ssize_t{11}, len.data()));
}

GettcorSettings settings_arg(const std::optional<GettcorSettings>& s, const py::object& plane) {
    GettcorSettings out = s.value_or(GettcorSettings{});
    if (!plane.is_none()) out.plane = plane_arg(plane);
    return out;
}

}  // namespace

void bind_sinumerik(py::module_& parent) {
    /// @pydoc sinumerik
    /// Sinumerik 840D tool data: $TC_DP cutting edges, tool lengths by plane, the $TC_DP
    /// file form, GETTCOR, toolholders ($TC_CARR) and TRAFO5 data. Planes are 17/18/19 or
    /// 'G17'/'G18'/'G19'; vectors are float64 (3,) arrays in X, Y, Z order.
    py::module_ m = parent.def_submodule(
        "sinumerik", pydoc::sinumerik);

    // ---- cutting edges -----------------------------------------------------------------
    py::class_<SinumerikEdge>(m, "Edge", pydoc::sinumerik_SinumerikEdge)
        /// @pydoc sinumerik.Edge.__init__
        /// dp: {n: value} for $TC_DPn (n = 1..25; ToolTableError 'sinumerik_bad_dp' otherwise)
        .def(py::init([](const std::optional<std::map<int, double>>& dp, int dl) {
                 SinumerikEdge e;
                 e.dl = dl;
                 if (dp)
                     for (const auto& [n, v] : *dp) e.DP(n) = v;
                 return e;
             }),
             py::arg("dp") = py::none(), py::kw_only(), py::arg("dl") = 1, pydoc::sinumerik_Edge___init__)
        .def_property(
            "dp", [](py::object self) { return array_view(self.cast<SinumerikEdge&>().dp.data(), 25, self); },
            [](SinumerikEdge& e, const std::array<double, 25>& v) { assign25(e.dp, v); },
            pydoc::sinumerik_SinumerikEdge_dp)
        .def_property(
            "ecp", [](py::object self) { return array_view(self.cast<SinumerikEdge&>().ecp.data(), 25, self); },
            [](SinumerikEdge& e, const std::array<double, 25>& v) { assign25(e.ecp, v); },
            pydoc::sinumerik_SinumerikEdge_ecp)
        .def_property(
            "scp", [](py::object self) { return array_view(self.cast<SinumerikEdge&>().scp.data(), 25, self); },
            [](SinumerikEdge& e, const std::array<double, 25>& v) { assign25(e.scp, v); },
            pydoc::sinumerik_SinumerikEdge_scp)
        .def_readwrite("dl", &SinumerikEdge::dl, pydoc::sinumerik_SinumerikEdge_dl)
        .def("get_dp", py::overload_cast<int>(&SinumerikEdge::DP, py::const_), py::arg("n"), pydoc::sinumerik_SinumerikEdge_DP)
        /// @pydoc sinumerik.Edge.set_dp
        /// $TC_DPn = value, n = 1..25
        .def(
            "set_dp", [](SinumerikEdge& e, int n, double v) { e.DP(n) = v; }, py::arg("n"), py::arg("value"),
            pydoc::sinumerik_Edge_set_dp)
        .def("get_ecp", &SinumerikEdge::ECP, py::arg("n"), pydoc::sinumerik_SinumerikEdge_ECP)
        .def("get_scp", &SinumerikEdge::SCP, py::arg("n"), pydoc::sinumerik_SinumerikEdge_SCP)
        .def_property_readonly("tool_type", &SinumerikEdge::type, pydoc::sinumerik_SinumerikEdge_type)
        /// @pydoc sinumerik.Edge.cutting_edge_position
        /// DP2, the cutting-edge position (turning tools, 1..9)
        .def_property_readonly(
            "cutting_edge_position", [](const SinumerikEdge& e) { return e.DP(2); },
            pydoc::sinumerik_Edge_cutting_edge_position)
        .def("length", &SinumerikEdge::length, py::arg("i"), py::arg("wear_sign") = 1.0,
             pydoc::sinumerik_SinumerikEdge_length)
        .def(
            "radius", [](const SinumerikEdge& e, double offn, double wear_sign) { return e.radius(wear_sign, offn); },
            py::arg("offn") = 0.0, py::kw_only(), py::arg("wear_sign") = 1.0, pydoc::sinumerik_SinumerikEdge_radius)
        .def("__eq__", [](const SinumerikEdge& a, const SinumerikEdge& b) { return a == b; }, py::is_operator())
        .def("__ne__", [](const SinumerikEdge& a, const SinumerikEdge& b) { return !(a == b); }, py::is_operator())
        .def("__copy__", [](const SinumerikEdge& e) { return e; })
        .def("__deepcopy__", [](const SinumerikEdge& e, py::dict) { return e; }, py::arg("memo"))
        .def("__repr__", [](const SinumerikEdge& e) {
            std::string s = "Edge({";
            bool first = true;
            for (int n = 1; n <= 25; ++n) {
                if (n != 1 && e.DP(n) == 0.0) continue;
                if (!first) s += ", ";
                first = false;
                s += std::to_string(n) + ": " + repr_float(e.DP(n));
            }
            return s + "}, dl=" + std::to_string(e.dl) + ")";
        });

    m.def("is_turning_type", &is_turning_type, py::arg("tool_type"), pydoc::sinumerik_is_turning_type);

    py::class_<SinumerikLengthSettings>(m, "LengthSettings", pydoc::sinumerik_SinumerikLengthSettings)
        .def(py::init([](int tool_length_const, int tool_length_type, bool wear_sign_inverted) {
                 SinumerikLengthSettings s;
                 s.tool_length_const = tool_length_const;
                 s.tool_length_type = tool_length_type;
                 s.wear_sign_inverted = wear_sign_inverted;
                 return s;
             }),
             py::kw_only(), py::arg("tool_length_const") = 0, py::arg("tool_length_type") = 0,
             py::arg("wear_sign_inverted") = false)
        .def_readwrite("tool_length_const", &SinumerikLengthSettings::tool_length_const,
                       pydoc::sinumerik_SinumerikLengthSettings_tool_length_const)
        .def_readwrite("tool_length_type", &SinumerikLengthSettings::tool_length_type,
                       pydoc::sinumerik_SinumerikLengthSettings_tool_length_type)
        .def_readwrite("wear_sign_inverted", &SinumerikLengthSettings::wear_sign_inverted, pydoc::sinumerik_SinumerikLengthSettings_wear_sign_inverted)
        .def_property_readonly("wear_sign", &SinumerikLengthSettings::wear_sign, pydoc::sinumerik_SinumerikLengthSettings_wear_sign)
        .def("__repr__", [](const SinumerikLengthSettings& s) {
            return "LengthSettings(tool_length_const=" + std::to_string(s.tool_length_const) +
                   ", tool_length_type=" + std::to_string(s.tool_length_type) +
                   ", wear_sign_inverted=" + (s.wear_sign_inverted ? "True" : "False") + ")";
        });

    /// @pydoc sinumerik.length_axes
    /// geometry-axis index (0 = X, 1 = Y, 2 = Z) on which L1, L2, L3 act
    m.def(
        "length_axes",
        [](int tool_type, const py::object& plane, const std::optional<SinumerikLengthSettings>& s) {
            const auto a = length_axes(tool_type, plane_arg(plane), s.value_or(SinumerikLengthSettings{}));
            return py::make_tuple(a[0], a[1], a[2]);
        },
        py::arg("tool_type"), py::arg("plane"), py::arg("settings") = py::none(), pydoc::sinumerik_length_axes);
    /// @pydoc sinumerik.lentoax
    /// LENTOAX: (status, _AXIND, _MATRIX): the 1-based geometry axis (1 X, 2 Y, 3 Z) of L1,
    /// L2, L3 and their unit vectors as rows; status -1 for an unknown coordinate system
    /// (frames are not modelled)
    m.def(
        "lentoax",
        [](int tool_type, const py::object& plane, const std::optional<SinumerikLengthSettings>& s,
           const std::string& coord) {
            const LentoaxResult r = lentoax(tool_type, plane_arg(plane), s.value_or(SinumerikLengthSettings{}), coord);
            return py::make_tuple(r.status, py::make_tuple(r.axind[0], r.axind[1], r.axind[2]),
                                  Eigen::Matrix<double, 3, 3, Eigen::RowMajor>(r.matrix));
        },
        py::arg("tool_type"), py::arg("plane"), py::arg("settings") = py::none(), py::arg("coord") = "W",
        pydoc::sinumerik_lentoax);
    /// @pydoc sinumerik.place_lengths
    /// (L1, L2, L3) placed on X, Y, Z for the tool type and plane
    m.def(
        "place_lengths",
        [](const Vec3& l123, int tool_type, const py::object& plane, const std::optional<SinumerikLengthSettings>& s) {
            return place_lengths(l123, tool_type, plane_arg(plane), s.value_or(SinumerikLengthSettings{}));
        },
        py::arg("lengths"), py::arg("tool_type"), py::arg("plane"), py::arg("settings") = py::none(),
        pydoc::sinumerik_place_lengths);
    /// @pydoc sinumerik.tool_length
    /// the tool length vector (x, y, z) of the edge's total lengths L1..L3
    m.def(
        "tool_length",
        [](const SinumerikEdge& e, const py::object& plane, const std::optional<SinumerikLengthSettings>& s) {
            return tool_length_vector(e, plane_arg(plane), s.value_or(SinumerikLengthSettings{}));
        },
        py::arg("edge"), py::arg("plane") = 17, py::arg("settings") = py::none(), pydoc::sinumerik_tool_length);

    /// @pydoc sinumerik.settcor
    /// SETTCOR: write a correction into the edge (in place); returns the status (0 OK).
    /// corcomp 0 scalar corval[0] along geometry axis geoax (1..3), 1/2 vector, 3..5
    /// L1..L3, 6 radius; cormode 0 replace, 1 add
    m.def(
        "settcor",
        [](SinumerikEdge& e, const Vec3& corval, const std::string& comp, int corcomp, int cormode, int geoax,
           const py::object& plane, const std::optional<SinumerikLengthSettings>& s) {
            return settcor(e, corval, comp, corcomp, cormode, geoax, plane_arg(plane),
                           s.value_or(SinumerikLengthSettings{}));
        },
        py::arg("edge"), py::arg("corval"), py::arg("comp"), py::arg("corcomp") = 0, py::arg("cormode") = 0,
        py::arg("geoax") = 0, py::arg("plane") = 17, py::arg("settings") = py::none(), pydoc::sinumerik_settcor);
    m.attr("SETTCOR_BAD_CORCOMP") = static_cast<int>(settcor_bad_corcomp);
    m.attr("SETTCOR_BAD_CORMODE") = static_cast<int>(settcor_bad_cormode);
    m.attr("SETTCOR_BAD_GEOAX") = static_cast<int>(settcor_bad_geoax);
    m.attr("SETTCOR_NO_RADIUS") = static_cast<int>(settcor_no_radius);

    // ---- $TC_DP file form ----------------------------------------------------------------
    /// @pydoc sinumerik.parse_tool_data
    /// parse '$TC_DPn[t,d]=value' lines ($TC_ECPn / $TC_SCPn too) into {(t, d): Edge};
    /// errors are ToolTableError with line and column
    m.def(
        "parse_tool_data",
        [](std::string_view text, int max_t, int max_d) { return parse_tc_dp(text, max_t, max_d); },
        py::arg("text"), py::kw_only(), py::arg("max_t") = 32000, py::arg("max_d") = 32000,
        pydoc::sinumerik_parse_tool_data);
    /// @pydoc sinumerik.read_tool_data
    /// parse_tool_data of a file's text; a missing file is ToolTableError 'file_not_found'
    m.def(
        "read_tool_data",
        [](const std::filesystem::path& path, int max_t, int max_d) {
            return parse_tc_dp(read_text(path), max_t, max_d);
        },
        py::arg("path"), py::kw_only(), py::arg("max_t") = 32000, py::arg("max_d") = 32000,
        pydoc::sinumerik_read_tool_data);
    m.def("format_tool_data", &write_tc_dp, py::arg("edges"), pydoc::sinumerik_write_tc_dp);

    // ---- GETTCOR -----------------------------------------------------------------------------
    m.attr("GETTCOR_OK") = static_cast<int>(gettcor_ok);
    m.attr("GETTCOR_NO_ENV_MEMORY") = static_cast<int>(gettcor_no_env_memory);
    m.attr("GETTCOR_ENV_MISSING") = static_cast<int>(gettcor_env_missing);
    m.attr("GETTCOR_BAD_COMP") = static_cast<int>(gettcor_bad_comp);
    m.attr("GETTCOR_BAD_T") = static_cast<int>(gettcor_bad_t);
    m.attr("GETTCOR_BAD_D") = static_cast<int>(gettcor_bad_d);
    m.attr("GETTCOR_BAD_DL") = static_cast<int>(gettcor_bad_dl);
    m.attr("GETTCOR_NO_MEMORY_MODULE") = static_cast<int>(gettcor_no_memory_module);
    m.attr("GETTCOR_MISSING_OPTION") = static_cast<int>(gettcor_missing_option);
    m.attr("GETTCOR_BAD_COORD") = static_cast<int>(gettcor_bad_coord);

    py::class_<GettcorSettings>(m, "GettcorSettings", pydoc::sinumerik_GettcorSettings)
        .def(py::init([](const py::object& plane, const std::optional<SinumerikLengthSettings>& lengths,
                         unsigned parameter_def_mask, int transverse_axis, int tool_env_memory) {
                 GettcorSettings s;
                 s.plane = plane_arg(plane);
                 if (lengths) s.lengths = *lengths;
                 s.set_parameter_def_mask(parameter_def_mask);
                 s.transverse_axis = transverse_axis;
                 s.tool_env_memory = tool_env_memory;
                 return s;
             }),
             py::kw_only(), py::arg("plane") = 17, py::arg("lengths") = py::none(), py::arg("parameter_def_mask") = 0u,
             py::arg("transverse_axis") = 0, py::arg("tool_env_memory") = 0)
        .def_property(
            "plane", [](const GettcorSettings& s) { return plane_number(s.plane); },
            [](GettcorSettings& s, const py::object& p) { s.plane = plane_arg(p); }, pydoc::sinumerik_GettcorSettings_plane)
        .def_readwrite("lengths", &GettcorSettings::lengths, pydoc::sinumerik_GettcorSettings_lengths)
        .def_readwrite("geometry_diameter", &GettcorSettings::geometry_diameter, pydoc::sinumerik_GettcorSettings_geometry_diameter)
        .def_readwrite("wear_diameter", &GettcorSettings::wear_diameter, pydoc::sinumerik_GettcorSettings_wear_diameter)
        .def_readwrite("transverse_axis", &GettcorSettings::transverse_axis, pydoc::sinumerik_GettcorSettings_transverse_axis)
        .def_readwrite("tool_env_memory", &GettcorSettings::tool_env_memory, pydoc::sinumerik_GettcorSettings_tool_env_memory)
        .def("set_parameter_def_mask", &GettcorSettings::set_parameter_def_mask, py::arg("mask"),
             pydoc::sinumerik_GettcorSettings_set_parameter_def_mask);

    /// @pydoc sinumerik.gettcor
    /// GETTCOR for one edge: (status, _LEN float64 (11,)); _LEN is zero unless status is 0.
    /// plane, when given, replaces settings.plane
    m.def(
        "gettcor",
        [](const SinumerikEdge& e, std::string_view comp, const std::optional<GettcorSettings>& s,
           const py::object& plane, std::string_view stat, int dl) {
            std::array<double, 11> len{};
            const int status = gettcor(len, comp, e, settings_arg(s, plane), stat, dl);
            return gettcor_result(status, len);
        },
        py::arg("edge"), py::arg("comp") = "GW", py::arg("settings") = py::none(), py::kw_only(),
        py::arg("plane") = py::none(), py::arg("stat") = "", py::arg("dl") = -1, pydoc::sinumerik_gettcor);
    /// @pydoc sinumerik.gettcor_2
    /// GETTCOR with explicit _T, _D looked up in {(t, d): Edge}
    m.def(
        "gettcor",
        [](const SinumerikEdgeMap& edges, int t, int d, std::string_view comp, const std::optional<GettcorSettings>& s,
           const py::object& plane, std::string_view stat, int dl) {
            std::array<double, 11> len{};
            const int status = gettcor(len, comp, edges, t, d, settings_arg(s, plane), stat, dl);
            return gettcor_result(status, len);
        },
        py::arg("edges"), py::arg("t"), py::arg("d"), py::arg("comp") = "GW", py::arg("settings") = py::none(),
        py::kw_only(), py::arg("plane") = py::none(), py::arg("stat") = "", py::arg("dl") = -1,
        pydoc::sinumerik_gettcor_2);

    // ---- toolholders ------------------------------------------------------------------------
    m.def("rotate_about_axis", &rotate_about_axis, py::arg("v"), py::arg("axis"), py::arg("angle_deg"),
          pydoc::rotate_about_axis);

    py::class_<Toolholder>(m, "Toolholder", pydoc::Toolholder)
        .def(py::init([](const std::string& kinematic_type, const Vec3& l1, const Vec3& l2, const Vec3& l3,
                         const Vec3& l4, const Vec3& v1, const Vec3& v2, double alpha1, double alpha2,
                         double offset1, double offset2, const std::string& name) {
                 Toolholder h;
                 h.set_text(23, kinematic_type);
                 h.l1 = l1, h.l2 = l2, h.l3 = l3, h.l4 = l4, h.v1 = v1, h.v2 = v2;
                 h.alpha1 = alpha1, h.alpha2 = alpha2, h.offset1 = offset1, h.offset2 = offset2;
                 h.name = name;
                 return h;
             }),
             py::arg("kinematic_type") = "T", py::kw_only(), py::arg("l1") = Vec3::Zero().eval(),
             py::arg("l2") = Vec3::Zero().eval(), py::arg("l3") = Vec3::Zero().eval(),
             py::arg("l4") = Vec3::Zero().eval(), py::arg("v1") = Vec3::Zero().eval(),
             py::arg("v2") = Vec3::Zero().eval(), py::arg("alpha1") = 0.0, py::arg("alpha2") = 0.0,
             py::arg("offset1") = 0.0, py::arg("offset2") = 0.0, py::arg("name") = "")
        .def_readwrite("l1", &Toolholder::l1, pydoc::Toolholder_l1)
        /// @pydoc sinumerik.Toolholder.l2
        /// $TC_CARR4..6
        .def_readwrite("l2", &Toolholder::l2, pydoc::sinumerik_Toolholder_l2)
        /// @pydoc sinumerik.Toolholder.l3
        /// $TC_CARR15..17
        .def_readwrite("l3", &Toolholder::l3, pydoc::sinumerik_Toolholder_l3)
        /// @pydoc sinumerik.Toolholder.l4
        /// $TC_CARR18..20
        .def_readwrite("l4", &Toolholder::l4, pydoc::sinumerik_Toolholder_l4)
        .def_readwrite("v1", &Toolholder::v1, pydoc::Toolholder_v1)
        /// @pydoc sinumerik.Toolholder.v2
        /// $TC_CARR10..12
        .def_readwrite("v2", &Toolholder::v2, pydoc::sinumerik_Toolholder_v2)
        .def_readwrite("alpha1", &Toolholder::alpha1, pydoc::Toolholder_alpha1)
        /// @pydoc sinumerik.Toolholder.alpha2
        /// $TC_CARR14
        .def_readwrite("alpha2", &Toolholder::alpha2, pydoc::sinumerik_Toolholder_alpha2)
        .def_readwrite("axis1", &Toolholder::axis1, pydoc::Toolholder_axis1)
        /// @pydoc sinumerik.Toolholder.axis2
        /// $TC_CARR22
        .def_readwrite("axis2", &Toolholder::axis2, pydoc::sinumerik_Toolholder_axis2)
        /// @pydoc sinumerik.Toolholder.kinematic_type
        /// $TC_CARR23: 'T', 'P' or 'M'
        .def_property(
            "kinematic_type", [](const Toolholder& h) { return std::string(1, h.kind); },
            [](Toolholder& h, const std::string& v) { h.set_text(23, v); }, pydoc::sinumerik_Toolholder_kinematic_type)
        .def_readwrite("offset1", &Toolholder::offset1, pydoc::Toolholder_offset1)
        /// @pydoc sinumerik.Toolholder.offset2
        /// $TC_CARR25
        .def_readwrite("offset2", &Toolholder::offset2, pydoc::sinumerik_Toolholder_offset2)
        .def_readwrite("hirth", &Toolholder::hirth, pydoc::Toolholder_hirth)
        .def_readwrite("limits", &Toolholder::limits, pydoc::Toolholder_limits)
        .def_readwrite("name", &Toolholder::name, pydoc::Toolholder_name)
        .def_readwrite("user", &Toolholder::user, pydoc::Toolholder_user)
        .def_property_readonly("angle1", &Toolholder::angle1, pydoc::Toolholder_angle1)
        .def_property_readonly("angle2", &Toolholder::angle2, pydoc::Toolholder_angle2)
        .def("set_carr", py::overload_cast<int, std::string_view>(&Toolholder::set_text), py::arg("n"),
             py::arg("value"), pydoc::Toolholder_set_text)
        .def("set_carr", py::overload_cast<int, double>(&Toolholder::set), py::arg("n"), py::arg("value"),
             pydoc::Toolholder_set)
        /// @pydoc sinumerik.Toolholder.resulting_tool_length
        /// the length vector (tool tip -> holder reference) through the holder
        .def(
            "resulting_tool_length",
            [](const Toolholder& h, const Vec3& tool_length) { return resulting_tool_length(h, tool_length); },
            py::arg("tool_length"), pydoc::sinumerik_Toolholder_resulting_tool_length)
        /// @pydoc sinumerik.Toolholder.table_zero_offset
        /// shift of the workpiece zero point by the table rotation (types P and M)
        .def(
            "table_zero_offset", [](const Toolholder& h) { return table_zero_offset(h); },
            pydoc::sinumerik_Toolholder_table_zero_offset)
        .def("__copy__", [](const Toolholder& h) { return h; })
        .def("__deepcopy__", [](const Toolholder& h, py::dict) { return h; }, py::arg("memo"))
        .def("__repr__", [](const Toolholder& h) {
            return "Toolholder('" + std::string(1, h.kind) + "', l1=" + repr_vec(h.l1) + ", l2=" + repr_vec(h.l2) +
                   ", l3=" + repr_vec(h.l3) + ", l4=" + repr_vec(h.l4) + ", v1=" + repr_vec(h.v1) +
                   ", v2=" + repr_vec(h.v2) + ", alpha1=" + repr_float(h.alpha1) +
                   ", alpha2=" + repr_float(h.alpha2) + ")";
        });

    py::class_<Trafo5Data>(m, "Trafo5", pydoc::Trafo5Data)
        .def(py::init([](int type, const Vec3& base_tool, const Vec3& joint_offset, const Vec3& joint_offset_part,
                         const Vec3& part_offset, const Vec3& axis1, const Vec3& axis2) {
                 Trafo5Data t;
                 t.type = type;
                 t.base_tool = base_tool, t.joint_offset = joint_offset, t.joint_offset_part = joint_offset_part;
                 t.part_offset = part_offset, t.axis1 = axis1, t.axis2 = axis2;
                 return t;
             }),
             py::arg("type") = 24, py::kw_only(), py::arg("base_tool") = Vec3::Zero().eval(),
             py::arg("joint_offset") = Vec3::Zero().eval(), py::arg("joint_offset_part") = Vec3::Zero().eval(),
             py::arg("part_offset") = Vec3::Zero().eval(), py::arg("axis1") = Vec3::Zero().eval(),
             py::arg("axis2") = Vec3::Zero().eval())
        .def_readwrite("type", &Trafo5Data::type, pydoc::Trafo5Data_type)
        .def_readwrite("base_tool", &Trafo5Data::base_tool, pydoc::Trafo5Data_base_tool)
        .def_readwrite("joint_offset", &Trafo5Data::joint_offset, pydoc::Trafo5Data_joint_offset)
        .def_readwrite("joint_offset_part", &Trafo5Data::joint_offset_part, pydoc::Trafo5Data_joint_offset_part)
        .def_readwrite("part_offset", &Trafo5Data::part_offset, pydoc::Trafo5Data_part_offset)
        .def_readwrite("axis1", &Trafo5Data::axis1, pydoc::Trafo5Data_axis1)
        /// @pydoc sinumerik.Trafo5.axis2
        /// TRAFO5_AXIS2
        .def_readwrite("axis2", &Trafo5Data::axis2, pydoc::sinumerik_Trafo5_axis2)
        /// @pydoc sinumerik.Trafo5.to_toolholder
        /// the equivalent Toolholder at axis positions a1, a2 (degrees)
        .def(
            "to_toolholder", [](const Trafo5Data& t, double a1, double a2) { return to_toolholder(t, a1, a2); },
            py::arg("a1") = 0.0, py::arg("a2") = 0.0, pydoc::sinumerik_Trafo5_to_toolholder)
        /// @pydoc sinumerik.Trafo5.tool_length
        /// the tool length through the machine data directly (equals the equivalent toolholder's)
        .def(
            "tool_length",
            [](const Trafo5Data& t, double a1, double a2, const Vec3& tool_length) {
                return trafo5_tool_length(t, a1, a2, tool_length);
            },
            py::arg("a1"), py::arg("a2"), py::arg("tool_length"), pydoc::sinumerik_Trafo5_tool_length)
        .def("__copy__", [](const Trafo5Data& t) { return t; })
        .def("__deepcopy__", [](const Trafo5Data& t, py::dict) { return t; }, py::arg("memo"));
}
