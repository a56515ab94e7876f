#include "toolcomp/run.hpp"
#include "toolcomp/program/codes.hpp"

#include <cmath>
#include <cstdio>
#include <algorithm>
#include <new>
#include <optional>

#include "pipeline.hpp"
#include "start.hpp"
#include "shared_path.hpp"
#include "program/program_source.hpp"

#include "control/travel.hpp"
#include "dialects/table.hpp"
#include "toolcomp/analysis/cycle_time.hpp"
#include "toolcomp/compensation/stages.hpp"

namespace toolcomp {

namespace {

// Whether every number of a move the Paths keep is finite (x * 0 is 0 for a finite x, NaN
// else; the feed may be NaN, "not known", but not infinite).
bool finite_move(const Motion& m) {
    // In millimetres, as the Paths keep them (a G20 program's values times 25.4).
    const double u = m.unit;
    double z = 0;
    for (int i = 0; i < 3; ++i) z += (m.start[i] * u) * 0 + (m.end[i] * u) * 0 + (m.tool_offset[i] * u) * 0 + m.abc[i] * 0;
    if (m.is_arc()) z += (m.center.x() * u) * 0 + (m.center.y() * u) * 0 + (m.center.z() * u) * 0;
    return z == 0 && !std::isinf(m.feed);
}

[[noreturn]] void refuse_not_finite(const Motion& m) {
    throw ProgramError(code::not_finite,
                       "A position, offset or feed rate of this move is not a finite number (an overflow of "
                       "the program's values)",
                       {m.line, 0, {}, m.file});
}

[[noreturn, gnu::cold]] void refuse_arc(const Motion& m, const char* why) {
    char radius[64];
    const Vec2 u = in_plane(m.start, m.plane) - in_plane(m.center, m.plane);
    std::snprintf(radius, sizeof radius, "%.6g", std::hypot(u.x(), u.y()) * m.unit);
    throw ProgramError(code::arc_radius_too_large,
                       std::string("This arc cannot be cut as written (radius ") + radius + " mm): " + why,
                       {m.line, 0, {}, m.file});
}

// Sends every move to two consumers, once its numbers are known to be finite and an arc's
// geometry sound.
class Tee : public MotionSink {
public:
    Tee(MotionSink& a, MotionSink& b) : a_(a), b_(b) {}
    void push(const Motion& m) override {
        if (!finite_move(m)) [[unlikely]]
            refuse_not_finite(m);
        if (m.is_arc())
            if (const char* why = arc_defect(m.arc(), m.unit)) [[unlikely]]
                refuse_arc(m, why);
        a_.push(m);
        b_.push(m);
    }
    void control(const ControlEvent& e) override {
        a_.control(e);
        b_.control(e);
    }
    void finish() override {
        a_.finish();
        b_.finish();
    }

private:
    MotionSink& a_;
    MotionSink& b_;
};

// Passes moves on to a Path until it holds `limit` segments; the move beyond stops the run
// with "memory_limit" at its line. After that, moves are dropped (a lenient run still
// flushes the compensation stages into it).
class SegmentLimit : public MotionSink {
public:
    SegmentLimit(MotionSink& out, std::size_t limit, const char* what) : out_(out), limit_(limit), what_(what) {}
    void push(const Motion& m) override {
        if (tripped_) return;
        if (count_ == limit_) [[unlikely]]
            trip(m);
        ++count_;
        out_.push(m);
    }
    void control(const ControlEvent& e) override {
        if (!tripped_) out_.control(e);
    }
    void finish() override { out_.finish(); }

private:
    // Out of line: the message's strings would give every push() their stack frame.
    [[noreturn, gnu::noinline, gnu::cold]] void trip(const Motion& m) {
        tripped_ = true;
        throw ProgramError(code::memory_limit, std::string("The ") + what_ + " path would hold more than " +
                                               std::to_string(limit_) + " segments (max_segments)",
                           {m.line, 0, {}, m.file});
    }

