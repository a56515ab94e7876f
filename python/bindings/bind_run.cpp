#include "bindings.hpp"

#include <cmath>

#include <pybind11/stl.h>

#include <pybind11/numpy.h>

#include "toolcomp/compensation/normal_offset.hpp"
#include "toolcomp/run.hpp"
#include "toolcomp/tools/tool_table.hpp"

using namespace toolcomp;

namespace {
MachineKind machine_kind(const std::string& k) {
    if (k != "mill" && k != "lathe") throw py::value_error("the kind of machine is 'mill' or 'lathe', not '" + k + "'");
    return k == "lathe" ? MachineKind::lathe : MachineKind::mill;
}

// run(probes=...): None (no contact), or the contact point X Y Z [A B C] (mm, degrees).
std::vector<ProbeResult> probe_results(const std::vector<std::optional<std::vector<double>>>& given) {
    std::vector<ProbeResult> out;
    for (const auto& g : given) {
        ProbeResult r;
        r.contact = g.has_value();
        if (g) {
            if (g->size() != 3 && g->size() != 6)
                throw py::value_error("a probe result is None (no contact) or X Y Z [A B C]: " + std::to_string(g->size()) +
                                      " numbers given");
            for (std::size_t i = 0; i < g->size(); ++i) {
                if (!std::isfinite((*g)[i])) throw py::value_error("a probe result's coordinates must be finite");
                r.point[i] = (*g)[i];
            }
            r.axes = static_cast<int>(g->size());
        }
        out.push_back(r);
    }
    return out;
}

// `progress` is held by the caller's frame for the whole run.
RunOptions run_options(bool strict, bool block_delete, std::optional<ControlProfile> profile, py::object& progress,
                       std::size_t progress_every, std::vector<std::string> search_path,
                       std::map<int, double> parameters, std::size_t max_segments, bool threads,
                       bool follow_links, const std::optional<Machine>& machine) {
    RunOptions o;
    if (machine) o.machine = std::make_shared<const Machine>(*machine);
    o.follow_links = follow_links;
    o.max_segments = max_segments;
    o.threads = threads;
    o.parameters = std::move(parameters);
    o.strict = strict;
    o.block_delete = block_delete;
    o.profile = std::move(profile);
    o.progress_every = progress_every;
    o.search_path = std::move(search_path);
    o.share_unchanged_path = true;  // `path` is then the `nominal` Path object
    if (!progress.is_none())
        o.progress = [&progress](std::size_t n) {
            py::gil_scoped_acquire gil;
            progress(n);  // a Python exception (Ctrl-C) stops the run
        };
    return o;
}
}  // namespace

std::optional<Vec3> start_position(const std::optional<std::array<double, 3>>& xyz) {
    if (!xyz) return std::nullopt;
    for (double v : *xyz)
        if (!std::isfinite(v)) throw py::value_error("start must be three finite numbers (x, y, z), mm");
    return Vec3((*xyz)[0], (*xyz)[1], (*xyz)[2]);
}

namespace {
// A tolerance a program's arcs are measured against: a finite number, not negative (refused
// when set, by name; check_profile refuses it again when a run starts).
double tolerance(const char* name, double v) {
    if (!std::isfinite(v) || v < 0) throw py::value_error(std::string(name) + " must be a finite number >= 0");
    return v;
}
// Properties of ControlProfile tolerances, refused by name when set badly: one value, or a
// pair (mm programs, inch programs) set together or not at all.
void def_tolerance(py::class_<ControlProfile>& cls, const char* name, double ControlProfile::*f, const char* doc) {
    cls.def_property(
        name, [f](const ControlProfile& p) { return p.*f; },
        [f, name](ControlProfile& p, double v) { p.*f = tolerance(name, v); }, doc);
}
void def_tolerance_pair(py::class_<ControlProfile>& cls, const char* name, double (ControlProfile::*f)[2],
                        const char* doc) {
    cls.def_property(
        name, [f](const ControlProfile& p) { return std::make_pair((p.*f)[0], (p.*f)[1]); },
        [f, name](ControlProfile& p, std::pair<double, double> v) {
            const double mm = tolerance(name, v.first), inch = tolerance(name, v.second);
            (p.*f)[0] = mm;
            (p.*f)[1] = inch;
        },
        doc);
}
}  // namespace

