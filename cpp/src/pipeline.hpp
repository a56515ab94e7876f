#pragma once
// The pipeline of a run, without the Result around it: interpreter -> Motion stream -> the
// programmed path (`nominal`) and the compensation stages -> the compensated path. run()
// collects both into Paths; a PathStream hands the compensated one over in chunks.
#include <functional>
#include <new>
#include <string>
#include <vector>

#include "toolcomp/dialects/iso/interpreter.hpp"
#include "toolcomp/run.hpp"

namespace toolcomp {

// What a streamed run adds (ISO dialects): the main program in pieces, and the files as
// they are opened.
struct PipelineHooks {
    std::function<const Program*()> next_piece;
    std::function<void(const std::string&)> file_opened;
};

// With options.strict an Error propagates; otherwise it ends the run as a diagnostic, after
// the compensation stages are flushed. `out` gets the files and the parameters at the end.
void run_pipeline(const Program& program, const ToolTable* tools, const RunOptions& options,
                  const ControlProfile& profile, MotionSink& nominal, MotionSink& compensated,
                  std::vector<Diagnostic>& diagnostics, iso::InterpretOutput& out, const PipelineHooks& hooks = {});

// The interpreter alone, its moves into `sink` (no compensation; diagnostics dropped).
void interpret_only(const Program& program, const ToolTable* tools, const RunOptions& options, MotionSink& sink,
                    const PipelineHooks& hooks);
// What start.hpp runs of a program file: its first piece and on, read again.
std::function<void(const RunOptions&, MotionSink&)> beginning_of_file(const std::string& path, Dialect dialect,
                                                                      const ToolTable* tools, const ReadLimits& limits);
// The same of `src`'s file: the Program already read when it was read whole (read once,
// not again for each look at its beginning), else beginning_of_file.
class ProgramSource;
std::function<void(const RunOptions&, MotionSink&)> beginning_of(const ProgramSource& src, const std::string& path,
                                                                 Dialect dialect, const ToolTable* tools,
                                                                 const ReadLimits& limits);

// Memory exhausted anywhere in a run (a Path's columns, a called file's text, the
// interpreter's state) is the run's error with a stable code, ProgramError("out_of_memory"),
// not std::bad_alloc (which Python raises as a bare MemoryError).
ProgramError out_of_memory_error();
template <class F>
auto out_of_memory_as_error(F&& f) -> decltype(f()) {
    try {
        return f();
    } catch (const std::bad_alloc&) {
        throw out_of_memory_error();
    }
}

}  // namespace toolcomp
