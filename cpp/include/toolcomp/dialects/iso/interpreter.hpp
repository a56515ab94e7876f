#pragma once
#include <functional>
// The ISO interpreter: runs a Program block by block with LinuxCNC's modal semantics (or
// Fanuc's where the profile says so) and emits the Motion stream.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "toolcomp/control/machine.hpp"
#include "toolcomp/control/probe.hpp"
#include "toolcomp/control/profile.hpp"
#include "toolcomp/dialects/output.hpp"
#include "toolcomp/motion/motion.hpp"
#include "toolcomp/program/diagnostic.hpp"
#include "toolcomp/program/program.hpp"
#include "toolcomp/program/search_path.hpp"
#include "toolcomp/tools/tool_table.hpp"

namespace toolcomp::iso {

using toolcomp::InterpretOutput;
using toolcomp::ParameterValues;

struct InterpretOptions {
    bool block_delete = false;  // skip blocks that start with '/'
    std::function<void(std::size_t)> progress;  // blocks read so far, every progress_every
    std::size_t progress_every = 1 << 16;
    // Directories where called subprogram files are looked up, in order, and nowhere else
    // (LinuxCNC o<name> call: name.ngc; Fanuc M98/G65 P1000: O1000.nc, O1000, 1000.nc), and
    // the limits they are read within (program/search_path.hpp).
    SearchPath search;
    ParameterValues parameters;  // start values (they win over the machine's origins)
    // What the probe moves (G38.2-G38.5) meet, in order; beyond them a probe touches at its target.
    std::vector<ProbeResult> probes;
    // The machine the program runs on: its builder M codes, work origin, G28/G30 positions,
    // tool change position and travel limits (control/machine.hpp); nullptr: none.
    const Machine* machine = nullptr;
    // Where the axes stand at the start, machine coordinates (mm); none: the machine's zero.
    std::optional<Vec3> start;
    // A main program read in pieces (streaming): called when the blocks of the piece run out,
    // it returns the next piece, or nullptr at the end of the file. The piece stays valid
    // until the next call. Control structures (O-words, GOTO targets) must lie within a piece.
    std::function<const Program*()> next_piece;
    // Told the name of every file moves may come from, as it is opened (main program first).
    std::function<void(const std::string&)> file_opened;
};


// Emits every move into `sink`; non-fatal messages go to `diagnostics`.
// Throws ProgramError (code, message, line, column) at the first error, after the moves
// before the failing block have been emitted.
// `output` (optional) receives the files and parameters, also when the run stops at an error.
void interpret(const Program& program, const ToolTable* tools, const ControlProfile& profile,
               const InterpretOptions& options, MotionSink& sink, std::vector<Diagnostic>& diagnostics,
               InterpretOutput* output = nullptr);

}  // namespace toolcomp::iso
