#pragma once
// The ISO interpreter's working data (modal state, positions, offsets) and its operations.
// Private to the ISO front end; the entry point is toolcomp::iso::interpret().
//
// Positions are kept as LinuxCNC keeps them: program coordinates in the current program
// units (X Y Z; converted when G20/G21 changes them) and degrees (A B C), with
// machine = program + G92 + G5x + tool length offset. Moves leave in millimetres.
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <type_traits>
#include <string>
#include <vector>

#include "../../control/travel.hpp"
#include "../../cycles/profile_cycles.hpp"
#include "../../cycles/turning_roughing.hpp"
#include "../idle_watch.hpp"
#include "block_words.hpp"
#include "flow.hpp"
#include "modal_snapshot.hpp"
#include "params.hpp"
#include "toolcomp/dialects/iso/interpreter.hpp"
#include "toolcomp/program/expr.hpp"

namespace toolcomp::iso {

using Vec6 = Eigen::Matrix<double, 6, 1>;  // X Y Z (mm) A B C (deg)

struct ModalState {
    int motion = 800;  // G80: axis words need a motion code first (LinuxCNC starts so)
    Plane plane = Plane::xy;
    bool incremental = false;   // G91
    bool arc_absolute = false;  // G90.1
    int feed_mode = 940;        // G93 / G94 / G95
    bool inch = false;          // G20
    bool retract_initial = false;  // G98 (true) / G99 (false); LinuxCNC starts in G99
    int coord_system = 1;       // 1..9 = G54..G59.3
    bool diameter = false;      // G7
    int length_mode = 490;      // G43 / G43.1 / G43.2 / G44 / G49
    int path_control = 640;
};

// The machine's switches a program can read back (LinuxCNC #<_mist>, #<_flood>,
// #<_feed_override>, ...): coolant M7/M8/M9, overrides M48/M49, M50-M53 with P0 (off) or P1.
struct MachineSwitches {
    bool mist = false, flood = false;
    bool feed_override = true, speed_override = true, adaptive_feed = false, feed_hold = true;
    void update(const BlockWords& bw);
};

// Values that stick from one canned-cycle block to the next while the cycle continues.
struct CycleMemory {
    double r = 0, z = 0, q = 0, p = 0;  // r, z, q as written (program units), p seconds
    double i = 0, j = 0, k = 0;          // G87: offsets of the back bore, K as written
};

// A program the run executes blocks of: the main program or a subprogram file.
struct LoadedProgram {
    const Program* prog = nullptr;
    FlowInfo flow;
    int file = 0;  // index into the run's files
};

// Where execution is: the main program, or a subprogram and where it returns to.
struct Frame {
    enum Kind : std::uint8_t { main, o_call, m98, g65, g70 } kind = main;
    const LoadedProgram* at = nullptr;
    std::size_t pc = 0;         // next block
    std::size_t entry = 0;      // first block of the body (M98 / G65 L repeats)
    std::size_t sub_block = FlowInfo::npos;  // LinuxCNC: the sub block of the running subroutine
    long repeats_left = 0;      // M98 / G65 L: passes still to run after this one
    long m98_loop = -1;         // LinuxCNC M98 L: passes still to run of the call on this level (-1: none)
    int call_line = 0;          // line of the calling block (in the caller's file)
    std::map<std::size_t, long> repeat_counts;  // o-repeat block -> passes left
    std::map<std::string, std::size_t> opened;  // LinuxCNC: if/while/repeat label -> its block, this call
    std::size_t stop = 0;         // G70: the block after the contour's last
    Vec6 back = Vec6::Zero();     // G70: where the tool goes at rapid after the contour
    ModalSnapshot saved;          // LinuxCNC M70 / M73 of this call level
    // A remap's sub: the rest of its block, run at the return, with the motion it read then.
    std::shared_ptr<const BlockWords> resume;
    int resume_motion = -1;
    const Program& prog() const { return *at->prog; }
};

class Interp : public expr::Env {
public:
    Interp(const Program& prog, const ToolTable* tools, const ControlProfile& profile,
           const InterpretOptions& opts, MotionSink& sink, std::vector<Diagnostic>& diags);
    void run();
    // expr::Env: named parameters, numbered parameters (interp_params.cpp)
    double get(const std::string& name, std::span<const double> indices) override;
    double param(double number) override;
    bool exists(const std::string& name) override;
    InterpretOutput output() const;
    // A dwell of P (seconds; milliseconds where G4 X is the seconds): added to the run's time.
    void dwell(double p) { dwell_seconds_ += std::max(0.0, profile_.dwell_x_seconds ? p / 1000 : p); }

private:
    // ---- block execution (interp.cpp) --------------------------------------------------
    // ---- one block, step by step in the control's order (interp_execute.cpp) ----------
    bool execute(const BlockWords& bw);  // false after M2/M30
    static constexpr int kBlockEnded = -2;
    int execute_head(const BlockWords& bw);  // its motion, or kBlockEnded
    bool execute_tail(const BlockWords& bw, int motion_to_be);
    static bool axes_are_data(const BlockWords& bw);
    void end_cycle_by_g80(const BlockWords& bw);
    int check_motion_words(const BlockWords& bw) const;  // the block's motion
    void check_axis_letters(const BlockWords& bw) const;
    void refuse_under_radius_comp(const BlockWords& bw);
    void refuse_m_codes_under_comp(const BlockWords& bw) const;
    void refuse_modes_under_comp(const BlockWords& bw, bool comp_before);
    void set_feed(const BlockWords& bw);
    void tool_change_codes(const BlockWords& bw);
    bool spindle_codes(const BlockWords& bw);  // true: an M72 restore ended the block
    void dwell_code(const BlockWords& bw);
    void set_modes(const BlockWords& bw);
    void set_path_control(const BlockWords& bw);
    void axis_data_codes(const BlockWords& bw);
    bool motion(const BlockWords& bw, int motion_to_be);  // false: a remapped motion's sub runs first
    bool move(const BlockWords& bw, int motion_to_be);
    bool stop_codes(const BlockWords& bw);  // false after M2/M30

