#pragma once
// The whole pipeline: program text -> Program -> interpreter -> Motion stream ->
// compensation stages -> Path.
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "toolcomp/control/machine.hpp"
#include "toolcomp/control/probe.hpp"
#include "toolcomp/control/profile.hpp"
#include "toolcomp/path.hpp"
#include "toolcomp/program/diagnostic.hpp"
#include "toolcomp/program/input_limits.hpp"
#include "toolcomp/program/program.hpp"
#include "toolcomp/tools/tool_table.hpp"

namespace toolcomp {

// Parse program text in the given dialect. strict: throws ParseError at the first syntax
// error; otherwise the error is kept in the Program and raised when a run reaches it. A line
// longer than `max_line_length` bytes throws ParseError("line_too_long") whatever `strict`
// is, before the dialect's front end sees the text.
Program parse_program(std::string_view text, Dialect dialect, std::string name = "<string>", bool strict = true,
                      std::size_t max_line_length = kDefaultMaxLineLength);

// Read a program file; the dialect comes from the suffix when not given. Only a regular file
// is read ("not_a_regular_file" otherwise), and its size is checked before it is read.
Program read_program(const std::string& path, std::optional<Dialect> dialect = std::nullopt, bool strict = true,
                     const ReadLimits& limits = {});
// Reads a program file through as read_program(strict) does, a piece at a time and without
// keeping it (every dialect: no max_bytes, as for a stream): its number of blocks, or the
// first syntax error
// anywhere in the file (ParseError), also after M2/M30. (program/check_file.cpp)
std::size_t check_program_file(const std::string& path, std::optional<Dialect> dialect = std::nullopt,
                               const ReadLimits& limits = {});

// Segments each of the two Paths of a run may hold by default. A segment takes about 120
// bytes of a Path (more when rotary axes, surface normals or tool axes vary), so the two
// Paths of a run stay within about 5 GB.
inline constexpr std::size_t kDefaultMaxSegments = 20'000'000;

struct RunOptions {
    bool strict = true;         // raise at the first error; else return the path up to it
    bool block_delete = false;  // skip '/' blocks
    std::optional<ControlProfile> profile;  // default: the machine's, else profile_for(program.dialect)
    // The machine the program runs on (control/machine.hpp): its control must be the
    // program's dialect ("machine_control" otherwise); its profile is the run's unless
    // `profile` is given; its builder M codes, origins, tool change position and travel
    // limits act in every dialect (doc/machines.md).
    std::shared_ptr<const Machine> machine;
    // Where the axes stand when the program starts, machine coordinates (mm; a lathe's X a
    // diameter, as the machine's). Not given: the machine's `start` when there is a machine,
    // else where the program first sends each axis (first_positions(), start.cpp).
    std::optional<Vec3> start;
    // Called with the number of blocks read (Heidenhain: executed) so far, every
    // `progress_every` blocks; may throw to stop the run.
    std::function<void(std::size_t)> progress;
    std::size_t progress_every = 1 << 16;
    // Directories where programs called by name (Heidenhain CALL PGM, Sinumerik
    // subprograms, LinuxCNC o<name> call, Fanuc M98 / G65) are looked up, in order, and
    // nowhere else (none may be empty: Error "search_path_empty"). Moves of a called program
    // carry line numbers of its own file and its index in Path::files.
    std::vector<std::string> search_path;
    // A called file whose real path leaves its search directory (through a symbolic link) is
    // refused ("outside_search_path") unless this is set (program/search_path.hpp).
    bool follow_links = false;
    // Limits every called file is read within (run_file applies its own `limits` to them).
    ReadLimits limits;
    // Numbered parameters the run starts from (LinuxCNC, Fanuc): a .var file's values.
    std::map<int, double> parameters;
    // What the probe moves (LinuxCNC G38.2-G38.5) meet, one per probe move in order
    // (control/probe.hpp); beyond them a probe touches at its target.
    std::vector<ProbeResult> probes;
    // Segments the programmed path and the compensated path may each hold: the segment
    // beyond it stops the run with ProgramError("memory_limit") at its block's line.
    std::size_t max_segments = kDefaultMaxSegments;
    // A run puts the overcut watch and the reading of the next piece of a program file on
    // threads of their own (the other core). false: everything on the calling thread, for a
    // batch whose runs keep every core busy anyway (the hand-over between threads is work too).
    bool threads = true;
    // A compensated path that is the programmed one, segment for segment (no compensation
    // changed anything: a program in tool-centre coordinates), is stored once: true leaves
    // Result::path empty and sets Result::path_is_nominal (the Python module does); false
    // copies it into Result::path.
    bool share_unchanged_path = false;
};

/// The outcome of run(): programmed and compensated paths, diagnostics and block count.
struct Result {
    /// the programmed Path (what the interpreter produced, before compensation)
    Path nominal;
    /// the compensated Path (after the compensation stages); the `nominal` Path itself when
    /// no stage changed a segment (a program without compensation: stored once)
    Path path;     // after the compensation stages (empty when path_is_nominal)
    // The compensated path is `nominal`, segment for segment (RunOptions::share_unchanged_path).
    bool path_is_nominal = false;
    const Path& compensated() const { return path_is_nominal ? nominal : path; }
    /// list of Diagnostic (info and warnings; with strict=False also the error that stopped
    /// the run)
    std::vector<Diagnostic> diagnostics;
    /// number of blocks in the program
    std::size_t blocks = 0;
    /// the workpiece blank the program declares (Heidenhain BLK FORM), ((min), (max)) in
    /// mm, or None
    std::optional<Blank> blank;  // the workpiece blank the program declares (mm), if any
    /// numbered parameters set at the end of the run, {number: value} (LinuxCNC, Fanuc;
    /// vacant Fanuc variables and LinuxCNC zeros left out)
    std::map<int, double> parameters;  // numbered parameters set at the end (LinuxCNC, Fanuc)
    /// the tool table as the program left it when it edited it (LinuxCNC G10 L1: the run's
    /// copy; the table passed in is never changed), else None
    std::optional<ToolTable> tools;    // the tool table as the program left it, when it edited it (G10 L1)
    /// seconds the program dwells: G4 (LinuxCNC P seconds, Fanuc P milliseconds or X/U
    /// seconds, Sinumerik F seconds or S revolutions), the dwells of LinuxCNC/Fanuc canned
    /// cycles (G82, G86, G88, G89 P), Heidenhain CYCL DEF 9
    double dwell_seconds = 0;          // the dwells the run made (G4, the cycles' dwells)
    /// True when no diagnostic has severity 'error'
    bool ok() const;
    // Seconds the program takes on the run's machine: its compensated path's segments, its
    // dwells and its tool changes (analysis/cycle_time.hpp).
    /// seconds the program takes on the run's machine: path.duration summed, the dwells
    /// (dwell_time) and path.tool_changes times the machine's tool_change_time; an estimate
    /// without acceleration (doc/cycle-time.md)
    double cycle_time() const;
};

Result run(const Program& program, const ToolTable* tools, const RunOptions& options = {});

// Text read at a time from a program file read piece by piece.
inline constexpr std::size_t kPieceBytes = std::size_t{1} << 20;

// Reads and runs a program file (dialect from the suffix unless given), read leniently (a
// syntax error is raised when the run reaches its line); `limits` apply to it and to every
// file it calls (they replace options.limits). A file in which nothing steers across blocks
// (its dialect's has_control_flow, dialects/table.hpp: CAM output of LinuxCNC, Fanuc,
// 9/Series, Sinumerik, Heidenhain) is read and parsed a piece at a time as it runs, so only the Paths
// grow with its length.
Result run_file(const std::string& path, std::optional<Dialect> dialect, const ToolTable* tools,
                const RunOptions& options = {}, const ReadLimits& limits = {});

}  // namespace toolcomp
