#pragma once
// The Sinumerik 840D interpreter: runs .mpf/.spf blocks (R parameters, DEF variables,
// control structures, subprograms, frames, tool data) and emits the Motion stream.
//
// Output coordinates: millimetres in the coordinate system of the settable frames as the
// machine's data has them (toolcomp does not have those values: they are taken as neutral,
// the way the ISO interpreters report program coordinates before work offsets). What the
// program itself writes into them ($P_UIFR, $P_IFRAME, $P_BFRAME) and the programmable frame
// (TRANS, ROT, SCALE, MIRROR, their additive forms, G58/G59, $P_PFRAME) are applied. The table
// zero-point shift of a type P toolholder (TCARR + TCOABS) is part of the output.
#include <optional>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "toolcomp/dialects/output.hpp"
#include "toolcomp/control/machine.hpp"
#include "toolcomp/control/profile.hpp"
#include "toolcomp/compensation/toolholder.hpp"
#include "toolcomp/motion/motion.hpp"
#include "toolcomp/program/diagnostic.hpp"
#include "toolcomp/program/program.hpp"
#include "toolcomp/program/search_path.hpp"
#include "toolcomp/tools/sinumerik_edge.hpp"

namespace toolcomp {
class ToolTable;
}

namespace toolcomp::sinumerik {

struct InterpretOptions {
    bool block_delete = false;
    std::function<void(std::size_t)> progress;  // blocks executed so far, every progress_every
    std::size_t progress_every = 1 << 16;
    // Directories searched, in order, for subprograms called by name or L number ("L10" looks
    // for L10.spf / L10.SPF / L10.mpf / L10 there); nothing else is ever opened. With the
    // limits called files are read within (program/search_path.hpp).
    SearchPath search;
    // $TC_DP edges known before the program starts (the program's own $TC_DP assignments add
    // to them). An edge here takes precedence over the ToolTable's tool of the same number.
    SinumerikEdgeMap tool_data;
    SinumerikLengthSettings lengths;            // SD42940 / SD42950 / SD42930
    unsigned tool_parameter_def_mask = 0;       // MD20360 (GETTCOR, diameter values)
    std::map<int, Toolholder> toolholders;      // $TC_CARR data known before the program starts
    int max_call_depth = 16;                    // program levels (main program included)
    const Machine* machine = nullptr;           // builder M codes (control/machine.hpp)
    std::optional<Vec3> start;                  // the axes at the start, machine coordinates (mm)
    // The main program read a piece at a time (program_source.hpp): the next piece when the
    // run is through the one before, nullptr at the end. The pieces hold no control flow
    // (has_control_flow), so each is run on its own.
    std::function<const Program*()> next_piece;
    std::function<void(const std::string&)> file_opened;  // each program file as the run enters it first
};

// `out` (optional) receives the main program's name and each subprogram file's, in the
// order first entered (Motion::file indexes them), and the dwells' seconds.
void interpret(const Program& program, const ToolTable* tools, const ControlProfile& profile,
               const InterpretOptions& options, MotionSink& sink, std::vector<Diagnostic>& diagnostics,
               InterpretOutput* out = nullptr);

}  // namespace toolcomp::sinumerik