    // ---- the block's words (interp.cpp) ---------------------------------------------------
    int motion_of(const BlockWords& bw) const;
    bool ended_ = false;  // the program ended in the rest of a remapped code's block
    void check_words(const BlockWords& bw, int motion_to_be);
    [[noreturn]] void fail(const char* code, const std::string& msg, int column = 0) const;
    // The file of the running block for messages: "" for the main program.
    std::string file_name() const { return file_ > 0 ? files_[static_cast<std::size_t>(file_)] : std::string(); }
    void info(const char* code, const std::string& msg, int column = 0);
    // One more block executed (every block read, and every repeat of a canned cycle after
    // its first): beyond ControlProfile::block_limit the run stops with "block_limit"
    // instead of running (and collecting moves) for hours.
    void count_block(int column = 0);
    [[noreturn]] void block_limit_exceeded(int column) const;
    // The blocks still allowed: what a cycle may make before it is stopped (cycles::MoveLimit).
    std::size_t block_budget() const { return profile_.block_limit - std::min(executed_, profile_.block_limit); }

    // ---- programs that compute (interp_flow.cpp) ----------------------------------------
    // Runs one block's control statement (O-word, Fanuc GOTO/WHILE/END); block index k.
    void control(const Statement& s, std::size_t k);
    // Evaluates an expression of the current program; math errors become ProgramErrors
    // with the control's message at `column`.
    double eval(std::int32_t e, int column);
    bool condition(std::int32_t e, int column) { return eval(e, column) != 0; }
    // The words of a block with their computed values (Fanuc: a word whose value is vacant
    // is left out); the block's own words when nothing is computed.
    std::span<const Word> block_words(const Block& b);
    void assignments(const Block& b);  // #n = ... of the block, all read first, then set
    bool declared_before(const std::string& name) const;
    void run_blocks();
    void set_param(double number, double v, int column);
    std::string substitute(const std::string& text);  // DEBUG / PRINT messages: #n, #<name> values
    void message_comment(const Comment& c);           // (MSG, ...), (DEBUG, ...), (PRINT, ...)
    void call_sub(const Statement& s);  // LinuxCNC o-call
    void call_o_sub(const std::string& label, const std::vector<double>& args, int column);
    void return_from_sub(const Statement& s);
    void subprogram(int mcode, const WordSlot& p, const WordSlot& l, int column);  // Fanuc M98 / M99
    void call_program(Frame::Kind kind, const WordSlot& p, const WordSlot& l, int column);
    void macro_call(std::span<const Word> words, int column);  // Fanuc G65 (the whole block)
    void push_frame(Frame f);
    [[noreturn]] void file_ended(const Program& p);
    [[noreturn]] void end_of_file(const Frame& f);  // a subprogram's file ends before its return  // an o-word structure the file does not close
    // A subprogram file on the search path (parsed once), or nullptr.
    const LoadedProgram* load(const std::string& file_name);
    const LoadedProgram* fanuc_program(long number);
    void goto_sequence(double n, int column);
    // System parameters (read from the interpreter's state), or nullptr / NaN when n is storage.
    bool system_param(int n, double& v) const;
    bool mode_param(const std::string& name, double& v) const;
    double parameter_number(double number, int column) const;
    static bool predefined(const std::string& name);  // LinuxCNC's read-only #<_x>, #<_value>, ...

