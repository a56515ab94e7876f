#pragma once
// Working data of the Klartext interpreter. Positions in program units (BEGIN PGM MM|INCH),
// in machine axis order X Y Z; the working plane follows the tool axis of TOOL CALL.
#include <functional>
#include <initializer_list>
#include <string_view>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "../idle_watch.hpp"
#include "../../cycles/tnc_drilling.hpp"
#include "frame.hpp"
#include "toolcomp/program/source_files.hpp"
#include "toolcomp/compensation/approach.hpp"
#include "toolcomp/geometry/element.hpp"
#include "toolcomp/dialects/heidenhain/interpreter.hpp"

namespace toolcomp::heidenhain {

struct ToolDef {
    double length = 0, radius = 0, r2 = 0;
};

class Interp {
public:
    Interp(const Program& prog, const ToolTable* tools, const ControlProfile& profile, MotionSink& sink,
           std::vector<Diagnostic>& diags, SearchPath search = {});
    // The machine the program runs on (interp_machine.cpp): its builder M codes, work origin,
    // machine datums (M91, M92) and tool change position. The run starts at its zero.
    void set_machine(const Machine* m);
    void set_start(const Vec3& machine);  // the axes at the start, machine coordinates (mm)
    void skip_marked_blocks(bool on) { block_delete_ = on; }  // the block skip '/'
    void read_in_pieces(PieceHooks hooks) { pieces_ = std::move(hooks); }
    void run();
    const std::vector<std::string>& files() const { return files_.names(); }
    double dwell_seconds() const { return dwell_seconds_; }
    // Called with the number of blocks executed so far, every `every` blocks.
    void on_progress(std::function<void(std::size_t)> f, std::size_t every) {
        progress_ = std::move(f);
        progress_every_ = every ? every : 1;
    }

private:
    std::function<void(std::size_t)> progress_;
    bool block_delete_ = false;
    std::size_t progress_every_ = 1 << 16;
    using Tokens = std::span<const Token>;
    bool tolerance_noted_ = false;  // CYCL DEF 32's note given
    // The coordinate transformations (CYCL DEF 7, 8, 10, 11, 26; interp_transform.cpp): the
    // interpreter works in program coordinates (pos_, the pole, cycle surfaces), sink_ hands
    // the moves on from the preset.
    Transformations transforms_;
    void datum_shift(Tokens t);
    void mirror_image(Tokens t);
    void rotation(Tokens t);
    void scaling(Tokens t);
    void axis_scaling(Tokens t);
    void datum_setting(Tokens t);  // CYCL DEF 247
    void transform(const Transformations& next, int column);  // takes effect from here
    // Refuses `what` (its geometry holds the tool radius) under scaling: "scaling_refused".
    void refuse_scaled(const char* what, int column) const;
    const Frame& frame() const { return sink_.frame(); }
    // The machining cycles (interp_cycles.cpp): CYCL DEF stores the cycle and its Q
    // parameters (the old cycles 1 and 17: their numbered lines' values, by line), CYCL CALL,
    // M99 and M89 run it where the tool stands, CYCL CALL POS / PAT and the pattern cycles
    // 220 / 221 elsewhere (interp_patterns.cpp).
    struct CycleDef {
        int number = 0;
        std::map<int, double> q;  // Q200=... (a Q208=MAX: +inf); old cycles: line -> value
    };
    std::optional<CycleDef> cycle_def_;
    void define_machining(Tokens t, int number);
    void define_old_cycle(Tokens t);
    void builder_cycle(Tokens t);
    std::map<int, double> cycle_parameters(Tokens t) const;  // Q200=... of a definition  // a cycle the machine file declares (Machine::cycles)
    void working_plane(Tokens t);  // CYCL DEF 19
    void plane_function(Tokens t);  // PLANE ...
    void untilted_plane();          // Q120-Q122 = 0
    void function_block(Tokens t);  // FUNCTION TCPM / FUNCTION RESET TCPM
    void cycle_call(Tokens t);      // CYCL CALL [POS | PAT]
    // Runs the cycle where the tool stands, its surface shifted by `surface_shift` along the
    // tool axis; `end_height`: where it ends instead of its own end (a pattern's traverse height).
    void call_cycle(int column, double surface_shift = 0, std::optional<double> end_height = std::nullopt);
    // A cycle's moves count as blocks (ControlProfile::block_limit), as ISO canned cycles'
    // repeats do: `moves` more, or the run stops with block_limit.
    void count_moves(std::size_t moves, int column);
    [[noreturn]] void block_limit_exceeded(int column) const;
    void straight_to(const Vec3& e, double feed);   // mm/min (+inf: FMAX), R0
    void axis_move(double to, double feed);         // along the tool axis, mm/min (+inf: FMAX)
    void plane_move(const Vec2& to, double feed);   // in the working plane, R0
    void bore_milling(const cycles::tnc::BoreMilling& b, std::optional<double> end_height);
    const CycleDef& machining_cycle(int column, const std::string& caller) const;  // a 2xx cycle defined
    double call_feed(Tokens t, std::size_t from);  // F / FMAX (and M) of CYCL CALL POS / PAT
    void call_at_position(Tokens t);
    void call_pattern(Tokens t);
    void pattern_def(Tokens t);
    void pattern_item(const Token& head, Tokens values);
    void pattern_cycle(Tokens t, int number);  // CYCL DEF 220 / 221
    struct PatternPoint {
        Vec2 at;       // in the working plane, from the preset
        double z = 0;  // shifts the cycle's surface
    };
    std::vector<PatternPoint> pattern_;  // PATTERN DEF
    bool cycle_call_pending_ = false;  // M99 / M89 in this block: the cycle runs after its move
    bool modal_call_ = false;          // M89: after every positioning block, until M99 / CYCL CALL / CYCL DEF
    bool shortest_rotary_ = false;     // M126: rotary axes take the shorter way
    double speed_ = 0;                 // S, rev/min (TOOL CALL, or a block's S)
    void cycle(Tokens t);           // CYCL DEF / CYCL CALL
    void dwell(Tokens t);           // CYCL DEF 9 DWELL TIME
    // The block's tokens with Q parameters in words replaced by values (in `scratch` when
    // there are any, else `t` itself).
    Tokens resolve(Tokens t, std::vector<Token>& scratch) const;
    bool execute(Tokens t);  // false at END PGM
    // Runs the blocks of one program (the main program, or one called with CALL PGM at
    // nesting depth `depth`) with its own labels; false when the run ends (M2/M30 seen).
    bool run_blocks(const Program& p, int depth);
    PieceHooks pieces_;
    int file_index(const std::string& name);  // Path::files index, told to pieces_.file_opened when new
    // CALL PGM name: the program is looked up in the search path only and run inline.
    void call_program(Tokens t, int depth);
    std::string find_program(const std::string& name, int column) const;
    [[noreturn]] void fail(const char* code, const std::string& msg, int column = 0) const;

