#pragma once
// The dialects toolcomp reads, one row each: name, file suffixes, how a file is read, the
// front end and the interpreter behind one interface. Adding a control is one folder under
// dialects/ and one row in table.cpp; the run, streaming, program reading and (through
// toolcomp._core.dialect_table) the command line and the pytest plugin read this table.
#include <array>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "../pipeline.hpp"
#include "toolcomp/program/dialect.hpp"

namespace toolcomp {

// A dialect's reading of a program file a piece at a time (whole lines each,
// program/file_pieces.hpp): each piece's Program goes on where the one before ended.
class PieceReader {
public:
    virtual ~PieceReader() = default;
    // `into`: a Program no longer needed, whose memory the piece reuses.
    virtual Program parse(std::string_view piece, Program into) = 0;
    virtual bool done() const = 0;  // later text is not part of the program (a closing %, an error)
    // The end of the file, unless done(): a last Program (without blocks, or with a block held
    // back) when the end itself tells something (Heidenhain: END PGM missing), else nothing.
    virtual std::optional<Program> end(Program) { return std::nullopt; }
};

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
    // The interpreter checks a machine's travel limits itself (ISO: its moves are in work
    // coordinates under offsets the program changes). Else its moves are in the machine's
    // axes less the work origin, and the run checks them as they come (control/travel.hpp).
    bool interpreter_checks_travel;
    Program (*parse)(std::string_view text, std::string name, bool strict);
    void (*interpret)(const DialectRun& run);
    // A file in which `has_control_flow` finds nothing is read and parsed a piece at a time as
    // it runs (CAM output of any length in bounded memory), by `pieces`; the interpreter then
    // tells each file it enters (PipelineHooks::file_opened). Without them (nullptr) a file is
    // read whole.
    // `start`: the text is the file's first piece (read before the run starts).
    bool (*has_control_flow)(std::string_view text, bool start) = nullptr;
    std::unique_ptr<PieceReader> (*pieces)(Dialect, std::string name, bool strict, std::size_t piece_bytes) = nullptr;
    bool read_in_pieces() const { return pieces != nullptr; }
};

std::span<const DialectRow> dialect_table();
const DialectRow& dialect_row(Dialect d);

}  // namespace toolcomp