    // ---- units and coordinates -----------------------------------------------------------
    double scale() const { return st_.inch ? kMmPerInch : 1.0; }
    int unit_index() const { return st_.inch ? 1 : 0; }
    // Axis words of `bw` as an absolute program position (G90/G91, G7); the current value
    // where a word is absent.
    Vec6 find_end(const BlockWords& bw) const;
    double axis_value(const BlockWords& bw, int axis) const;  // word value (G7 halves X)
    // machine = rotate(program + G92) + G5x + tool length offset; the rotation (G10 L2 R)
    // turns X/Y about the origin of the active coordinate system.
    Vec6 to_machine(const Vec6& prog) const;
    Vec6 from_machine(const Vec6& machine) const;

    // ---- motion (interp_motion.cpp) --------------------------------------------------------
    Motion motion_to(MotionKind kind, const Vec6& end) const;
    void straight(MotionKind kind, const Vec6& end, double feed);
    void emit(const Motion& m);  // a move out, the position at its end
    MotionSink& out() { return capture_ ? *capture_ : sink_; }
    Vec2 center_from_radius_lcnc(const Vec2& s, const Vec2& e, double R, int dir) const;
    void set_units(bool inch);
    void motion_line(const BlockWords& bw, int code, bool machine_coords);
    void motion_arc(const BlockWords& bw, int code);
    void check_arc_ends(const Vec2& s, const Vec2& c, const Vec2& e, char a_l, char b_l) const;
    void check_feed_per_rev(int column) const;
    // `x_end`: the X (radius) where the move ends, for the spindle speed of G96.
    double feed_for(const BlockWords& bw, int code, double length, double x_end) const;

