#pragma once
// The ISO interpreter's working data (modal state, positions, offsets) and its operations.
// Private to the ISO front end; the entry point is toolcomp::iso::interpret().
//
// Positions are kept as LinuxCNC keeps them: program coordinates in the current program
// units (X Y Z; converted when G20/G21 changes them) and degrees (A B C), with
// machine = program + G92 + G5x + tool length offset. Moves leave in millimetres.
#include <Eigen/Core>
#include <array>
#include <type_traits>
#include <string>
#include <vector>

#include "block_words.hpp"
#include "toolcomp/dialects/iso/interpreter.hpp"

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

// Values that stick from one canned-cycle block to the next while the cycle continues.
struct CycleMemory {
    double r = 0, z = 0, q = 0, p = 0;  // r, z, q as written (program units), p seconds
    double i = 0, j = 0, k = 0;          // G87: offsets of the back bore, K as written
};

class Interp {
public:
    Interp(const Program& prog, const ToolTable* tools, const ControlProfile& profile,
           const InterpretOptions& opts, MotionSink& sink, std::vector<Diagnostic>& diags);
    void run();

private:
    // ---- block execution (interp.cpp) --------------------------------------------------
    bool execute(const BlockWords& bw);  // false after M2/M30
    void check_words(const BlockWords& bw, int motion_to_be);
    [[noreturn]] void fail(const char* code, const std::string& msg, int column = 0) const;
    void info(const char* code, const std::string& msg, int column = 0);
    // One more block executed (every block read, and every repeat of a canned cycle after
    // its first): beyond ControlProfile::block_limit the run stops with "block_limit"
    // instead of running (and collecting moves) for hours.
    void count_block(int column = 0);

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
    Vec2 center_from_radius_lcnc(const Vec2& s, const Vec2& e, double R, int dir) const;
    void set_units(bool inch);
    void motion_line(const BlockWords& bw, int code, bool machine_coords);
    void motion_arc(const BlockWords& bw, int code);
    double feed_for(const BlockWords& bw, int code, double length) const;

    // ---- offsets (interp_offsets.cpp) ------------------------------------------------------
    void set_coord_system(int n);
    void g10(const BlockWords& bw);
    void g92(const BlockWords& bw, int code);
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
    void set_radius_from_offset();
    bool comp_on() const { return radius_.side != 0; }

    // ---- canned cycles (interp_cycles.cpp) ---------------------------------------------------
    void cycle(const BlockWords& bw, int code);

    const Program& prog_;
    const ToolTable* tools_;
    const ControlProfile& profile_;
    InterpretOptions opts_;
    MotionSink& sink_;
    std::vector<Diagnostic>& diags_;

    int line_ = 0;  // current block's source line
    std::size_t executed_ = 0;  // blocks executed, cycle repeats included (count_block)
    ModalState st_;
    Vec6 pos_ = Vec6::Zero();
    std::array<Vec6, 9> g5x_;
    std::array<double, 9> rotation_{};  // XY rotation of each coordinate system, degrees
    Vec6 g92_ = Vec6::Zero(), g92_saved_ = Vec6::Zero();
    Vec6 tlo_ = Vec6::Zero();
    Vec6 g28_ = Vec6::Zero(), g30_ = Vec6::Zero();  // machine coordinates
    double feed_ = 0;   // mm/min (G94), mm/rev (G95) or 1/min (G93), as last programmed
    double speed_ = 0;  // S, rev/min
    int tool_ = 0;      // tool in the spindle
    int selected_ = -1; // tool prepared by T
    int geometry_offset_ = 0, wear_offset_ = 0;  // lathes with T offsets: the active numbers
    bool checks_ = true;  // gouge checks on (9/Series M801) or off (M800)
    CycleMemory cyc_;
    int prev_motion_ = 800;      // motion mode before the current block
    double cycle_il_ = 0;        // initial level of the running canned cycle
    bool cycle_il_set_ = false;
    int spindle_ = 0;            // 0 stopped, 1 clockwise, -1 counter-clockwise
    RadiusRequest radius_;       // cutter radius compensation carried on every move (side 0 = off)
};

}  // namespace toolcomp::iso
