#pragma once
// The machine's axis travel (Machine::travel), checked move by move by every interpreter
// that runs on a machine with limits. Each interpreter knows how its coordinates lie in the
// machine's (work offsets, frames, tool length, a lathe's diameter); it hands that over as
// a function, and this check finds the points of the move that bound it and the first bound
// they pass.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "toolcomp/control/machine.hpp"
#include "toolcomp/motion/motion.hpp"
#include "toolcomp/program/diagnostic.hpp"

namespace toolcomp {

class TravelCheck {
public:
    // The machine coordinates (mm, a lathe's X as a diameter) of a point of the interpreter's
    // output coordinates (the coordinates of Motion::start / end).
    using ToMachine = std::function<Vec3(const Vec3&)>;

    explicit TravelCheck(const Machine& m) : machine_(m) {}

    // The message of the first travel bound the move passes (at its end, or for an arc at an
    // extreme point of its circle that it passes), or nullopt. `rotation`: how far (radians)
    // the output's X and Y axes are turned about Z against the machine's.
    std::optional<std::string> beyond(const Motion& m, double rotation, const ToMachine& to_machine);

    // A move beyond the travel is an error that stops the run (the control's soft limit)
    // unless the machine file makes it a warning.
    bool stops() const { return !machine_.travel_limit_warning; }

    // The warning of a move beyond the travel at `at`: the first 100 one by one, then one info.
    void warn(const std::string& message, const SourcePos& at, std::vector<Diagnostic>& diags);

private:
    const Machine& machine_;
    std::size_t warnings_ = 0;
    std::vector<Vec3> points_;  // the bounding points of a move, kept from move to move
};

// The travel check on a stream of moves whose coordinates are the machine's, less the work
// origin (Machine::work_origin), with the tool length in Motion::tool_offset: the Sinumerik
// and Heidenhain interpreters put out their moves with their frames applied. The axes carry
// the spindle: a move's machine position is its end plus the tool offset. A move beyond the
// travel is ProgramError travel_limit at its block, or a warning (TravelCheck::stops).
class TravelSink final : public MotionSink {
public:
    TravelSink(const Machine& m, MotionSink& next, std::vector<Diagnostic>& diags)
        : check_(m), machine_(m), next_(next), diags_(diags) {}
    void push(const Motion& m) override;
    void control(const ControlEvent& e) override { next_.control(e); }
    void finish() override { next_.finish(); }

private:
    TravelCheck check_;
    const Machine& machine_;
    MotionSink& next_;
    std::vector<Diagnostic>& diags_;
};

}  // namespace toolcomp