    // ---- offsets (interp_offsets.cpp) ------------------------------------------------------
    void set_coord_system(int n);
    void g10(const BlockWords& bw);
    void g92(const BlockWords& bw, int code);
    void g50(const BlockWords& bw);  // G-code system A: G50 X Z (as G92), G50 S (spindle clamp)
    // ---- the machine (interp_machine.cpp) -----------------------------------------------
    void place_machine(const Machine& m, const ParameterValues& values);
    void machine_subprogram(const BlockWords& bw);  // a builder M code that runs a program
    void remap_call(const MachineCode& c, const BlockWords& bw, const std::string& code_name, int column);
    bool remapped_motion(const BlockWords& bw);  // false: the block's stop waits for the sub
    void to_tool_change_position(int column);  // M6 on a machine with a tool change position
    void check_travel(const Motion& m);         // the machine's travel limits (travel_limit)
    // mm of the machine file per program unit of axis i: a lathe's machine X is a diameter.
    double machine_scale(int i) const { return scale() * (i == 0 && st_.diameter ? 2.0 : 1.0); }
    void home(const BlockWords& bw, int code);  // G28 / G30 and G28.1 / G30.1
    // Sets an offset (or rotation) while the machine stays still: the program coordinates
    // of the current point change instead.
    template <class T>
    void change_offset(T& offset, const std::type_identity_t<T>& value) {
        Vec6 m = to_machine(pos_);
        offset = value;
        pos_ = from_machine(m);
    }

    // ---- tools (interp_tools.cpp) ------------------------------------------------------------
    void select_tool(const BlockWords& bw);
    void change_tool(const BlockWords& bw, int mcode);
    void length_comp(const BlockWords& bw, int code);
    Vec6 tool_offset_of(int tool, int column) const;
    struct OffsetValues {
        Vec6 length = Vec6::Zero();  // program units
        double radius = 0;           // program units
        int orientation = 0;
    };
    OffsetValues offset_values() const;

    // ---- cutter radius compensation request (interp_radius.cpp) ----------------------------
    void radius_comp(const BlockWords& bw, int code);
    void modal_d_number(const BlockWords& bw);  // D without G41/G42 (ControlProfile::d_word_alone)
    void set_radius_from_offset();
    // LinuxCNC's rule after G40: the next G0/G1 must come before any arc; moves of G28/G30 and
    // canned cycles do not count (the stage alone would take them as straight moves).
    bool arc_not_allowed_ = false;
    bool comp_moved_ = false;  // a move made since compensation came on (else G40 sets no rule)
    std::size_t moves_ = 0;    // moves given to the sink (a block that adds none moves nothing)
    int last_h_ = 0, last_d_ = 0;  // the modal H and D numbers (ControlProfile::modal_offset_numbers)
    bool warned_blending_ = false;  // G64's info given
    bool comp_on() const { return radius_.side != 0; }
    void system_a_codes(const BlockWords& bw) const;  // Fanuc lathes: G90/G92/G94 are cycles
    void load_parameters(const ParameterValues& values);  // start values, the machine's state among them
    void fanuc_dwell(BlockWords& bw) const;           // G04 X / U: the dwell, not a move
    void inverse_time_rate(double feed);

    // ---- LinuxCNC M70-M73 (interp_modal_state.cpp) ---------------------------------------------
    ModalSnapshot snapshot() const;
    bool modal_state(const BlockWords& bw);  // true: an M72 restore ran, the block ends there
    bool restore_modal(const ModalSnapshot& saved, int column);  // true: it ran G-code
    void run_restore_text(const std::string& text, int column);
    void restore_on_return(const ModalSnapshot& saved, int call_line);  // M73's, at a subroutine's return
    double tolerance_ = 0, naivecam_ = 0;  // LinuxCNC G64 P and Q, as given

    // ---- LinuxCNC's splines G5, G5.1, G5.2 / G5.3 (interp_splines.cpp) ---------------------
    void spline(const BlockWords& bw, int code);  // G5, G5.1
    void nurbs_point(const BlockWords& bw);       // G5.2
    void nurbs_end(const BlockWords& bw);         // G5.3
    void nurbs_feed(const std::vector<std::array<double, 3>>& points, unsigned order, int col);
    void spline_arc(const Vec2& from, const Vec2& to, const Vec2& d);
    std::vector<std::array<double, 3>> nurbs_points_;  // G5.2: X Y weight (program units)
    unsigned nurbs_order_ = 3;

