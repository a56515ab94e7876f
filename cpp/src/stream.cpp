#include "toolcomp/stream.hpp"
#include "toolcomp/program/codes.hpp"

#include <algorithm>

#include <unistd.h>

#include <utility>

#include "dialects/table.hpp"
#include "pipeline.hpp"
#include "program/program_source.hpp"
#include "start.hpp"

namespace toolcomp {

namespace {

// The programmed path: counted, not kept.
class CountingSink : public MotionSink {
public:
    explicit CountingSink(std::atomic<std::size_t>& n) : n_(n) {}
    void push(const Motion&) override { n_.fetch_add(1, std::memory_order_relaxed); }

private:
    std::atomic<std::size_t>& n_;
};

}  // namespace

// The end of the compensated pipeline: fills a Path and hands it over every `chunk` segments.
class PathStream::Chunker : public MotionSink {
public:
    Chunker(PathStream& s, const std::vector<std::string>& files) : s_(s), files_(files) { fresh(); }
    void push(const Motion& m) override {
        cur_.push(m);
        if (cur_.size() >= s_.options_.chunk) hand_over();
    }
    void flush() {
        if (cur_.size()) hand_over();
    }

private:
    void fresh() {
        cur_ = Path();
        // Room for a chunk, up to a million rows: a larger chunk grows as it fills (a huge
        // `chunk` must not ask for its whole size before the first segment).
        cur_.reserve(std::min<std::size_t>(s_.options_.chunk, std::size_t{1} << 20));
    }
    void hand_over() {
        cur_.files = files_;
        s_.deliver(std::move(cur_));
        fresh();
    }
    PathStream& s_;
    const std::vector<std::string>& files_;
    Path cur_;
};

PathStream::PathStream(std::string path, std::optional<Dialect> dialect, std::optional<ToolTable> tools,
                       StreamOptions options)
    : path_(std::move(path)), tools_(std::move(tools)), options_(std::move(options)) {
    dialect_ = dialect_of_file(path_, dialect);
    ::close(open_program_file(path_));  // a missing or unreadable file fails here, not in the stream
    start();
}

PathStream::PathStream(std::shared_ptr<const Program> program, std::optional<ToolTable> tools, StreamOptions options)
    : program_(std::move(program)), tools_(std::move(tools)), options_(std::move(options)) {
    start();
}

PathStream::~PathStream() { close(); }

void PathStream::start() {
    if (options_.chunk == 0) throw ProgramError(code::bad_chunk, "A stream's chunk must hold at least one segment");
    if (options_.run.profile) check_profile(*options_.run.profile);
    if (options_.run.machine) check_machine(*options_.run.machine);
    check_search_path(options_.run.search_path);
    options_.run.limits = options_.read;  // the limits of the main file hold for every file it calls
    thread_ = std::thread([this] { produce(); });
}

void PathStream::close() {
    {
        std::lock_guard<std::mutex> lk(mu_);
        cancelled_ = true;
        ready_.clear();
    }
    cv_.notify_all();
    if (thread_.joinable()) thread_.join();
}

void PathStream::deliver(Path&& p) {
    p.release_unused();  // the last chunk is shorter than its reservation
    std::unique_lock<std::mutex> lk(mu_);
    cv_.wait(lk, [this] { return ready_.empty() || cancelled_; });
    if (cancelled_) throw Cancelled{};
    ready_.push_back(std::move(p));
    cv_.notify_all();
}

bool PathStream::wait_for(std::chrono::milliseconds timeout) {
    std::unique_lock<std::mutex> lk(mu_);
    return cv_.wait_for(lk, timeout, [this] { return !ready_.empty() || finished_; });
}

std::optional<Path> PathStream::next() {
    std::unique_lock<std::mutex> lk(mu_);
    cv_.wait(lk, [this] { return !ready_.empty() || finished_; });
    if (!ready_.empty()) {
        Path p = std::move(ready_.front());
        ready_.pop_front();
        cv_.notify_all();
        return p;
    }
    if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
    return std::nullopt;
}

void PathStream::produce() {
    std::vector<std::string> live;  // the files known so far (each chunk carries them)
    std::vector<Diagnostic> diags;
    iso::InterpretOutput out;
    std::size_t blocks = 0;
    std::exception_ptr error;
    Chunker chunker(*this, live);
    CountingSink nominal(programmed_);
    PipelineHooks hooks;
    RunOptions run = options_.run;  // its progress also tells blocks_read()
    const ToolTable* tools = tools_ ? &*tools_ : nullptr;
    auto settle_start = [&](const Beginning& beginning) {
        try {
            run = with_start(run, beginning);
        } catch (...) {  // an option the run refuses: the run says so
        }
    };
    run.progress = [this, user = options_.run.progress](std::size_t n) {
        blocks_read_.store(n, std::memory_order_relaxed);
        if (user) user(n);
    };
    hooks.file_opened = [&live](const std::string& f) { live.push_back(f); };
    auto cancelled = [this] {
        std::lock_guard<std::mutex> lk(mu_);
        return cancelled_;
    };
    auto pipeline = [&](const Program& p) {
        // Files read whole: the main file only, until the end (pieces tell each file opened).
        if (!dialect_row(p.dialect).read_in_pieces()) live.push_back(p.name);
        const ControlProfile profile = run.profile ? *run.profile
                                       : run.machine ? run.machine->profile
                                                     : profile_for(p.dialect);
        run_pipeline(p, tools_ ? &*tools_ : nullptr, run, profile, nominal, chunker, diags, out, hooks);
    };
    try {
        if (program_) {
            blocks = program_->size();
            settle_start([&](const RunOptions& o, MotionSink& sink) { interpret_only(*program_, tools, o, sink, {}); });
            pipeline(*program_);
        } else {
            ProgramSource src(path_, *dialect_, options_.read, options_.piece_bytes, /*limit_pieces=*/false, [&] {
                if (cancelled()) throw Cancelled{};
            }, run.threads);
            settle_start(beginning_of(src, path_, *dialect_, tools, options_.read));
            hooks.next_piece = src.next_piece();
            try {
                pipeline(src.first());
            } catch (...) {
                blocks = src.blocks();
                throw;
            }
            blocks = src.blocks();
        }
    } catch (const Cancelled&) {
    } catch (const ProgramSource::InputError& e) {
        error = e.error;
    } catch (const std::bad_alloc&) {
        error = std::make_exception_ptr(out_of_memory_error());
    } catch (...) {
        error = std::current_exception();
    }
    try {
        if (out.files.size() > live.size()) live = out.files;
        chunker.flush();  // the last chunk; after an error, the segments before it
    } catch (const Cancelled&) {
    }
    std::lock_guard<std::mutex> lk(mu_);
    finished_ = true;
    error_ = error;
    diagnostics_ = std::move(diags);
    blocks_ = blocks;
    blocks_read_.store(blocks, std::memory_order_relaxed);
    files_ = out.files.empty() ? live : out.files;
    cv_.notify_all();
}

std::vector<Diagnostic> PathStream::diagnostics() const {
    std::lock_guard<std::mutex> lk(mu_);
    return diagnostics_;
}

std::size_t PathStream::blocks() const {
    std::lock_guard<std::mutex> lk(mu_);
    return blocks_;
}

std::vector<std::string> PathStream::files() const {
    std::lock_guard<std::mutex> lk(mu_);
    return files_;
}

}  // namespace toolcomp