    // words
    const Token* find(Tokens t, std::string_view key) const;
    std::optional<double> number(Tokens t, std::string_view key) const;
    Vec3 end_point(Tokens t, std::size_t from) const;  // X Y Z with I-prefix increments
    void modal_words(Tokens t, std::size_t from);      // R0/RL/RR, F/FMAX, M functions
    void m_function(Tokens t, const Token& k);  // an M word of a positioning block
    // M91 / M92 in an L block: its absolute coordinates are the spindle's (no tool length)
    // from the machine's zero / the additional machine datum; `end` in program coordinates.
    void machine_datum_end(Tokens t, Vec3& end) const;
    void to_tool_change_position();  // the machine's tool change position, before TOOL CALL
    void refuse_words(Tokens t, std::initializer_list<std::string_view> names, const char* why,
                      std::size_t from = 1) const;
    void refuse_plane_axes(Tokens t, const char* why, std::size_t from = 1) const;
    void approach_words(Tokens t, ApproachKind kind, bool polar);              // F and M of an APPR / DEP block

    // blocks
    void tool_def(Tokens t);
    void tool_call(Tokens t);
    void line(Tokens t);
    void circle_centre(Tokens t);
    void arc_about_pole(Tokens t);
    void arc_radius(Tokens t);
    void arc_tangential(Tokens t, bool polar = false);  // CT, CTP
    void polar_line(Tokens t);
    Vec3 polar_end(Tokens t) const;  // PR/IPR, PA/IPA about the pole, the tool axis from Z words
    void polar_arc(Tokens t);
    void corner_feed(Tokens t);  // the modal words of RND / CHF, their F for the corner only
    void rounding(Tokens t);
    void chamfer(Tokens t);
    double q_value(int n, int column) const;  // a Q parameter read (refused where it is the control's)
    void check_q(int n, int column) const;     // Q0-Q1999
    void surface_line(Tokens t);  // LN
    // LN's tool orientation TX TY TZ as the block is written: numbers, never Q parameters.
    void check_surface_line(Tokens raw) const;
    void approach(Tokens t);
    void departure(Tokens t);
    void emit_approach(const Motion& first);  // once the first contour element is known
    // APPR while RL/RR is active: the approach path computed on the contour (radius 0) and
    // put as compensated contour elements, before `first`.
    void emit_connecting_approach(const Motion& first);
    // `depth_after`: the piece after which the tool axis goes to `h`, or kDepthWithFirst: the
    // first piece (PS -> PH) goes there itself, in all three axes.
    static constexpr std::size_t kDepthWithFirst = static_cast<std::size_t>(-1);
    void emit_pieces(const std::vector<PathPiece>& pieces, double h, double feed_first, double feed_rest,
                     std::size_t depth_after);
    void put_contour_pieces(const std::vector<PathPiece>& pieces, const Vec3& from, double h, double feed_first,
                            double feed_rest, std::size_t depth_after);
    ApproachOptions approach_options() const {
        return {profile_.radius.ct_radius_on_contour, profile_.radius.lct_tangency_tool_space};
    }

