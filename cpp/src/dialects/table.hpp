#pragma once
// The dialects toolcomp reads, one row each: name, file suffixes, how a file is read, the
// front end and the interpreter behind one interface. Adding a control is one folder under
// dialects/ and one row in table.cpp; the run, streaming, program reading and (through
// toolcomp._core.dialect_table) the command line and the pytest plugin read this table.
#include <array>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "../pipeline.hpp"
#include "toolcomp/program/dialect.hpp"

namespace toolcomp {

// What a run hands a dialect's interpreter.
struct DialectRun {
    const Program& program;
    const ToolTable* tools;
    const ControlProfile& profile;
    const RunOptions& options;
    MotionSink& sink;
    std::vector<Diagnostic>& diagnostics;
    iso::InterpretOutput& out;  // the files moves come from, the parameters at the end
    const PipelineHooks& hooks;
};

struct DialectRow {
    Dialect dialect;
    std::string_view name;
    std::array<std::string_view, 2> suffixes;  // lower case, without the dot; "" unused
    // A lone CR ends a line (LinuxCNC reads up to LF only, as rs274 does).
    bool cr_ends_line;
    // A file without control flow is read and parsed a piece at a time as it runs (CAM
    // output of any length in bounded memory); else the file is read whole.
    bool read_in_pieces;
    // The interpreter checks a machine's travel limits itself (ISO: its moves are in work
    // coordinates under offsets the program changes). Else its moves are in the machine's
    // axes less the work origin, and the run checks them as they come (control/travel.hpp).
    bool interpreter_checks_travel;
    Program (*parse)(std::string_view text, std::string name, bool strict);
    void (*interpret)(const DialectRun& run);
};

std::span<const DialectRow> dialect_table();
const DialectRow& dialect_row(Dialect d);

}  // namespace toolcomp
