#pragma once
// The Motion stream: the control-independent output of every interpreter.
//
// One Motion is one canonical move (rapid, line, arc/helix) in program coordinates (before
// work offsets, the way LinuxCNC's interpreter reports them) and in the program's units, as
// the control computes: `unit` is millimetres per program unit (25.4 in a G20 program). The
// Path converts to millimetres. A Motion carries the state the compensation stages need: the
// active tool, the tool length offset vector and the cutter radius compensation request.
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

#include "toolcomp/compensation/radius_styles.hpp"
#include "toolcomp/geometry/arc.hpp"
#include "toolcomp/geometry/vec.hpp"

namespace toolcomp {

enum class MotionKind : std::uint8_t { rapid = 0, line = 1, arc_cw = 2, arc_ccw = 3 };

// Cutter radius compensation requested for a move (carried, applied by a later stage).
struct RadiusRequest {
    std::int8_t side = 0;     // 0 off, +1 left (G41), -1 right (G42)
    double radius = 0;        // program units
    std::int8_t orientation = 0;  // lathe tip number, 0 = none
    bool checks = true;           // gouge and interference checks on (9/Series M800 turns them off)
    // Block-local (Heidenhain M97 / M98 / M120): the outside corner after this move met at
    // the intersection of the equidistants whatever its angle (M97), an open contour corner
    // after it (M98), a look-ahead that skips what the tool cannot reach (M120).
    bool corner_at_intersection = false;
    bool open_corner = false;
    std::int8_t lookahead = 0;
    // Modal choices a program switches (Sinumerik NORM/KONT, G450/G451, DISC, CDON/CDOF);
    // none: the profile's. `entry` is read on the activation move, `exit` on the last
    // compensated move, the others at the corner before this move.
    std::optional<EntryStyle> entry;
    std::optional<ExitStyle> exit;
    std::optional<OutsideCorner> outside;
    std::optional<GougeReaction> gouge;
    std::optional<float> disc;  // DISC 0..100
};

// 3D compensation requested for a move (Heidenhain LN): the surface normal at its end and
// the summed deltas of the tool (ΔR = ΣDR, ΔR2 = ΣDR2), program units.
struct SurfaceRequest {
    Vec3 normal = Vec3::Constant(std::numeric_limits<double>::quiet_NaN());  // NaN: none
    double d_r = 0, d_r2 = 0;
    bool active() const { return !std::isnan(normal.x()); }
};

struct Motion {
    MotionKind kind = MotionKind::line;
    Plane plane = Plane::xy;
    Vec3 start = Vec3::Zero(), end = Vec3::Zero();
    Vec3 center = Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
    std::int32_t turns = 0;  // arcs: extra full turns
    std::array<double, 3> abc{0, 0, 0};  // rotary axes at the end, degrees
    double feed = std::numeric_limits<double>::quiet_NaN();  // mm/min, NaN for rapids
    std::int32_t line = 0;
    std::int32_t file = 0;  // which file the block is in (Path::files)
    std::int32_t tool = 0;
    Vec3 tool_offset = Vec3::Zero();
    // Where the work coordinates lie in the machine's: machine = Rz(work_rotation) * end +
    // work_offset + tool_offset (the rotation in degrees about Z, LinuxCNC's G10 L2 R).
    Vec3 work_offset = Vec3::Zero();
    double work_rotation = 0;
    RadiusRequest radius;
    SurfaceRequest surface;
    Vec3 tool_axis = Vec3(0, 0, 1);  // unit vector from the tip towards the spindle
    bool generated = false;  // inserted by a compensation stage
    double unit = 1.0;       // mm per program unit of all lengths above (feed is mm/min)

    bool inch() const { return unit != 1.0; }

    bool is_arc() const { return kind == MotionKind::arc_cw || kind == MotionKind::arc_ccw; }
    Arc arc() const { return {start, end, center, plane, kind == MotionKind::arc_ccw ? 1 : -1, turns}; }
};

// Points in the program where a compensation stage must settle what it holds back: the
// block that cancels radius compensation (G40), a program stop (M0/M1/M60) and the program
// end (M2/M30). Errors found there are reported at that block's line. `no_motion`: a block
// that moves nothing (M8, S500, G4, a frame) while radius compensation is on, which controls
// that count blocks without plane motion count too (RadiusRules::count_blocks_without_motion;
// interpreters send it only for such profiles).
enum class ControlKind : std::uint8_t { radius_off, stop, program_end, no_motion };
struct ControlEvent {
    ControlKind kind;
    std::int32_t line;
    // radius_off: a direction given in the cancel block (9/Series I/K): the last compensated
    // move ends as if the contour went on in this direction (program units, XYZ); zero = none.
    Vec3 direction = Vec3::Zero();
    std::int32_t file = 0;  // Motion::file of the block
};

// A consumer of the stream: compensation stages and the Path collector.
class MotionSink {
public:
    virtual ~MotionSink() = default;
    virtual void push(const Motion& m) = 0;
    virtual void control(const ControlEvent&) {}
    virtual void finish() {}
};

}  // namespace toolcomp