void bind_run(py::module_& m) {
    py::enum_<LengthAxes>(m, "LengthAxes", pydoc::LengthAxes)
        .value("all", LengthAxes::all, pydoc::LengthAxes_all)
        .value("z_only", LengthAxes::z_only, pydoc::LengthAxes_z_only)
        .value("plane_normal", LengthAxes::plane_normal, pydoc::LengthAxes_plane_normal);

    py::enum_<EntryStyle>(m, "EntryStyle", pydoc::EntryStyle)
        .value("perpendicular_to_entry", EntryStyle::perpendicular_to_entry, pydoc::EntryStyle_perpendicular_to_entry)
        .value("perpendicular_to_next", EntryStyle::perpendicular_to_next, pydoc::EntryStyle_perpendicular_to_next)
        .value("around_start_when_behind", EntryStyle::around_start_when_behind,
               pydoc::EntryStyle_around_start_when_behind);
    py::enum_<ExitStyle>(m, "ExitStyle", pydoc::ExitStyle)
        .value("perpendicular_to_last", ExitStyle::perpendicular_to_last, pydoc::ExitStyle_perpendicular_to_last)
        .value("corner_with_exit", ExitStyle::corner_with_exit, pydoc::ExitStyle_corner_with_exit)
        .value("around_end_when_behind", ExitStyle::around_end_when_behind, pydoc::ExitStyle_around_end_when_behind);
    py::enum_<OutsideCorner>(m, "OutsideCorner", pydoc::OutsideCorner)
        .value("arc", OutsideCorner::arc, pydoc::OutsideCorner_arc)
        .value("intersection", OutsideCorner::intersection, pydoc::OutsideCorner_intersection)
        .value("extension", OutsideCorner::extension, pydoc::OutsideCorner_extension);
    py::enum_<GougeReaction>(m, "GougeReaction", pydoc::GougeReaction)
        .value("error", GougeReaction::error, pydoc::GougeReaction_error)
        .value("skip", GougeReaction::skip, pydoc::GougeReaction_skip)
        .value("report", GougeReaction::report, pydoc::GougeReaction_report);
    py::enum_<NonPlaneReaction>(
        m, "NonPlaneReaction", pydoc::NonPlaneReaction)
        .value("error", NonPlaneReaction::error, pydoc::NonPlaneReaction_error)
        .value("overcut", NonPlaneReaction::overcut, pydoc::NonPlaneReaction_overcut);

    py::enum_<TipConvention>(m, "TipConvention", pydoc::TipConvention)
        .value("linuxcnc", TipConvention::linuxcnc, pydoc::TipConvention_linuxcnc)
        .value("fanuc", TipConvention::fanuc, pydoc::TipConvention_fanuc);
    py::enum_<MachineKind>(m, "MachineKind", pydoc::MachineKind)
        .value("mill", MachineKind::mill, pydoc::MachineKind_mill)
        .value("lathe", MachineKind::lathe, pydoc::MachineKind_lathe);

    py::class_<RadiusRules>(m, "RadiusRules", pydoc::RadiusRules)
        .def_readwrite("yz_plane", &RadiusRules::yz_plane, pydoc::RadiusRules_yz_plane)
        .def_readwrite("entry", &RadiusRules::entry, pydoc::RadiusRules_entry)
        .def_readwrite("entry_arc", &RadiusRules::entry_arc, pydoc::RadiusRules_entry_arc)
        .def_readwrite("exit", &RadiusRules::exit, pydoc::RadiusRules_exit)
        .def_readwrite("tip_convention", &RadiusRules::tip_convention, pydoc::RadiusRules_tip_convention)
        .def_readwrite("extension_min_length", &RadiusRules::extension_min_length,
                       pydoc::RadiusRules_extension_min_length)
        .def_readwrite("ct_radius_on_contour", &RadiusRules::ct_radius_on_contour,
                       pydoc::RadiusRules_ct_radius_on_contour)
        .def_readwrite("lct_tangency_tool_space", &RadiusRules::lct_tangency_tool_space,
                       pydoc::RadiusRules_lct_tangency_tool_space)
        .def_readwrite("exit_direction_words", &RadiusRules::exit_direction_words,
                       pydoc::RadiusRules_exit_direction_words)
        .def_readwrite("offset_change_reenters", &RadiusRules::offset_change_reenters,
                       pydoc::RadiusRules_offset_change_reenters)
        .def_readwrite("exit_must_be_straight", &RadiusRules::exit_must_be_straight,
                       pydoc::RadiusRules_exit_must_be_straight)
        .def_readwrite("entry_length_check", &RadiusRules::entry_length_check, pydoc::RadiusRules_entry_length_check)
        .def_readwrite("outside_corner", &RadiusRules::outside_corner, pydoc::RadiusRules_outside_corner)
        .def_readwrite("corner_limit", &RadiusRules::corner_limit, pydoc::RadiusRules_corner_limit)
        .def_readwrite("disc", &RadiusRules::disc, pydoc::RadiusRules_disc)
        .def_readwrite("side_change", &RadiusRules::side_change, pydoc::RadiusRules_side_change)
        .def_readwrite("corner_tolerance", &RadiusRules::corner_tolerance, pydoc::RadiusRules_corner_tolerance)
        .def_property(
            "arc_sweep_tolerance",
            [](const RadiusRules& r) { return std::make_pair(r.arc_sweep_tolerance[0], r.arc_sweep_tolerance[1]); },
            [](RadiusRules& r, std::pair<double, double> v) {
                r.arc_sweep_tolerance[0] = v.first;
                r.arc_sweep_tolerance[1] = v.second;
            },
            pydoc::RadiusRules_arc_sweep_tolerance)
        .def_readwrite("max_non_plane_moves", &RadiusRules::max_non_plane_moves, pydoc::RadiusRules_max_non_plane_moves)
        .def_readwrite("count_blocks_without_motion", &RadiusRules::count_blocks_without_motion,
                       pydoc::RadiusRules_count_blocks_without_motion)
        .def_readwrite("non_plane_reaction", &RadiusRules::non_plane_reaction, pydoc::RadiusRules_non_plane_reaction)
        .def_readwrite("lookahead", &RadiusRules::lookahead, pydoc::RadiusRules_lookahead)
        .def_readwrite("gouge", &RadiusRules::gouge, pydoc::RadiusRules_gouge)
        .def_readwrite("overcut_neighbours", &RadiusRules::overcut_neighbours, pydoc::RadiusRules_overcut_neighbours)
        .def_readwrite("overcut_tolerance", &RadiusRules::overcut_tolerance, pydoc::RadiusRules_overcut_tolerance);

    py::class_<ControlProfile> profile(
        m, "ControlProfile", pydoc::ControlProfile);
    profile
        /// @pydoc ControlProfile.__init__
        /// The profile of a control ('linuxcnc', 'fanuc', 'sinumerik', 'heidenhain',
        /// 'rockwell') on a kind of machine ('mill' or 'lathe'; machine= is its former
        /// name)
        .def(py::init([](const std::string& dialect, std::optional<std::string> kind, std::optional<std::string> machine) {
                 if (kind && machine && *kind != *machine)
                     throw py::value_error("kind and machine (its former name) name different kinds");
                 return profile_for(dialect_from_name(dialect), machine_kind(kind ? *kind : machine.value_or("mill")));
             }),
             py::arg("dialect") = "linuxcnc", py::arg("kind") = py::none(), py::arg("machine") = py::none(),
             pydoc::ControlProfile___init__)
        .def_readonly("kind", &ControlProfile::kind, pydoc::ControlProfile_kind)
        /// @pydoc ControlProfile.machine
        /// the former name of kind
        .def_readonly("machine", &ControlProfile::kind, pydoc::ControlProfile_machine)
        .def_readwrite("x_diameter", &ControlProfile::x_diameter, pydoc::ControlProfile_x_diameter)
        .def_readwrite("incremental_uw", &ControlProfile::incremental_uw, pydoc::ControlProfile_incremental_uw)
        .def_readwrite("t_offsets", &ControlProfile::t_offsets, pydoc::ControlProfile_t_offsets)
        .def_readwrite("g_code_system_a", &ControlProfile::g_code_system_a, pydoc::ControlProfile_g_code_system_a)
        .def_readwrite("modal_offset_numbers", &ControlProfile::modal_offset_numbers,
                       pydoc::ControlProfile_modal_offset_numbers)
        .def_readwrite("t_format", &ControlProfile::t_format, pydoc::ControlProfile_t_format)
        .def_readwrite("wear_sign", &ControlProfile::wear_sign, pydoc::ControlProfile_wear_sign)
        .def_readwrite("tool_length_const", &ControlProfile::tool_length_const, pydoc::ControlProfile_tool_length_const)
        .def_readwrite("tool_length_type", &ControlProfile::tool_length_type, pydoc::ControlProfile_tool_length_type)
        .def_readwrite("tool_parameter_def_mask", &ControlProfile::tool_parameter_def_mask,
                       pydoc::ControlProfile_tool_parameter_def_mask)
        .def_readwrite("name", &ControlProfile::name, pydoc::ControlProfile_name)
        .def_readwrite("startup_inch", &ControlProfile::startup_inch, pydoc::ControlProfile_startup_inch)
        .def_property(
            "startup_plane",
            [](const ControlProfile& p) { return p.startup_plane == Plane::xy ? 17 : p.startup_plane == Plane::zx ? 18 : 19; },
            [](ControlProfile& p, int g) {
                if (g != 17 && g != 18 && g != 19) throw py::value_error("startup_plane must be 17, 18 or 19");
                p.startup_plane = g == 17 ? Plane::xy : g == 18 ? Plane::zx : Plane::yz;
            },
            pydoc::ControlProfile_startup_plane)
        .def_readwrite("startup_feed_per_rev", &ControlProfile::startup_feed_per_rev,
                       pydoc::ControlProfile_startup_feed_per_rev)
        .def_readwrite("block_limit", &ControlProfile::block_limit, pydoc::ControlProfile_block_limit)
        .def_readwrite("feed_mode_clears_feed", &ControlProfile::feed_mode_clears_feed,
                       pydoc::ControlProfile_feed_mode_clears_feed)
        .def_readwrite("tool_change_after_block", &ControlProfile::tool_change_after_block,
                       pydoc::ControlProfile_tool_change_after_block)
        .def_readwrite("bare_motion_codes", &ControlProfile::bare_motion_codes, pydoc::ControlProfile_bare_motion_codes)
        .def_readwrite("inverse_time_min_rate", &ControlProfile::inverse_time_min_rate,
                       pydoc::ControlProfile_inverse_time_min_rate)
        .def_readwrite("integer_word_slack", &ControlProfile::integer_word_slack,
                       pydoc::ControlProfile_integer_word_slack)
        .def_readwrite("linuxcnc_g_numbers", &ControlProfile::linuxcnc_g_numbers,
                       pydoc::ControlProfile_linuxcnc_g_numbers)
        .def_readwrite("last_g_code_wins", &ControlProfile::last_g_code_wins, pydoc::ControlProfile_last_g_code_wins)
        .def_readwrite("max_m_code", &ControlProfile::max_m_code, pydoc::ControlProfile_max_m_code)
        .def_readwrite("fixed_m_codes", &ControlProfile::fixed_m_codes, pydoc::ControlProfile_fixed_m_codes)
        .def_readwrite("negative_l_refused", &ControlProfile::negative_l_refused,
                       pydoc::ControlProfile_negative_l_refused)
        .def_readwrite("dwell_negative_p", &ControlProfile::dwell_negative_p, pydoc::ControlProfile_dwell_negative_p)
        .def_readwrite("arc_turns_word", &ControlProfile::arc_turns_word, pydoc::ControlProfile_arc_turns_word)
        .def_readwrite("c_word_is_chamfer", &ControlProfile::c_word_is_chamfer, pydoc::ControlProfile_c_word_is_chamfer)
        .def_readwrite("dwell_x_seconds", &ControlProfile::dwell_x_seconds, pydoc::ControlProfile_dwell_x_seconds)
        .def_readwrite("g10_tool_table", &ControlProfile::g10_tool_table, pydoc::ControlProfile_g10_tool_table)
        .def_readwrite("numbered_subprograms", &ControlProfile::numbered_subprograms,
                       pydoc::ControlProfile_numbered_subprograms)
        .def_readwrite("modal_state_codes", &ControlProfile::modal_state_codes, pydoc::ControlProfile_modal_state_codes)
        .def_readwrite("tool_change_stops_spindle", &ControlProfile::tool_change_stops_spindle,
                       pydoc::ControlProfile_tool_change_stops_spindle)
        .def_readwrite("splines", &ControlProfile::splines, pydoc::ControlProfile_splines)
        .def_readwrite("spindle_sync_motion", &ControlProfile::spindle_sync_motion,
                       pydoc::ControlProfile_spindle_sync_motion)
        .def_readwrite("profile_cycles", &ControlProfile::profile_cycles, pydoc::ControlProfile_profile_cycles)
        .def_readwrite("spindle_orient", &ControlProfile::spindle_orient, pydoc::ControlProfile_spindle_orient)
        .def_readwrite("restore_feed_speed_always", &ControlProfile::restore_feed_speed_always,
                       pydoc::ControlProfile_restore_feed_speed_always)
        .def_readwrite("fanuc_g10", &ControlProfile::fanuc_g10, pydoc::ControlProfile_fanuc_g10)
        .def_readwrite("startup_motion", &ControlProfile::startup_motion, pydoc::ControlProfile_startup_motion)
        .def_readwrite("cycles_own_group", &ControlProfile::cycles_own_group, pydoc::ControlProfile_cycles_own_group)
        .def_readwrite("startup_retract_initial", &ControlProfile::startup_retract_initial,
                       pydoc::ControlProfile_startup_retract_initial)
        .def_readwrite("motion_beside_data_axes", &ControlProfile::motion_beside_data_axes,
                       pydoc::ControlProfile_motion_beside_data_axes)
        .def_readwrite("g84_axes_warning", &ControlProfile::g84_axes_warning, pydoc::ControlProfile_g84_axes_warning)
        .def_readwrite("g53_rapid", &ControlProfile::g53_rapid, pydoc::ControlProfile_g53_rapid)
        .def_readwrite("d_word_alone", &ControlProfile::d_word_alone, pydoc::ControlProfile_d_word_alone)
        .def_readwrite("turning_cycles", &ControlProfile::turning_cycles, pydoc::ControlProfile_turning_cycles)
        .def_readwrite("turning_escape", &ControlProfile::turning_escape, pydoc::ControlProfile_turning_escape)
        .def_readwrite("pattern_return_shifted", &ControlProfile::pattern_return_shifted,
                       pydoc::ControlProfile_pattern_return_shifted)
        .def_readwrite("cutting_edge_default", &ControlProfile::cutting_edge_default,
                       pydoc::ControlProfile_cutting_edge_default)
        .def_readwrite("m89_modal_cycle_call", &ControlProfile::m89_modal_cycle_call,
                       pydoc::ControlProfile_m89_modal_cycle_call)
        .def_readwrite("thread_chamfer", &ControlProfile::thread_chamfer, pydoc::ControlProfile_thread_chamfer)
        .def_readwrite("thread_chamfer_angle", &ControlProfile::thread_chamfer_angle,
                       pydoc::ControlProfile_thread_chamfer_angle)
        .def_readwrite("thread_finish_allowance", &ControlProfile::thread_finish_allowance,
                       pydoc::ControlProfile_thread_finish_allowance)
        .def_readwrite("thread_min_cut", &ControlProfile::thread_min_cut, pydoc::ControlProfile_thread_min_cut)
        .def_readwrite("roughing_nose_allowance", &ControlProfile::roughing_nose_allowance,
                       pydoc::ControlProfile_roughing_nose_allowance)
        .def_readwrite("g52_offset", &ControlProfile::g52_offset, pydoc::ControlProfile_g52_offset)
        .def_readwrite("macro_calls", &ControlProfile::macro_calls, pydoc::ControlProfile_macro_calls)
        .def_readwrite("m98_subprograms", &ControlProfile::m98_subprograms, pydoc::ControlProfile_m98_subprograms)
        .def_readwrite("ttrc_check_codes", &ControlProfile::ttrc_check_codes, pydoc::ControlProfile_ttrc_check_codes)
        .def_readwrite("program_end_required", &ControlProfile::program_end_required,
                       pydoc::ControlProfile_program_end_required)
        .def_readwrite("errors_at_outermost_call", &ControlProfile::errors_at_outermost_call,
                       pydoc::ControlProfile_errors_at_outermost_call)
        .def_readwrite("abort_comment", &ControlProfile::abort_comment, pydoc::ControlProfile_abort_comment)
        .def_readwrite("call_depth_message", &ControlProfile::call_depth_message,
                       pydoc::ControlProfile_call_depth_message)
        .def_readwrite("g96_needs_s", &ControlProfile::g96_needs_s, pydoc::ControlProfile_g96_needs_s)
        .def_readwrite("last_comment_only", &ControlProfile::last_comment_only, pydoc::ControlProfile_last_comment_only)
        .def_property(
            "call_depth_limit", [](const ControlProfile& p) { return p.call_depth_limit; },
            [](ControlProfile& p, std::size_t v) {
                if (v > kMaxCallDepthLimit)
                    throw py::value_error("call_depth_limit must be at most " + std::to_string(kMaxCallDepthLimit));
                p.call_depth_limit = v;
            },
            pydoc::ControlProfile_call_depth_limit)
        .def_property(
            "no_motion_limit", [](const ControlProfile& p) { return p.no_motion_limit; },
            [](ControlProfile& p, std::size_t v) {
                if (v < 1) throw py::value_error("no_motion_limit must be at least 1");
                p.no_motion_limit = v;
            },
            pydoc::ControlProfile_no_motion_limit)
        .def_readwrite("length_axes", &ControlProfile::length_axes, pydoc::ControlProfile_length_axes)
        .def_readwrite("length_subtract_word", &ControlProfile::length_subtract_word,
                       pydoc::ControlProfile_length_subtract_word)
        .def_readwrite("radius", &ControlProfile::radius, pydoc::ControlProfile_radius)
        .def("__repr__", [](const ControlProfile& p) { return "ControlProfile('" + p.name + "')"; });
    def_tolerance_pair(profile, "arc_spiral_abs", &ControlProfile::arc_spiral_abs,
                       pydoc::ControlProfile_arc_spiral_abs);
    def_tolerance(profile, "arc_spiral_rel", &ControlProfile::arc_spiral_rel, pydoc::ControlProfile_arc_spiral_rel);
    def_tolerance(profile, "arc_spiral_hard_factor", &ControlProfile::arc_spiral_hard_factor,
                  pydoc::ControlProfile_arc_spiral_hard_factor);
    def_tolerance_pair(profile, "arc_min_radius", &ControlProfile::arc_min_radius,
                       pydoc::ControlProfile_arc_min_radius);

    py::class_<Result, std::shared_ptr<Result>>(
        m, "Result", pydoc::Result)
        .def_property_readonly("ok", &Result::ok, pydoc::Result_ok)
        .def_readonly("diagnostics", &Result::diagnostics, pydoc::Result_diagnostics)
        .def_property_readonly("nominal",
                               [](std::shared_ptr<Result> r) { return std::shared_ptr<Path>(r, &r->nominal); },
                               pydoc::Result_nominal)
        .def_property_readonly(
            "path",
            [](std::shared_ptr<Result> r) { return std::shared_ptr<Path>(r, r->path_is_nominal ? &r->nominal : &r->path); },
            pydoc::Result_path)
        .def_readonly("blocks", &Result::blocks, pydoc::Result_blocks)
        .def_property_readonly(
            "cycle_time",
            [](const Result& r) {
                py::gil_scoped_release nogil;
                return r.cycle_time();
            },
            pydoc::Result_cycle_time)
        .def_readonly("dwell_time", &Result::dwell_seconds, pydoc::Result_dwell_seconds)
        .def_readonly("tools", &Result::tools, pydoc::Result_tools)
        .def_readonly("parameters", &Result::parameters, pydoc::Result_parameters)
        .def_property_readonly(
            "blank",
            [](const Result& r) {
                using Xyz = std::tuple<double, double, double>;
                std::optional<std::tuple<Xyz, Xyz>> out;
                auto t = [](const Vec3& v) { return Xyz(v.x(), v.y(), v.z()); };
                if (r.blank) out.emplace(t(r.blank->min), t(r.blank->max));
                return out;
            },
            pydoc::Result_blank)
        .def("__repr__", [](const Result& r) {
            return "Result(ok=" + std::string(r.ok() ? "True" : "False") + ", segments=" +
                   std::to_string(r.compensated().size()) + ", diagnostics=" + std::to_string(r.diagnostics.size()) + ")";
        });

    /// @pydoc compensate_3d
    /// 3D tool compensation of CAM tool datum points along surface normals: PT + DR2*N -
    /// (DR - DR2)*w (the same code as Heidenhain LN blocks). Arrays are (N, 3) float64;
    /// C-contiguous input is not copied, and `out` (which may be `points`) receives the
    /// result.
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
            if (!(R >= 0) || !(R2 >= 0) || R2 > R || !std::isfinite(R)) throw py::value_error("need 0 <= R2 <= R, finite");
            const auto n = static_cast<std::size_t>(points.shape(0));
            // The result goes into `out` itself (no hidden copy), or a new array.
            py::array result = out.is_none() ? py::array(py::array_t<double>({points.shape(0), py::ssize_t(3)}))
                                             : out.cast<py::array>();
            if (!result.dtype().is(py::dtype::of<double>()) || !(result.flags() & py::array::c_style) ||
                !result.writeable() || !shape_ok(result) || static_cast<std::size_t>(result.shape(0)) != n)
                throw py::value_error("out must be a writeable C-contiguous float64 array of shape (N, 3)");
            if (!std::isfinite(DR) || !std::isfinite(DR2)) throw py::value_error("DR and DR2 must be finite numbers");
            const double* p = points.data();
            const double* q = normals.data();
            const double* t = tool_axes ? tool_axes->data() : nullptr;
            double* o = static_cast<double*>(result.mutable_data());
            std::size_t bad = n;
            {
                py::gil_scoped_release nogil;
                // Checked before anything is written: `out` may be `points`.
                bad = first_bad_row(q, t, n);
                if (bad == n) compensate_3d(p, q, t, n, DR, DR2, o);
            }
            if (bad != n)
                throw py::value_error("row " + std::to_string(bad) +
                                      ": the normal and the tool axis must be directions (finite, not of zero "
                                      "length); nothing was written");
            return result;
        },
        py::arg("points"), py::arg("normals"), py::arg("tool_axes") = py::none(), py::kw_only(), py::arg("R"),
        py::arg("R2"), py::arg("DR") = 0.0, py::arg("DR2") = 0.0, py::arg("out") = py::none(), pydoc::compensate_3d);
}

