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
    py::enum_<LengthAxes>(m, "LengthAxes", "Which axes a tool length offset (G43 H) acts on.")
        .value("all", LengthAxes::all, "the tool's whole offset vector (LinuxCNC: X..W from the tool table)")
        .value("z_only", LengthAxes::z_only, "type A: the tool's length on Z whatever the plane (Fanuc default)")
        .value("plane_normal", LengthAxes::plane_normal, "type B: the length on the axis normal to the active plane");

    py::enum_<EntryStyle>(m, "EntryStyle", "How a control finishes the activation block of radius compensation.")
        .value("perpendicular_to_entry", EntryStyle::perpendicular_to_entry,
               "the activation block ends perpendicular to itself at its programmed end, then the corner rule "
               "joins it to the next element (LinuxCNC; Fanuc start-up type B; Sinumerik KONT)")
        .value("perpendicular_to_next", EntryStyle::perpendicular_to_next,
               "the activation block ends where the next element's equidistant starts, perpendicular to the next "
               "element (Fanuc start-up type A; Sinumerik NORM; Heidenhain RL/RR)")
        .value("around_start_when_behind", EntryStyle::around_start_when_behind,
               "Sinumerik KONT: as perpendicular_to_next, unless the start point lies behind the contour; then as "
               "perpendicular_to_entry, so the tool goes round the contour start by the outside-corner rule");
    py::enum_<ExitStyle>(m, "ExitStyle", "How the compensated path leaves the contour when compensation is cancelled.")
        .value("perpendicular_to_last", ExitStyle::perpendicular_to_last,
               "the last compensated move ends perpendicular to itself at its programmed end; the cancel move runs "
               "from there to its programmed end point (LinuxCNC; Fanuc type A)")
        .value("corner_with_exit", ExitStyle::corner_with_exit,
               "the cancel move starts perpendicular to itself at its start, joined to the last move by the corner "
               "rule, and ends uncompensated (Fanuc type B)")
        .value("around_end_when_behind", ExitStyle::around_end_when_behind,
               "Sinumerik KONT: as perpendicular_to_last, unless the cancel move's end point lies behind the "
               "contour; then as corner_with_exit, round the contour end by the outside-corner rule");
    py::enum_<OutsideCorner>(m, "OutsideCorner", "What fills the gap at an outside corner of the compensated path.")
        .value("arc", OutsideCorner::arc, "transition arc of the tool radius about the programmed corner")
        .value("intersection", OutsideCorner::intersection,
               "meet at the intersection of the equidistants; turns sharper than corner_limit get the transition arc")
        .value("extension", OutsideCorner::extension,
               "intersection for turns up to corner_limit; sharper ones extend both elements by the radius and join "
               "the extensions with a line");
    py::enum_<GougeReaction>(m, "GougeReaction",
                             "What the control does when the compensated tool cannot reach part of the contour.")
        .value("error", GougeReaction::error, "stop with the control's alarm (LinuxCNC, Fanuc, Heidenhain default)")
        .value("skip", GougeReaction::skip,
               "leave out the unreachable elements and join the neighbours where their equidistants cross, within "
               "the look-ahead (Sinumerik CDON, Heidenhain M120)")
        .value("report", GougeReaction::report, "keep the path as computed (it gouges) and report a warning");
    py::enum_<NonPlaneReaction>(
        m, "NonPlaneReaction",
        "What happens when more than max_non_plane_moves blocks without motion in the plane follow each other "
        "while compensating.")
        .value("error", NonPlaneReaction::error, "refuse the program (Sinumerik alarm 10762)")
        .value("overcut", NonPlaneReaction::overcut,
               "end the held move perpendicular to its programmed end and warn (9/Series)");

    py::class_<RadiusRules>(m, "RadiusRules", "How a control applies cutter radius compensation.")
        .def_readwrite("yz_plane", &RadiusRules::yz_plane,
                       "compensation allowed in G19 (LinuxCNC refuses it)")
        .def_readwrite("entry", &RadiusRules::entry,
                       "EntryStyle: how the activation block of compensation ends")
        .def_readwrite("entry_arc", &RadiusRules::entry_arc,
                       "an arc may be the activation block (LinuxCNC: yes)")
        .def_readwrite("exit", &RadiusRules::exit,
                       "ExitStyle: how the path leaves the contour when compensation is cancelled")
        .def_readwrite("tip_convention", &RadiusRules::tip_convention,
                       "TipConvention: how lathe tip numbers (CuttingEdge.orientation) are read")
        .def_readwrite("extension_min_length", &RadiusRules::extension_min_length,
                       "extension blocks: a middle block shorter than this in both plane axes is dropped, mm "
                       "(9/Series AMP minimum)")
        .def_readwrite("ct_radius_on_contour", &RadiusRules::ct_radius_on_contour,
                       "Heidenhain APPR/DEP CT and LCT: R is the contour radius (tool arc R - r) when True, "
                       "the tool-centre radius when False")
        .def_readwrite("lct_tangency_tool_space", &RadiusRules::lct_tangency_tool_space,
                       "Heidenhain APPR/DEP LCT: tangency in tool-centre space when True, on the contour "
                       "circle when False")
        .def_readwrite("exit_direction_words", &RadiusRules::exit_direction_words,
                       "I/K (I/J) in the cancel block give the direction in which the contour is taken to go on, "
                       "for the last compensated move's end (9/Series); False: they need an arc to use them")
        .def_readwrite("offset_change_reenters", &RadiusRules::offset_change_reenters,
                       "a work offset change under compensation (G54-G59.3, G92...) ends it for the moment: the "
                       "last move is the exit, the first move in the new system an entry (9/Series); False: "
                       "refused (LinuxCNC, Fanuc)")
        .def_readwrite("exit_must_be_straight", &RadiusRules::exit_must_be_straight,
                       "the move after the cancel (G40) may not be an arc")
        .def_readwrite("entry_length_check", &RadiusRules::entry_length_check,
                       "the entry move must be longer than the tool radius (LinuxCNC)")
        .def_readwrite("outside_corner", &RadiusRules::outside_corner,
                       "OutsideCorner: what fills the gap at an outside corner")
        .def_readwrite("corner_limit", &RadiusRules::corner_limit,
                       "turn angle, radians, beyond which intersection/extension corners change rule (see "
                       "OutsideCorner)")
        .def_readwrite("disc", &RadiusRules::disc,
                       "Sinumerik DISC, 0..100: the corner between two straight moves becomes a fillet of radius "
                       "r*(1 - DISC/100); 0 is the transition arc, 100 the sharp intersection")
        .def_readwrite("side_change", &RadiusRules::side_change,
                       "G41 <-> G42 without G40 between is allowed: the old move ends perpendicular at its "
                       "end, the new starts perpendicular at its start, joined by a line (Fanuc, Sinumerik, "
                       "9/Series); False refuses it (LinuxCNC, Heidenhain)")
        .def_readwrite("corner_tolerance", &RadiusRules::corner_tolerance,
                       "joints turning at most this much (radians) are tangent: nothing is inserted")
        .def_property(
            "arc_sweep_tolerance",
            [](const RadiusRules& r) { return std::make_pair(r.arc_sweep_tolerance[0], r.arc_sweep_tolerance[1]); },
            [](RadiusRules& r, std::pair<double, double> v) {
                r.arc_sweep_tolerance[0] = v.first;
                r.arc_sweep_tolerance[1] = v.second;
            },
            "how much more (radians) a pulled-back arc may sweep than programmed before it gouges, as "
            "(mm programs, inch programs)")
        .def_readwrite("max_non_plane_moves", &RadiusRules::max_non_plane_moves,
                       "consecutive blocks without plane motion the control looks past; -1 = no limit")
        .def_readwrite("count_blocks_without_motion", &RadiusRules::count_blocks_without_motion,
                       "blocks that move nothing (M8, S500, G4, F alone; not assignments, calls or comments) "
                       "count among the blocks without plane motion (Fanuc, 9/Series, Sinumerik); False: only "
                       "moves without plane motion count (LinuxCNC, Heidenhain)")
        .def_readwrite("non_plane_reaction", &RadiusRules::non_plane_reaction,
                       "NonPlaneReaction: what happens beyond max_non_plane_moves")
        .def_readwrite("lookahead", &RadiusRules::lookahead,
                       "plane moves looked at when an element turns out unreachable (LinuxCNC: 1)")
        .def_readwrite("gouge", &RadiusRules::gouge,
                       "GougeReaction: what happens when the tool cannot reach part of the contour")
        .def_readwrite("overcut_neighbours", &RadiusRules::overcut_neighbours,
                       "programmed elements before and after each compensated one whose contour its tool "
                       "centre is checked against (warning 'comp_overcut'); 0 = no check")
        .def_readwrite("overcut_tolerance", &RadiusRules::overcut_tolerance,
                       "mm the tool centre may come closer to that contour than the radius without a warning");

    py::enum_<TipConvention>(m, "TipConvention", "Numbering of lathe tool tip directions (orientation 0..9).")
        .value("linuxcnc", TipConvention::linuxcnc,
               "LinuxCNC: 1 (-X,+Z), 2 (-X,-Z), 3 (+X,-Z), 4 (+X,+Z), 5 +Z, 6 -X, 7 -Z, 8 +X; 0 and 9 centre")
        .value("fanuc", TipConvention::fanuc,
               "Fanuc/Haas: as linuxcnc with the sign of X flipped (1<->4, 2<->3, 6<->8)");
    py::enum_<MachineKind>(m, "MachineKind", "The kind of machine of a ControlProfile: mill or lathe.")
        .value("mill", MachineKind::mill, "milling machine")
        .value("lathe", MachineKind::lathe,
               "lathe (in the Fanuc profile: X diameters, incremental U/W, T-word offsets, Fanuc tip numbers)");

    py::class_<ControlProfile> profile(
        m, "ControlProfile",
        "How a particular control behaves, as plain data: the profile of a dialect ('linuxcnc', 'fanuc', ...) "
        "and machine ('mill' or 'lathe'), whose fields may be adjusted and passed as run(..., profile=...).");
    profile
        .def(py::init([](const std::string& dialect, std::optional<std::string> kind, std::optional<std::string> machine) {
                 if (kind && machine && *kind != *machine)
                     throw py::value_error("kind and machine (its former name) name different kinds");
                 return profile_for(dialect_from_name(dialect), machine_kind(kind ? *kind : machine.value_or("mill")));
             }),
             py::arg("dialect") = "linuxcnc", py::arg("kind") = py::none(), py::arg("machine") = py::none(),
             "The profile of a control ('linuxcnc', 'fanuc', 'sinumerik', 'heidenhain', 'rockwell') on a kind of "
             "machine ('mill' or 'lathe'; machine= is its former name)")
        .def_readonly("kind", &ControlProfile::kind, "MachineKind: mill or lathe (fixed at construction)")
        .def_readonly("machine", &ControlProfile::kind, "the former name of kind")
        .def_readwrite("x_diameter", &ControlProfile::x_diameter,
                       "lathe: X words are diameters")
        .def_readwrite("incremental_uw", &ControlProfile::incremental_uw,
                       "lathe: U and W are incremental X and Z")
        .def_readwrite("t_offsets", &ControlProfile::t_offsets,
                       "lathe: a T word is tool and offset number (T0313: tool 3, offset 13) and applies the "
                       "offset at once (geometry + wear X and Z, nose radius and tip; no D word)")
        .def_readwrite("g_code_system_a", &ControlProfile::g_code_system_a,
                       "Fanuc lathe G-code system A: G90, G92 and G94 are the turning, threading and facing cycles "
                       "(refused), G91 does not exist (U and W are the increments)")
        .def_readwrite("modal_offset_numbers", &ControlProfile::modal_offset_numbers,
                       "H and D are modal offset numbers (Fanuc): G43/G44 without H take the last H, G41/G42 without "
                       "D the last D, both 0 at the start (no offset); False: the tool in the spindle (LinuxCNC)")
        .def_readwrite("t_format", &ControlProfile::t_format,
                       "how a T word splits into tool, geometry and wear offset numbers: 0 T<tool><two offset "
                       "digits> (Fanuc); 1-3 geometry and wear from the last 1, 2 or 3 digits; 4-6 wear from "
                       "the last 1, 2 or 3 digits and geometry from the tool number (9/Series)")
        .def_readwrite("wear_sign", &ControlProfile::wear_sign,
                       "effective offset = geometry + wear_sign * wear")
        .def_readwrite("tool_length_const", &ControlProfile::tool_length_const,
                       "Sinumerik SD42940 TOOL_LENGTH_CONST: 0, or 17/18/19 (and negative) to fix the length axes")
        .def_readwrite("tool_length_type", &ControlProfile::tool_length_type,
                       "Sinumerik SD42950 TOOL_LENGTH_TYPE: 0 by tool type, 1 always milling, 2 always turning")
        .def_readwrite("tool_parameter_def_mask", &ControlProfile::tool_parameter_def_mask,
                       "Sinumerik MD20360: bit 0 wear, bit 1 geometry in diameter on the transverse axis (GETTCOR)")
        .def_readwrite("name", &ControlProfile::name,
                       "profile name (the dialect's name for built-in profiles)")
        .def_readwrite("startup_inch", &ControlProfile::startup_inch,
                       "G20 (inch) active at program start")
        .def_property(
            "startup_plane",
            [](const ControlProfile& p) { return p.startup_plane == Plane::xy ? 17 : p.startup_plane == Plane::zx ? 18 : 19; },
            [](ControlProfile& p, int g) {
                if (g != 17 && g != 18 && g != 19) throw py::value_error("startup_plane must be 17, 18 or 19");
                p.startup_plane = g == 17 ? Plane::xy : g == 18 ? Plane::zx : Plane::yz;
            },
            "the working plane at program start: 17 (XY, mills), 18 (ZX, lathes) or 19")
        .def_readwrite("startup_feed_per_rev", &ControlProfile::startup_feed_per_rev,
                       "feed per revolution at program start (Fanuc lathes: G99 at power on)")
        .def_readwrite("block_limit", &ControlProfile::block_limit, "blocks a program may execute (loops count)")
        .def_readwrite("feed_mode_clears_feed", &ControlProfile::feed_mode_clears_feed,
                       "G94/G95 set the feed rate to 0, so the next feed move needs an F word (LinuxCNC)")
        .def_readwrite("tool_change_after_block", &ControlProfile::tool_change_after_block,
                       "a tool change counts only after its block: G41/G42 without D and G43 without H beside "
                       "M6/M61 take the tool in the spindle before it (rs274's way)")
        .def_readwrite("bare_motion_codes", &ControlProfile::bare_motion_codes,
                       "G0/G1/G2/G3 without axis words move to where the tool is, other motion codes need "
                       "axis words, I/J/K alone under a modal G2/G3 make an arc (LinuxCNC); False: a motion "
                       "code alone only sets the mode")
        .def_readwrite("inverse_time_min_rate", &ControlProfile::inverse_time_min_rate,
                       "least feed rate of a G93 move, program units a minute (LinuxCNC 0.1)")
        .def_readwrite("integer_word_slack", &ControlProfile::integer_word_slack,
                       "integer words with LinuxCNC's slack (M T H L within 0.0001, D is_near_int, G2/G3 P 0.001, "
                       "M61 Q and G10 P to the nearest); False: exactly whole, as written")
        .def_readwrite("linuxcnc_g_numbers", &ControlProfile::linuxcnc_g_numbers,
                       "G numbers read as LinuxCNC's read_g does; False: to a tenth, exactly")
        .def_readwrite("last_g_code_wins", &ControlProfile::last_g_code_wins,
                       "two G codes of one modal group in a block: the last counts (Fanuc); False: refused")
        .def_readwrite("max_m_code", &ControlProfile::max_m_code, "the highest M code number (LinuxCNC 199)")
        .def_readwrite("fixed_m_codes", &ControlProfile::fixed_m_codes,
                       "the M codes the control itself fixes, which a machine cannot declare")
        .def_readwrite("negative_l_refused", &ControlProfile::negative_l_refused,
                       "a negative L word is refused as it is read (LinuxCNC)")
        .def_readwrite("dwell_negative_p", &ControlProfile::dwell_negative_p,
                       "G4: only P-1 is missing, negative P dwells (LinuxCNC); False: a negative P is missing")
        .def_readwrite("arc_turns_word", &ControlProfile::arc_turns_word,
                       "G2/G3 P is the number of turns (LinuxCNC); False: a P on an arc is refused")
        .def_readwrite("c_word_is_chamfer", &ControlProfile::c_word_is_chamfer,
                       "C beside X/Z in a lathe's G1 is the Fanuc T chamfer (refused), not a C axis move")
        .def_readwrite("dwell_x_seconds", &ControlProfile::dwell_x_seconds,
                       "G4 X (U on lathes) is the dwell in seconds, P in milliseconds (Fanuc)")
        .def_readwrite("g10_tool_table", &ControlProfile::g10_tool_table,
                       "G10 L1/L10/L11 set a tool's offsets in the run's copy of the tool table (LinuxCNC); False: refused")
        .def_readwrite("numbered_subprograms", &ControlProfile::numbered_subprograms,
                       "Fanuc-style numbered subprograms as LinuxCNC 2.9 reads them: O<n> ... M99, M98 P L as a line's first word")
        .def_readwrite("modal_state_codes", &ControlProfile::modal_state_codes,
                       "M70-M73 save, invalidate and restore the modal state, M73 until the subroutine returns (LinuxCNC)")
        .def_readwrite("tool_change_stops_spindle", &ControlProfile::tool_change_stops_spindle,
                       "M6 stops the spindle (LinuxCNC without TOOL_CHANGE_WITH_SPINDLE_ON)")
        .def_readwrite("splines", &ControlProfile::splines,
                       "G5, G5.1 splines and G5.2/G5.3 NURBS as LinuxCNC's machine cuts them (biarcs); False: refused")
        .def_readwrite("spindle_sync_motion", &ControlProfile::spindle_sync_motion,
                       "G33, G33.1 and the G76 threading cycle as LinuxCNC runs them; False: refused")
        .def_readwrite("profile_cycles", &ControlProfile::profile_cycles,
                       "LinuxCNC's lathe profile cycles G70, G71, G72 and G71.1/.2, G72.1/.2; False: refused")
        .def_readwrite("spindle_orient", &ControlProfile::spindle_orient,
                       "LinuxCNC's M19 R Q P: the spindle stops, oriented (no move); False: refused")
        .def_readwrite("restore_feed_speed_always", &ControlProfile::restore_feed_speed_always,
                       "M72/M73 restores set F and S even when unchanged (LinuxCNC 2.9.1 on); False: only when they differ")
        .def_readwrite("fanuc_g10", &ControlProfile::fanuc_g10,
                       "G10 L2/L20 as Fanuc reads them (L20 and L2 P0 refused, P 1-6, no R, L2 adds in G91); "
                       "False: LinuxCNC's G10")
        .def_readwrite("startup_motion", &ControlProfile::startup_motion,
                       "the motion mode at start, ten times its G code: 800 (G80: axis words need a motion code, "
                       "LinuxCNC) or 0 (G00, Fanuc)")
        .def_readwrite("cycles_own_group", &ControlProfile::cycles_own_group,
                       "G80 is group 09 with the cycles: it cancels a cycle and the G00-G03 mode before it is back (Fanuc)")
        .def_readwrite("startup_retract_initial", &ControlProfile::startup_retract_initial,
                       "canned cycles return to the initial level (G98) at start (Fanuc mill); False: G99 (LinuxCNC)")
        .def_readwrite("motion_beside_data_axes", &ControlProfile::motion_beside_data_axes,
                       "G00-G03 beside G28/G30/G10/G92/G50 only sets the mode, the axis words are that code's (Fanuc)")
        .def_readwrite("g84_axes_warning", &ControlProfile::g84_axes_warning,
                       "warn at G84 in G18/G19: LinuxCNC 2.9 feeds that tap along the plane's axes out of order")
        .def_readwrite("g53_rapid", &ControlProfile::g53_rapid,
                       "G53 moves at rapid whatever the motion mode (Fanuc); False: it needs G0 or G1 (LinuxCNC)")
        .def_readwrite("d_word_alone", &ControlProfile::d_word_alone,
                       "a D word without G41/G42 sets the D number of the next G41/G42 (Fanuc)")
        .def_readwrite("turning_cycles", &ControlProfile::turning_cycles,
                       "the Fanuc T series' lathe cycles G70-G76, G90/G92/G94 and G32")
        .def_readwrite("turning_escape", &ControlProfile::turning_escape,
                       "the escape of a G71/G72 pass when the cycle gives no R, mm (Fanuc parameter 5133, Haas setting 73)")
        .def_readwrite("pattern_return_shifted", &ControlProfile::pattern_return_shifted,
                       "G73: after each pass the tool goes back to the start shifted as the next pass (Haas)")
        .def_readwrite("cutting_edge_default", &ControlProfile::cutting_edge_default,
                       "Sinumerik MD20270: the edge M6 selects (n; 0 none; -1 the D number programmed before M6)")
        .def_readwrite("m89_modal_cycle_call", &ControlProfile::m89_modal_cycle_call,
                       "Heidenhain M89 calls the cycle after every positioning block until M99 / CYCL CALL / CYCL DEF "
                       "(false: a free M function)")
        .def_readwrite("thread_chamfer", &ControlProfile::thread_chamfer,
                       "the pull-out chamfer at the end of G92 and one-block G76 threads, in leads (Haas setting 95; 0: none)")
        .def_readwrite("thread_chamfer_angle", &ControlProfile::thread_chamfer_angle,
                       "the thread chamfer's angle from the Z axis, degrees (Haas setting 96)")
        .def_readwrite("thread_finish_allowance", &ControlProfile::thread_finish_allowance,
                       "the one-block G76's finishing allowance, mm (Haas setting 86)")
        .def_readwrite("thread_min_cut", &ControlProfile::thread_min_cut,
                       "the one-block G76's least depth of a pass, mm (Haas setting 99)")
        .def_readwrite("roughing_nose_allowance", &ControlProfile::roughing_nose_allowance,
                       "G41/G42 in a G71/G72 contour: the roughing passes leave the nose radius more allowance (Haas)")
        .def_readwrite("g52_offset", &ControlProfile::g52_offset,
                       "G52 offsets all coordinate systems as LinuxCNC runs it; False: refused (not run)")
        .def_readwrite("macro_calls", &ControlProfile::macro_calls,
                       "G65 calls a macro program, G66/G67 (refused) are its modal calls (Fanuc); False: unknown codes")
        .def_readwrite("m98_subprograms", &ControlProfile::m98_subprograms,
                       "M98 P calls a subprogram, M99 returns (Fanuc); False: unknown codes")
        .def_readwrite("ttrc_check_codes", &ControlProfile::ttrc_check_codes,
                       "M800/M801 switch the TTRC checks off/on (9/Series); False: unknown codes")
        .def_readwrite("program_end_required", &ControlProfile::program_end_required,
                       "a program must end with M2/M30 or '%' (LinuxCNC)")
        .def_readwrite("errors_at_outermost_call", &ControlProfile::errors_at_outermost_call,
                       "an error in a called subroutine is reported at the line of the outermost call (LinuxCNC)")
        .def_readwrite("abort_comment", &ControlProfile::abort_comment,
                       "(ABORT, text) stops the program with the text (LinuxCNC 2.9)")
        .def_readwrite("call_depth_message", &ControlProfile::call_depth_message,
                       "the error text for calls nested too deep ('' : toolcomp's own, naming the limit)")
        .def_readwrite("g96_needs_s", &ControlProfile::g96_needs_s,
                       "G96 needs an S word in its block (LinuxCNC); False: the S in force is the surface speed")
        .def_readwrite("last_comment_only", &ControlProfile::last_comment_only,
                       "only the last comment in parentheses of a block is read for MSG/DEBUG/PRINT, ';' "
                       "comments never (LinuxCNC); False: every comment")
        .def_property(
            "call_depth_limit", [](const ControlProfile& p) { return p.call_depth_limit; },
            [](ControlProfile& p, std::size_t v) {
                if (v > kMaxCallDepthLimit)
                    throw py::value_error("call_depth_limit must be at most " + std::to_string(kMaxCallDepthLimit));
                p.call_depth_limit = v;
            },
            "nested subprogram calls a program may make (LinuxCNC 9, Fanuc 10, default 100; at most 10000)")
        .def_property(
            "no_motion_limit", [](const ControlProfile& p) { return p.no_motion_limit; },
            [](ControlProfile& p, std::size_t v) {
                if (v < 1) throw py::value_error("no_motion_limit must be at least 1");
                p.no_motion_limit = v;
            },
            "blocks executed in a row without a move before the run stops with 'no_progress' (an endless loop "
            "that never moves the tool; default 10 000 000)")
        .def_readwrite("length_axes", &ControlProfile::length_axes,
                       "LengthAxes: which axes a tool length offset (G43 H) acts on")
        .def_readwrite("length_subtract_word", &ControlProfile::length_subtract_word,
                       "G44 (subtract the tool length offset) exists")
        .def_readwrite("radius", &ControlProfile::radius,
                       "RadiusRules: the cutter radius compensation rules")
        .def("__repr__", [](const ControlProfile& p) { return "ControlProfile('" + p.name + "')"; });
    def_tolerance_pair(profile, "arc_spiral_abs", &ControlProfile::arc_spiral_abs,
                       "an arc by its centre is refused when its start and end radius differ by more than this and "
                       "by more than arc_spiral_rel of the larger radius, as (mm programs in mm, inch programs in "
                       "inch); LinuxCNC 2.9: (0.0283, 0.00283)");
    def_tolerance(profile, "arc_spiral_rel", &ControlProfile::arc_spiral_rel,
                  "see arc_spiral_abs: the relative part of the test (LinuxCNC 2.9: 0.001)");
    def_tolerance(profile, "arc_spiral_hard_factor", &ControlProfile::arc_spiral_hard_factor,
                  "an arc whose start and end radius differ by more than this times arc_spiral_abs is refused "
                  "whatever its radius (LinuxCNC 2.9: 100)");
    def_tolerance_pair(profile, "arc_min_radius", &ControlProfile::arc_min_radius,
                       "arcs of a smaller radius are zero-radius arcs, and an R-format chord may exceed 2|R| by "
                       "this, as (mm programs in mm, inch programs in inch); LinuxCNC 2.9: (0.00127, 0.00005)");

    py::class_<Result, std::shared_ptr<Result>>(
        m, "Result", "The outcome of run(): programmed and compensated paths, diagnostics and block count.")
        .def_property_readonly("ok", &Result::ok, "True when no diagnostic has severity 'error'")
        .def_readonly("diagnostics", &Result::diagnostics,
                      "list of Diagnostic (info and warnings; with strict=False also the error that stopped the run)")
        .def_property_readonly("nominal",
                               [](std::shared_ptr<Result> r) { return std::shared_ptr<Path>(r, &r->nominal); },
                               "the programmed Path (what the interpreter produced, before compensation)")
        .def_property_readonly(
            "path",
            [](std::shared_ptr<Result> r) { return std::shared_ptr<Path>(r, r->path_is_nominal ? &r->nominal : &r->path); },
            "the compensated Path (after the compensation stages); the `nominal` Path itself when no stage changed "
            "a segment (a program without compensation: stored once)")
        .def_readonly("blocks", &Result::blocks, "number of blocks in the program")
        .def_property_readonly(
            "cycle_time",
            [](const Result& r) {
                py::gil_scoped_release nogil;
                return r.cycle_time();
            },
            "seconds the program takes on the run's machine: path.duration summed, the dwells (dwell_time) and "
            "path.tool_changes times the machine's tool_change_time; an estimate without acceleration "
            "(doc/cycle-time.md)")
        .def_readonly("dwell_time", &Result::dwell_seconds,
                      "seconds the program dwells: G4 (LinuxCNC P seconds, Fanuc P milliseconds or X/U seconds, "
                      "Sinumerik F seconds or S revolutions), the dwells of LinuxCNC/Fanuc canned cycles (G82, G86, "
                      "G88, G89 P), Heidenhain CYCL DEF 9")
        .def_readonly("tools", &Result::tools,
                      "the tool table as the program left it when it edited it (LinuxCNC G10 L1: the run's copy; "
                      "the table passed in is never changed), else None")
        .def_readonly("parameters", &Result::parameters,
                      "numbered parameters set at the end of the run, {number: value} (LinuxCNC, Fanuc; vacant "
                      "Fanuc variables and LinuxCNC zeros left out)")
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
                   std::to_string(r.compensated().size()) + ", diagnostics=" + std::to_string(r.diagnostics.size()) + ")";
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
        py::arg("R2"), py::arg("DR") = 0.0, py::arg("DR2") = 0.0, py::arg("out") = py::none(),
        "3D tool compensation of CAM tool datum points along surface normals: PT + DR2*N - (DR - DR2)*w "
        "(the same code as Heidenhain LN blocks). Arrays are (N, 3) float64; C-contiguous input is not "
        "copied, and `out` (which may be `points`) receives the result.");

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
        py::arg("start") = py::none(),
        "Interpret a Program with an optional ToolTable and apply tool compensation; returns a Result. strict=True "
        "raises the first error, strict=False returns the path up to it; block_delete skips '/' blocks; profile "
        "overrides the dialect's ControlProfile; progress(blocks_read) is called every progress_every blocks; "
        "search_path lists the directories where called programs and subprogram files are looked up; parameters "
        "gives numbered parameters their start values ({number: value}, e.g. a LinuxCNC .var file); a run "
        "whose programmed or compensated path would hold more than max_segments segments stops with "
        "ProgramError 'memory_limit' at the line of the block that crossed it; threads=False keeps the "
        "overcut watch on the run's thread (for batches that keep every core busy); follow_links lets a called file be a "
        "link out of its search directory; max_bytes and max_line_length bound every called file. The GIL is "
        "released while the program runs. probes: what the probe moves (LinuxCNC G38.2-G38.5) meet, one per "
        "probe move in order: None (no contact) or the contact point X Y Z [A B C] in the program's coordinates "
        "(mm); beyond them a probe touches at its target. start: where the axes stand when the program starts, "
        "(x, y, z) machine coordinates in mm; None: the machine's start, or without a machine where the program "
        "first sends each axis.");
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
        "run() on a program file, read leniently; a LinuxCNC / Fanuc file without control flow is read and "
        "parsed a piece at a time as it runs (see toolcomp.run).");
}