    // motion output, one element held back for RND/CHF
    Motion motion_to(MotionKind kind, const Vec3& end) const;
    void put(Motion m);
    void settle_pending();
    Vec2 plane2(const Vec3& v) const { return in_plane(v, plane_); }
    Vec3 with_plane(const Vec3& v, const Vec2& ab) const;
    Vec2 end_tangent() const;  // direction at the end of the last element
    Element2 plane_element(const Motion& m) const;  // the move in the working plane

    const Program& prog_;
    const SearchPath search_;  // directories for CALL PGM, and the limits of the files read
    const Machine* machine_ = nullptr;  // the machine, if any
    Vec3 work_origin_ = Vec3::Zero();   // the machine's work origin (the preset), program units
    std::map<std::string, std::shared_ptr<const Program>> called_;  // parsed called programs, by file
    std::size_t executed_ = 0;  // blocks executed, called programs included (block limit)
    std::size_t moves_ = 0;     // moves put (put(), put_contour_pieces())
    IdleWatch idle_;            // blocks in a row without a move
    const ToolTable* tools_;
    const ControlProfile& profile_;
    FrameSink sink_;
    std::vector<Diagnostic>& diags_;

    int line_ = 0;
    int file_ = 0;        // Path::files index of the program whose blocks run
    SourceFiles files_;
    double dwell_seconds_ = 0;  // CYCL DEF 9, seconds
    double unit_ = 1.0;  // mm per program unit
    Plane plane_ = Plane::xy;
    Vec3 pos_ = Vec3::Zero();
    std::array<double, 3> abc_{0, 0, 0};
    std::optional<Vec2> pole_;
    Plane pole_plane_ = Plane::xy;  // the plane of the axes CC named (CC X.. Z..: ZX)
    // While a block moves about a pole outside the working plane: the working plane (the tool
    // axis), plane_ being the pole's for that block (PolePlane in contour.cpp).
    std::optional<Plane> working_plane_;
    friend class PolePlane;
    void refuse_other_plane(Tokens t) const;  // RND / CHF / CT next to an element in another plane
    void retract(Tokens t);     // M140 MB (interp_machine.cpp)
    bool axis_called_ = false;  // a TOOL CALL gave the tool axis
    void sysread(const Token& statement);  // FN 18: SYSREAD (interp_sysread.cpp)
    double system_datum(int id, int nr, int idx, int column) const;
    double feed_ = 0;  // mm/min
    bool rapid_ = false;
    int side_ = 0;     // 0 R0, +1 RL, -1 RR
    bool comp_started_ = false;
    int tool_ = 0;
    double radius_ = 0;  // effective tool radius, program units
    Vec3 tlo_ = Vec3::Zero();
    std::map<int, ToolDef> defs_;
    bool m97_ = false;         // M97 in this block
    bool open_corner_ = false; // M98 in this block
    int lookahead_ = 0;        // M120 LA n, modal until R0
    bool m128_ = false;        // M128: tool orientation follows the program (TCPM)
    bool m107_ = false;        // M107: positive deltas allowed with 3D compensation
    double sum_dr_ = 0, sum_dr2_ = 0;  // ΣDR, ΣDR2 of the called tool (TOOL CALL + table)
    double call_dl_ = 0, call_dr_ = 0, call_dr2_ = 0;  // the deltas of the last TOOL CALL block
    bool warned_normal_ = false;
    bool ended_ = false;               // M2 / M30
    std::map<int, double> q_;          // Q parameters (unset read as 0)
    std::map<int, double> control_q_;  // Q100-Q199 the control has set (Q120-Q122: the untilted plane)
    int paraxial_ = 0;  // R+ (+1) / R- (-1) in the current L block
    std::optional<Motion> pending_;
    double pending_round_ = 0, pending_chamfer_ = 0;  // RND / CHF between pending_ and the next
    int pending_corner_line_ = 0;
    double pending_corner_feed_ = 0;  // the feed of the rounding or chamfer (its own F, else the contour's)
    int plane_moves_ = 0;  // positioning blocks in the plane (CT needs two)
    bool last_rapid_ = false;  // the last positioning block was FMAX
    struct PendingApproach {
        Approach a;
        Vec3 ps = Vec3::Zero();  // where the tool is (tool centre)
        double depth = 0;        // tool-axis coordinate of the APPR block
        bool depth_with_lead = false;  // APPR LCT with X, Y and Z: PS -> PH in all three axes
        double feed_lead = 0, feed_arc = 0;
        int line = 0;
        bool connecting = false;  // compensation was already active: a connecting element
    };
    std::optional<PendingApproach> approach_;
};

}  // namespace toolcomp::heidenhain