    // ---- LinuxCNC's straight probe G38.2-G38.5 (interp_probe.cpp) -------------------------
    void probe(const BlockWords& bw, int code);
    std::size_t probes_used_ = 0;             // probe moves so far (the next takes opts_.probes[this])
    std::array<double, 10> probe_values_{};   // #5061-#5070 after a probe
    bool probed_ = false;
    double dwell_seconds_ = 0;  // G4 and the cycles' dwells, seconds
    bool debug_output_ = true;  // LinuxCNC #5599: (DEBUG, ...) shown

    // ---- LinuxCNC's spindle-synchronised motion (interp_spindle_sync.cpp) ------------------
    void sync_line(const BlockWords& bw);       // G33
    void rigid_tap(const BlockWords& bw);       // G33.1
    void lcnc_threading(const BlockWords& bw);  // G76
    void sync_can_start(const BlockWords& bw, const char* what) const;
    void spindle_choice(const BlockWords& bw, int motion_to_be) const;  // $
    double sync_feed(double lead, double x_end) const;  // lead (program units) per rev: mm/min
    bool diameter_switched_ = false;  // this block's G7 / G8 changed the mode

    void io_code(const BlockWords& bw);  // M62-M68 (interp_io.cpp)
    void g10_tool(const BlockWords& bw, int l);  // G10 L1 / L10 / L11 (interp_tool_table.cpp)
    void polar_end(const BlockWords& bw, Vec6& end) const;  // @ ^ (interp_motion.cpp)
    void polar_checks(const BlockWords& bw) const;

    // ---- LinuxCNC's lathe profile cycles G70, G71, G72 (interp_profile_cycles.cpp) ------------
    void profile_cycle(const BlockWords& bw, int code);
    std::vector<cycles::profile::Piece> read_profile(const BlockWords& bw, cycles::profile::Point start, int& mode);
    void read_profile_blocks(std::size_t depth, int& mode, cycles::profile::Point& at,
                             std::vector<cycles::profile::Piece>& pieces);
    void profile_piece(const BlockWords& w, int& mode, cycles::profile::Point& at,
                       std::vector<cycles::profile::Piece>& pieces) const;

    // ---- canned cycles (interp_cycles.cpp) ---------------------------------------------------
    void cycle(const BlockWords& bw, int code);