// run() and run_file(): after bind_machine, so that their signatures name the Machine class.
void bind_run_calls(py::module_& m) {
    /// @pydoc run
    /// Interpret a Program with an optional ToolTable and apply tool compensation; returns
    /// a Result. strict=True raises the first error, strict=False returns the path up to
    /// it; block_delete skips '/' blocks; profile overrides the dialect's ControlProfile;
    /// progress(blocks_read) is called every progress_every blocks; search_path lists the
    /// directories where called programs and subprogram files are looked up; parameters
    /// gives numbered parameters their start values ({number: value}, e.g. a LinuxCNC .var
    /// file); a run whose programmed or compensated path would hold more than max_segments
    /// segments stops with ProgramError 'memory_limit' at the line of the block that
    /// crossed it; threads=False keeps the overcut watch on the run's thread (for batches
    /// that keep every core busy); follow_links lets a called file be a link out of its
    /// search directory; max_bytes and max_line_length bound every called file. The GIL is
    /// released while the program runs. probes: what the probe moves (LinuxCNC G38.2-G38.5)
    /// meet, one per probe move in order: None (no contact) or the contact point X Y Z [A B
    /// C] in the program's coordinates (mm); beyond them a probe touches at its target.
    /// start: where the axes stand when the program starts, (x, y, z) machine coordinates
    /// in mm; None: the machine's start, or without a machine where the program first sends
    /// each axis.
    m.def(
        "run",
        [](const Program& program, const ToolTable* tools, bool strict, bool block_delete,
           std::optional<ControlProfile> profile, py::object progress, std::size_t progress_every,
           std::vector<std::string> search_path, std::map<int, double> parameters, std::size_t max_segments,
           bool threads, bool follow_links, std::uint64_t max_bytes, std::size_t max_line_length,
           std::optional<Machine> machine, const std::vector<std::optional<std::vector<double>>>& probes,
           std::optional<std::array<double, 3>> start) {
            RunOptions o = run_options(strict, block_delete, std::move(profile), progress, progress_every,
                                       std::move(search_path), std::move(parameters), max_segments, threads,
                                       follow_links, machine);
            o.probes = probe_results(probes);
            o.start = start_position(start);
            o.limits = ReadLimits{max_bytes, max_line_length};
            const auto table = snapshot(tools);
            py::gil_scoped_release nogil;
            return std::make_shared<Result>(run(program, ptr(table), o));
        },
        py::arg("program"), py::arg("tools") = nullptr, py::arg("strict") = true, py::arg("block_delete") = false,
        py::arg("profile") = py::none(), py::arg("progress") = py::none(), py::arg("progress_every") = 1 << 16,
        py::arg("search_path") = std::vector<std::string>{}, py::arg("parameters") = std::map<int, double>{},
        py::arg("max_segments") = kDefaultMaxSegments, py::arg("threads") = true, py::arg("follow_links") = false,
        py::arg("max_bytes") = kDefaultMaxProgramBytes, py::arg("max_line_length") = kDefaultMaxLineLength,
        py::arg("machine") = py::none(), py::arg("probes") = std::vector<std::optional<std::vector<double>>>{},
        py::arg("start") = py::none(), pydoc::run);
    /// @pydoc run_file
    /// run() on a program file, read leniently; a LinuxCNC / Fanuc file without control
    /// flow is read and parsed a piece at a time as it runs (see toolcomp.run).
    m.def(
        "run_file",
        [](const std::string& path, std::optional<std::string> dialect, const ToolTable* tools, bool strict,
           bool block_delete, std::optional<ControlProfile> profile, py::object progress, std::size_t progress_every,
           std::vector<std::string> search_path, std::map<int, double> parameters, std::size_t max_segments,
           std::uint64_t max_bytes, std::size_t max_line_length, bool threads, bool follow_links,
           std::optional<Machine> machine, const std::vector<std::optional<std::vector<double>>>& probes,
           std::optional<std::array<double, 3>> start) {
            RunOptions o = run_options(strict, block_delete, std::move(profile), progress, progress_every,
                                       std::move(search_path), std::move(parameters), max_segments, threads,
                                       follow_links, machine);
            o.probes = probe_results(probes);
            o.start = start_position(start);
            std::optional<Dialect> d;
            if (dialect) d = dialect_from_name(*dialect);
            const auto table = snapshot(tools);
            py::gil_scoped_release nogil;
            return std::make_shared<Result>(run_file(path, d, ptr(table), o, ReadLimits{max_bytes, max_line_length}));
        },
        py::arg("path"), py::arg("dialect"), py::arg("tools"), py::arg("strict"), py::arg("block_delete"),
        py::arg("profile"), py::arg("progress"), py::arg("progress_every"), py::arg("search_path"),
        py::arg("parameters"), py::arg("max_segments"), py::arg("max_bytes"), py::arg("max_line_length"),
        py::arg("threads") = true, py::arg("follow_links") = false, py::arg("machine") = py::none(),
        py::arg("probes") = std::vector<std::optional<std::vector<double>>>{}, py::arg("start") = py::none(),
        pydoc::run_file);
}
