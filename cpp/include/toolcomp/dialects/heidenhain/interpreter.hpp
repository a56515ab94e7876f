#pragma once
// The Heidenhain conversational interpreter: runs Klartext blocks and emits the Motion
// stream (tool-centre requests for RL/RR, length offsets from TOOL CALL).
#include <optional>
#include <functional>
#include <string>
#include <vector>

#include "toolcomp/dialects/output.hpp"
#include "toolcomp/control/machine.hpp"
#include "toolcomp/control/profile.hpp"
#include "toolcomp/motion/motion.hpp"
#include "toolcomp/program/diagnostic.hpp"
#include "toolcomp/program/program.hpp"
#include "toolcomp/program/search_path.hpp"

namespace toolcomp {
class ToolTable;
}

namespace toolcomp::heidenhain {

// The main program read a piece at a time (program/program_source.hpp): `next_piece` gives
// the next piece when the run is through the one before, nullptr at the end (the pieces hold
// no labels or jumps: has_control_flow, so each is run on its own); `file_opened` is told
// each program file as the run enters it first (the main program's too).
struct PieceHooks {
    std::function<const Program*()> next_piece;
    std::function<void(const std::string&)> file_opened;
};

// `progress` (optional) is called with the blocks executed so far every `progress_every`.
// `search`: the directories where CALL PGM looks for the called program (`name`, or
// `name.h` when the name has no suffix), in order; no other place is searched, and with an
// empty search path every CALL PGM fails with "not found". The called program runs inline:
// Q parameters and modal state are shared, radius compensation is cancelled by the call
// (TNC), and its moves carry the line numbers of the called file and its index (Motion::file)
// in `out->files` (optional: the main program first, then each called file as first
// entered); `out->dwell_seconds` gets the dwells' seconds.
void interpret(const Program& program, const ToolTable* tools, const ControlProfile& profile, MotionSink& sink,
               std::vector<Diagnostic>& diagnostics, const std::function<void(std::size_t)>& progress = {},
               std::size_t progress_every = 1 << 16, const SearchPath& search = {},
               InterpretOutput* out = nullptr, const Machine* machine = nullptr,
               bool block_delete = false,  // skip the blocks marked '/'
               const std::optional<Vec3>& start = std::nullopt,  // the axes at the start, machine coordinates (mm)
               const PieceHooks& pieces = {});

}  // namespace toolcomp::heidenhain