    // ---- lathe cycles: G70, G71, G72 (interp_turning.cpp) -------------------------------------
    void roughing_cycle(const BlockWords& bw, int code);
    // G-code system A's single cycles and threading (interp_lathe_single.cpp).
    void thread_line(const BlockWords& bw);                 // G32
    void single_cycle(const BlockWords& bw, int code);      // G90, G92, G94
    double thread_feed(double x_end) const;                 // F as the lead: mm/min at X (radius)
    void threading_cycle(const BlockWords& bw);             // G76 (interp_threading.cpp)
    // A lathe cycle's P or Q written in least input increments: its whole number (0 when the
    // block has none), refused (PS0062) unless whole and 0 or more; one increment in program units.
    double whole_count(const BlockWords& bw, char c, const char* cycle) const;
    double least_increment() const { return st_.inch ? 1e-4 : 1e-3; }
    double spindle_rpm(double x_end) const;  // S, or under G96 the speed at X (radius), clamped
    struct Threading {
        int finishing = 1, chamfer = 0, angle = 60;  // G76 P(m)(r)(a)
        double min_depth = 0, allowance = 0;         // Q(Δdmin), R(d), program units
    } thread_{};
    bool thread_chamfer_on_ = true;  // Haas M23 / M24: the profile's thread chamfer is cut
    // One G76 (either form): the depth of each pass, cut from the start point A to `end`
    // (the thread's root at its end), taper (radius, the start's minus the end's), the flank
    // angle of the infeed (degrees), the pull-out chamfer's length along Z and its angle.
    struct ThreadPasses {
        std::vector<double> depths;
        double height = 0, taper = 0, angle = 0, chamfer = 0, chamfer_angle = 45;
        Vec6 end = Vec6::Zero();
    };
    void thread_passes(const ThreadPasses& t, int col);
    void haas_threading(const BlockWords& bw, int col);     // G76 X Z K D A I F (one block)
    double thread_chamfer_length(double lead) const;        // the profile's chamfer when on
    std::vector<double> thread_depths(double first, double least, double rough_to, int col) const;
    void thread_cycle_can_start(int col) const;
    void thread_cut(const Vec6& s, const Vec6& e, double chamfer, double angle, double out);
    struct SingleCycle {
        double z = 0, x = 0, r = 0;  // the last cycle's end Z, X and taper R (program units)
    } single_{};
    void finishing_cycle(const BlockWords& bw);
    void pattern_cycle(const BlockWords& bw);              // G73
    BlockWords first_block(std::size_t from, int col);     // the P block of G71-G73 (G00/G01)
    void contour_cycle_can_start(const char* name, int col) const;
    int pass_count(const BlockWords& bw, char c) const;    // G73 R / D
    static Vec2 turning_uv(const Vec3& q, bool along_z);
    cycles::Contour cycle_contour(std::size_t from, std::size_t to, bool along_z, RadiusRequest* nose = nullptr);
    Vec2 nose_allowance(const RadiusRequest& nose, const cycles::Contour& contour, const Vec2& start, bool g71) const;
    void emit_steps(const std::vector<cycles::Step>& steps, bool along_z, const BlockWords& bw, int col);
    void peck_cycle(const BlockWords& bw, int code);       // G74, G75 (interp_grooving.cpp)
    struct PatternRepeat {
        double relief_x = 0, relief_z = 0;  // G73 U(Δi) W(Δk), program units (X a radius)
        int divisions = 1;                  // G73 R(d)
    } pattern_{};
    double peck_return_ = -1;  // G74 / G75 R(e), program units; -1: not given
    // The blocks N<p> .. N<q> of the running program (their indexes), for G70-G73.
    std::pair<std::size_t, std::size_t> contour_blocks(const BlockWords& bw);
    // The moves of blocks [from, to] as they would run from here, nothing else changed: where
    // the first block ends, and the moves of the others.
    struct ContourMoves {
        Vec3 first_end = Vec3::Zero();
        std::vector<Motion> moves;
        RadiusRequest nose;  // the first G41/G42 in the contour (side 0: none)
    };
    ContourMoves read_contour(std::size_t from, std::size_t to);
    MotionSink* capture_ = nullptr;  // while a contour is read: where its moves go
    double turn_depth_ = 0, turn_escape_ = -1;  // G71 U R / G72 W R (program units; -1: not given)

    const Program& prog_;  // the main program
    const ToolTable* tools_;                  // the caller's table, or edited_tools_ after a G10 L1
    std::optional<ToolTable> edited_tools_;  // the run's copy, made at the first G10 L1
    const ControlProfile& profile_;
    InterpretOptions opts_;
    MotionSink& sink_;
    std::vector<Diagnostic>& diags_;

