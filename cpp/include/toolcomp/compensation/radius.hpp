#pragma once
// Cutter radius compensation (G41/G42, G41.1/G42.1) as a stage of the Motion stream.
//
// The stage moves the tool centre to the side of the programmed contour. It holds back the
// last compensated plane move (and the moves without plane motion behind it) until the next
// plane move decides where it ends: at an outside (convex) corner a transition arc about the
// programmed corner is inserted (a straight traverse for rapids), at an inside (concave)
// corner the held move is pulled back to the intersection of the two compensated elements,
// joints turning by less than the profile's corner tolerance are taken as tangent. The entry
// move ends perpendicular to itself at its programmed end (an entry arc gets a new centre),
// the exit move runs uncompensated from the last compensated point. Pulled-back moves are
// checked for reversal (gouging). This is LinuxCNC's interpreter's algorithm, reproduced to
// its numbers and error messages; the profile holds what a control may choose differently.
//
// In G18 with a lathe tool (orientation 1..8) the emitted points are the imaginary tool tip:
// the nose centre shifted by ±r in X and Z per orientation (LinuxCNC numbering).
#include <optional>
#include <vector>

#include "toolcomp/compensation/background_watch.hpp"
#include "toolcomp/compensation/front_queue.hpp"
#include "toolcomp/control/profile.hpp"
#include "toolcomp/geometry/element.hpp"
#include "toolcomp/motion/motion.hpp"
#include "toolcomp/program/diagnostic.hpp"

namespace toolcomp {

class RadiusCompensation : public MotionSink {
public:
    // `threads`: the overcut watch may run on a thread of its own (else on the stage's).
    RadiusCompensation(const ControlProfile& profile, MotionSink& out, std::vector<Diagnostic>& diagnostics,
                       bool threads = true)
        : profile_(profile), out_(out), diags_(diagnostics), overcut_(threads) {}
    void push(const Motion& m) override;
    void control(const ControlEvent& e) override;
    void finish() override;
    // The overcut watch's warnings so far into the diagnostics (finish() does it; after an
    // error, the run does).
    void settle() { overcut_.settle(diags_); }

private:
    // A move held back until the next plane move settles its end point.
    struct Held {
        Motion m;            // end/centre in machine naming (X Y Z), nose-centre path
        Vec2 dir;            // straights: the direction the reversal check compares against
        double sweep = 0;    // arcs: programmed sweep (0 = never checked: corner and entry arcs)
        bool approach = false;  // the entry move (comes from off the contour: no overcut check)
        Held(const Motion& m_, const Vec2& dir_, double sweep_) : m(m_), dir(dir_), sweep(sweep_) {}
    };
    // An emitted move kept for the look-ahead before it leaves the stage.
    struct Emitted {
        Motion m;            // nose-centre path, start set
        Vec2 dir;
        double sweep = 0;
        bool in_plane = false;  // a programmed move with plane motion (not a corner fill)
        bool approach = false;
        std::size_t settled = 0;  // the overcut watch's programmed elements when it was emitted
        explicit Emitted(const Held& h) : m(h.m), dir(h.dir), sweep(h.sweep), approach(h.approach) {}
    };

    // joints and entry (radius.cpp, radius_joints.cpp)
    void entry_line(const Motion& m);
    void entry_arc(const Motion& m);
    void next_line(const Motion& m);
    void next_arc(const Motion& m);
    void hold_arc_and_advance(const Motion& m, const Vec2& e, const Vec2& centre, int turn, const Vec2& P,
                              const Vec2& p);
    std::optional<Element2> held_element() const;
    void outside_corner(const Motion& m, const Vec2& P, const Element2& next, double turn, bool check_held);
    // the outside corner's strategies (radius_joints.cpp)
    bool meet_at_intersection(const Motion& m, const Vec2& P, const Element2& held, const Element2& next);
    bool disc_fillet(const Motion& m, const Vec2& P, const Element2& held, const Element2& next);
    void extension_blocks(const Motion& m, const Element2& held, const Element2& next);
    void transition_arc(const Motion& m, const Vec2& P, const Vec2& mid);
    void hold_piece(Motion piece, const Vec2& at);
    bool close_open_entry(const Vec2& mid);
    bool open_corner(const Motion& m, const Vec2& mid);
    void turn_off(int line, bool cancel = true);
    void change_side(const Motion& m);
    // One more block without plane motion in a row: past the profile's limit its reaction (an
    // error, or the held moves end perpendicular with an overcut warning).
    void count_non_plane_block(int line);
    void bridge(const Element2& next, int line);
    void rescale(double new_unit);
    [[noreturn]] void fail(const char* code, const std::string& msg, int line) const;
    // The file (Motion::file) of the move of `line` the stage is given, else of the moves of
    // that line it holds; -1 when there is none or they are of several files.
    int file_of(int line) const;