    MotionSink& out_;
    std::size_t limit_;
    const char* what_;
    std::size_t count_ = 0;
    bool tripped_ = false;
};

// The programmed Path's SegmentLimit, telling the compensated side what it stored.
class Programmed : public MotionSink {
public:
    Programmed(MotionSink& limit, const Path& path, SharedPath& unchanged)
        : limit_(limit), path_(path), unchanged_(unchanged) {}
    void push(const Motion& m) override {
        const std::size_t before = path_.size();
        limit_.push(m);
        if (path_.size() != before) unchanged_.programmed(m);
    }
    void control(const ControlEvent& e) override { limit_.control(e); }
    void finish() override { limit_.finish(); }

private:
    MotionSink& limit_;
    const Path& path_;
    SharedPath& unchanged_;
};

// The compensation stages know a move's file by its index only (Motion::file): the name,
// for a position that has none yet. Index 0 is the main program ("").
bool name_file(SourcePos& pos, const std::vector<std::string>& files) {
    if (!pos.file.empty() || pos.file_index <= 0 || static_cast<std::size_t>(pos.file_index) >= files.size()) return false;
    pos.file = files[static_cast<std::size_t>(pos.file_index)];
    return true;
}

}  // namespace

Program parse_program(std::string_view text, Dialect dialect, std::string name, bool strict,
                      std::size_t max_line_length) {
    const DialectRow& row = dialect_row(dialect);
    check_line_lengths(text, max_line_length, row.cr_ends_line);
    return row.parse(text, std::move(name), strict);
}

Program read_program(const std::string& path, std::optional<Dialect> dialect, bool strict, const ReadLimits& limits) {
    const Dialect d = dialect_of_file(path, dialect);
    const std::string text = read_program_text(path, limits.max_bytes);
    return parse_program(text, d, path, strict, limits.max_line_length);
}

ProgramError out_of_memory_error() {
    return ProgramError(code::out_of_memory,
                       "The run ran out of memory (the machine's memory or the process's limit): see max_segments, "
                       "max_bytes and ControlProfile.call_depth_limit");
}

double Result::cycle_time() const {
    const Path& p = compensated();
    double seconds = dwell_seconds + static_cast<double>(tool_changes(p)) * p.rates.tool_change_seconds;
    for (double s : segment_seconds(p, p.rates)) seconds += s;
    return seconds;
}

bool Result::ok() const {
    for (const auto& d : diagnostics)
        if (d.severity == Severity::error) return false;
    return true;
}

void interpret_only(const Program& program, const ToolTable* tools, const RunOptions& options, MotionSink& sink,
                    const PipelineHooks& hooks) {
    const ControlProfile profile = options.profile ? *options.profile
                                   : options.machine ? options.machine->profile
                                                     : profile_for(program.dialect);
    std::vector<Diagnostic> diagnostics;
    iso::InterpretOutput out;
    dialect_row(program.dialect).interpret({program, tools, profile, options, sink, diagnostics, out, hooks});
}

Beginning beginning_of_file(const std::string& path, Dialect dialect, const ToolTable* tools, const ReadLimits& limits) {
    return [=](const RunOptions& o, MotionSink& sink) {
        // Small pieces: the beginning is a few moves, not the megabyte a run reads ahead.
        ProgramSource src(path, dialect, limits, kPieceBytes / 16, /*limit_pieces=*/true, {}, /*threads=*/false);
        PipelineHooks hooks;
        hooks.next_piece = src.next_piece();
        interpret_only(src.first(), tools, o, sink, hooks);
    };
}

Beginning beginning_of(const ProgramSource& src, const std::string& path, Dialect dialect, const ToolTable* tools,
                       const ReadLimits& limits) {
    if (src.in_pieces()) return beginning_of_file(path, dialect, tools, limits);
    return [&src, tools](const RunOptions& o, MotionSink& sink) { interpret_only(src.first(), tools, o, sink, {}); };
}

void run_pipeline(const Program& program, const ToolTable* tools, const RunOptions& options,
                  const ControlProfile& profile, MotionSink& nominal, MotionSink& compensated,
                  std::vector<Diagnostic>& diagnostics, iso::InterpretOutput& out, const PipelineHooks& hooks) {
    CompensationChain chain(profile, compensated, diagnostics, options.threads);
    Tee tee(nominal, chain);
    const DialectRow& row = dialect_row(program.dialect);
    if (options.machine && options.machine->control != program.dialect)
        throw ProgramError(code::machine_control, "The machine '" + options.machine->name + "' has a " +
                                                  std::string(dialect_name(options.machine->control)) +
                                                  " control; the program is read as " + std::string(row.name));
    std::optional<TravelSink> travel;
    if (options.machine && options.machine->has_travel_limits() && !row.interpreter_checks_travel)
        travel.emplace(*options.machine, tee, diagnostics);
    MotionSink& sink = travel ? static_cast<MotionSink&>(*travel) : tee;
    out.files.push_back(program.name);
    try {
        try {
            row.interpret({program, tools, profile, options, sink, diagnostics, out, hooks});
        } catch (const Error& e) {
            if (options.strict) {
                SourcePos at = e.pos();
                if (name_file(at, out.files)) throw_at(e, at);
                throw;
            }
            tee.finish();
            diagnostics.push_back(e.diagnostic());
        }
    } catch (...) {
        // The overcut watch's warnings up to the error are still put in (a stream keeps them);
        // an error of the watch itself gives way to the one being raised.
        try {
            chain.settle();
        } catch (...) {
        }
        throw;
    }
    for (Diagnostic& d : diagnostics) name_file(d.pos, out.files);
}

namespace {
// `expected`: blocks the program is thought to have (the Paths are reserved for as many).
Result run_main(const Program& program, const ToolTable* tools, const RunOptions& options,
                const PipelineHooks& hooks, std::size_t expected) {
    Result res;
    res.blocks = program.size();
    if (program.blank) {
        const double unit = program.inch ? kMmPerInch : 1.0;
        res.blank = Blank{program.blank->min * unit, program.blank->max * unit, program.blank->axis};
    }
    // One segment per block is the common case (CAM output): reserving it up front avoids the
    // copies and the doubled capacity of growing columns (peak memory). Radius compensation
    // adds a corner arc at each outside corner, up to a second segment a block: the
    // compensated path is reserved for two. A reservation is address space only: large
    // columns are mapped, and pages never written are never memory (release_unused gives
    // back what the last segment's page leaves).
    res.nominal.reserve_granted(std::min(expected, options.max_segments));
    ControlProfile profile = options.profile ? *options.profile
                             : options.machine ? options.machine->profile
                                               : profile_for(program.dialect);
    // The compensated path is stored only once it differs from the programmed one
    // (shared_path.hpp); its reservation is address space until then.
    SharedPath unchanged(res.nominal, res.path, std::min(2 * expected, options.max_segments));
    SegmentLimit nominal_limit(res.nominal, options.max_segments, "programmed");
    Programmed nominal(nominal_limit, res.nominal, unchanged);
    SegmentLimit compensated(unchanged, options.max_segments, "compensated");
    // The Paths' fresh pages are faulted in on another thread, ahead of the rows being
    // written (page_warmer.hpp). Stopped before the Paths give back what they do not use
    // (and, declared after them, before they are freed).
    std::optional<PageWarmer> warmer;
    if (options.threads) {
        warmer.emplace();
        res.nominal.warm_with(&*warmer);
        unchanged.warm_with(&*warmer);
    }
    iso::InterpretOutput out;
    run_pipeline(program, tools, options, profile, nominal, compensated, res.diagnostics, out, hooks);
    const bool same = unchanged.settle();
    res.nominal.warm_with(nullptr);
    unchanged.warm_with(nullptr);
    warmer.reset();
    res.nominal.release_unused();  // what the reservation and the last 2 MB pages left over
    res.nominal.files = out.files;
    if (same && options.share_unchanged_path) {
        res.path = Path();
        res.path_is_nominal = true;
    } else if (same) {
        res.path = res.nominal;
    } else {
        res.path.release_unused();
        res.path.files = std::move(out.files);
    }
    res.parameters = std::move(out.parameters);
    res.tools = std::move(out.tools);
    res.dwell_seconds = out.dwell_seconds;
    if (options.machine) res.nominal.rates = res.path.rates = options.machine->rates();
    return res;
}
}  // namespace

namespace {
Result run_file_main(const std::string& path, std::optional<Dialect> dialect, const ToolTable* tools,
                     const RunOptions& run_options) {
    const Dialect d = dialect_of_file(path, dialect);
    ProgramSource src(path, d, run_options.limits, kPieceBytes, /*limit_pieces=*/true, {}, run_options.threads);
    const RunOptions options = with_start(run_options, beginning_of(src, path, d, tools, run_options.limits));
    PipelineHooks hooks;
    hooks.next_piece = src.next_piece();
    try {
        Result res = run_main(src.first(), tools, options, hooks, src.estimated_blocks());
        res.blocks = src.blocks();
        return res;
    } catch (const ProgramSource::InputError& e) {
        std::rethrow_exception(e.error);
    }
}
}  // namespace

Result run(const Program& program, const ToolTable* tools, const RunOptions& options) {
    if (options.profile) check_profile(*options.profile);
    if (options.machine) check_machine(*options.machine);
    check_search_path(options.search_path);
    return out_of_memory_as_error([&] {
        const RunOptions o = with_start(options, [&](const RunOptions& r, MotionSink& sink) {
            interpret_only(program, tools, r, sink, {});
        });
        return run_main(program, tools, o, {}, program.size());
    });
}

Result run_file(const std::string& path, std::optional<Dialect> dialect, const ToolTable* tools,
                const RunOptions& options, const ReadLimits& limits) {
    if (options.profile) check_profile(*options.profile);
    if (options.machine) check_machine(*options.machine);
    check_search_path(options.search_path);
    RunOptions o = options;
    o.limits = limits;
    return out_of_memory_as_error([&] { return run_file_main(path, dialect, tools, o); });
}

}  // namespace toolcomp