    int line_ = 0;  // current block's source line
    std::size_t executed_ = 0;  // blocks executed, cycle repeats included (count_block)
    IdleWatch idle_;            // blocks in a row without a move (count_block)
    std::optional<TravelCheck> travel_;  // the machine's travel limits, when it has any
    ModalState st_;
    Vec6 pos_ = Vec6::Zero();
    std::array<Vec6, 9> g5x_;
    std::array<double, 9> rotation_{};  // XY rotation of each coordinate system, degrees
    Vec6 g92_ = Vec6::Zero(), g92_saved_ = Vec6::Zero();  // in force; kept (#5211-#5219)
    bool g92_on_ = false;                                 // #5210
    Vec6 tlo_ = Vec6::Zero();
    Vec6 g28_ = Vec6::Zero(), g30_ = Vec6::Zero();  // machine coordinates
    double feed_ = 0;   // mm/min (G94), mm/rev (G95) or 1/min (G93), as last programmed
    // The spindles (LinuxCNC: up to 8, chosen with $; the machine's count), and the one G95
    // feeds follow and G33/G76 synchronise with (LinuxCNC: $ with G93-G97, G33, G76; else 0).
    struct Spindle {
        double speed = 0;    // S, rev/min (G96: surface speed, m/min or ft/min)
        bool css = false;    // G96 constant surface speed
        double css_max = 0;  // G96 D: the spindle speed it may not exceed (0: none given)
        int turning = 0;     // 0 stopped, 1 clockwise, -1 counter-clockwise
    };
    std::array<Spindle, Machine::kMaxSpindles> spindles_{};
    int active_spindle_ = 0;
    Spindle& spindle() { return spindles_[static_cast<std::size_t>(active_spindle_)]; }
    const Spindle& spindle() const { return spindles_[static_cast<std::size_t>(active_spindle_)]; }
    int spindle_count() const { return opts_.machine ? opts_.machine->spindles : 1; }
    void spindle_words(const BlockWords& bw);  // S, G96/G97, G93-G95 with $ (interp_spindle_sync.cpp)
    void spindle_turn(const BlockWords& bw, int code);  // M3, M4, M5, M19 with $
    double spindle_clamp_ = 0;  // G50 S (G-code system A): the highest speed under G96 (0: none)
    int tool_ = 0;      // tool in the spindle
    int block_tool_ = 0;  // and before the block being executed
    // The tool G41/G42 without D and G43 without H (or H0) take: the one in the spindle, or
    // with ControlProfile::tool_change_after_block the one before this block's M6/M61.
    int spindle_tool() const { return profile_.tool_change_after_block ? block_tool_ : tool_; }
    int selected_ = -1; // tool prepared by T
    int geometry_offset_ = 0, wear_offset_ = 0;  // lathes with T offsets: the active numbers
    bool checks_ = true;  // gouge checks on (9/Series M801) or off (M800)
    CycleMemory cyc_;
    int prev_motion_ = 800;      // motion mode before the current block
    int plain_motion_ = 0;       // the last G0/G1/G2/G3 mode (G80 of group 09 returns to it)
    double cycle_il_ = 0;        // initial level of the running canned cycle
    bool cycle_il_set_ = false;
    MachineSwitches machine_;    // coolant and overrides
    RadiusRequest radius_;       // cutter radius compensation carried on every move (side 0 = off)

    // ---- programs that compute -------------------------------------------------------------
    ParameterStore params_;
    const expr::Syntax* syntax_ = nullptr;  // null for dialects without parameters
    LoadedProgram main_;
    std::deque<LoadedProgram> loaded_;               // subprogram files read from the search path
    std::deque<Program> loaded_programs_;
    std::map<std::string, const LoadedProgram*> by_file_;
    std::vector<std::string> files_;                 // main program first
    std::vector<Frame> frames_;
    const Block* block_ = nullptr;  // the block being executed
    int eval_column_ = 0;           // column of the value being evaluated
    int file_ = 0;                                   // file of the running block
    std::vector<Word> scratch_words_;
    std::vector<double> scratch_values_;
    std::string alarm_text_;                         // Fanuc #3000: the comment of the block
    std::set<std::pair<const LoadedProgram*, std::size_t>> recorded_subs_;  // definitions passed or called
    std::map<std::string, std::pair<const LoadedProgram*, std::size_t>> numbered_found_;  // LinuxCNC O<n> found by M98
    void enter_sub(Frame::Kind kind, const LoadedProgram* where, std::size_t block);
    void numbered_call(std::size_t k);    // LinuxCNC M98 (interp_numbered.cpp)
    void numbered_return(std::size_t k);  // LinuxCNC M99 in a subprogram
    bool value_returned_ = false;
    double value_ = 0;                               // #<_value>: what the last return gave
};

}  // namespace toolcomp::iso