    // held moves, gouge reactions and output (radius_output.cpp)
    Held& hold(const Motion& m, const Vec2& dir, double sweep);  // the held move, to be changed in place
    // Gives every held move the in-plane end x and emits them. A move that would run
    // backwards (or an arc that would sweep further) is a gouge, met by the profile's
    // reaction; `next` is the next element's equidistant, for skipping the unreachable move.
    void move_end_and_flush(const Vec2& x, int line, bool check = true, const Element2* next = nullptr);
    // An inside corner without an intersection: the reaction decides, as for gouges.
    void no_intersection(const Element2& next, int line, const std::string& msg);
    bool skip_unreachable(const Element2& next, int line);
    void flush();
    void emit(Held& h);
    void release(std::size_t keep_plane_moves);
    void send(Motion& m, bool approach, std::size_t settled);
    void passthrough(const Motion& m);
    void warn(const char* code, const std::string& msg, int line);
    void watch_programmed(const Element2& e, int line);
    void watch_released(const Motion& m, bool approach, std::size_t settled);

    Vec2 plane2(const Vec3& v) const { return in_plane(v, plane_); }
    Vec3 with_plane(const Vec3& v, const Vec2& ab) const;

    const ControlProfile& profile_;
    MotionSink& out_;
    std::vector<Diagnostic>& diags_;
    int non_plane_run_ = 0;  // blocks without plane motion since the last plane move

    double unit_ = 1.0;            // program unit (mm per unit) of everything held below
    bool checks_ = true;           // gouge checks of the current move (switchable on the 9/Series)
    int lookahead_ = 0;            // block-local look-ahead with skipping (Heidenhain M120 LA)
    // The profile's rules as the current move overrides them (RadiusRequest entry ... disc).
    EntryStyle entry_ = EntryStyle::perpendicular_to_entry;
    OutsideCorner outside_ = OutsideCorner::arc;
    GougeReaction gouge_ = GougeReaction::error;
    double disc_ = 0;
    GougeReaction reaction() const {
        if (lookahead_ > 0) return GougeReaction::skip;
        return checks_ ? gouge_ : GougeReaction::report;
    }
    int lookahead() const { return lookahead_ > 0 ? lookahead_ : profile_.radius.lookahead; }
    bool active_ = false;          // compensating, the entry move made
    Plane plane_ = Plane::xy;
    int side_ = 0;                 // +1 left, -1 right
    double r_ = 0;
    Vec3 program_ = Vec3::Zero();  // P: last programmed end point
    Vec3 current_ = Vec3::Zero();  // C: last compensated end point (nose/cutter centre)
    std::vector<Held> queue_;
    Vec2 endpoint_ = Vec2::Zero();  // start of the last held plane move
    bool endpoint_valid_ = false;
    bool arc_not_allowed_ = false;  // the move after G40 must be straight
    bool exit_pending_ = false;     // the next uncompensated move starts at the last compensated point
    bool entry_open_ = false;       // the entry block waits for the next element (type A entry)
    bool joint_free_ = false;       // the next element starts at C without a joint (side change)
    std::string bridge_lines_;      // lines of arcs left out, waiting for the next element
    bool exit_open_ = false;        // G40 seen, the cancel move settles the last joint (type B exit)
    std::int8_t exit_orientation_ = 0;
    bool exit_when_behind_ = false;  // KONT: the cancel move decides between the two exits
    int exit_line_ = 0;
    int in_line_ = 0, in_file_ = 0;  // the move or event being handed in
    BackgroundWatch overcut_;       // tool centre against the neighbouring programmed contour
    FrontQueue<Emitted> window_;    // emitted, not yet released (look-ahead for bottlenecks)
    bool have_last_ = false;
    Vec3 last_ = Vec3::Zero();      // end of the last emitted move (nose centre)
    Vec3 last_off_ = Vec3::Zero();  // and its tool length offset (a new offset moves the start)
    bool refused_ = false;          // a stage after this one refused a move (send() sends no more)
    bool have_out_ = false;
    Vec3 last_out_ = Vec3::Zero();  // end of the last released move (controlled point)
    Vec3 last_out_off_ = Vec3::Zero();
};

}  // namespace toolcomp
