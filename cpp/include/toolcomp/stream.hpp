#pragma once
// A run whose compensated path comes out in chunks, for programs whose Paths (or text) do not
// fit in memory. The pipeline runs in a thread of its own, a chunk ahead of the consumer at
// most; the compensation look-ahead runs on across chunk boundaries, so the chunks joined are
// the Path run() returns. The programmed path is not kept.
//
// A program file is read a piece (about 1 MB of whole lines) at a time when nothing in it
// steers across blocks (its dialect's has_control_flow: no O-words, GOTO, loops, labels ...):
// memory stays the same whatever the program's length. A program that has them is read and
// parsed whole; its path is still streamed.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "toolcomp/path.hpp"
#include "toolcomp/run.hpp"
#include "toolcomp/tools/tool_table.hpp"

namespace toolcomp {

struct StreamOptions {
    RunOptions run;                     // max_segments does not apply: a stream has no total
    std::size_t chunk = 1'000'000;      // segments per chunk (the last may hold fewer)
    std::size_t piece_bytes = kPieceBytes;  // text read at a time
    ReadLimits read;                    // max_bytes: for a program read whole; every called file too
};

/// Iterator over a run's compensated path in chunks (Path objects); see toolcomp.iter_run.
/// After the last chunk: diagnostics, blocks, files.
class PathStream {
public:
    // A program file (dialect from the suffix unless given), or a parsed program.
    PathStream(std::string path, std::optional<Dialect> dialect, std::optional<ToolTable> tools, StreamOptions options);
    PathStream(std::shared_ptr<const Program> program, std::optional<ToolTable> tools, StreamOptions options);
    ~PathStream();  // stops the run
    PathStream(const PathStream&) = delete;
    PathStream& operator=(const PathStream&) = delete;

    // The next chunk; nullopt after the last. Waits for the run. The run's error (strict) is
    // raised after the chunk holding the segments before it.
    std::optional<Path> next();
    // Waits at most `timeout` for a chunk or the end: true when next() would not wait.
    bool wait_for(std::chrono::milliseconds timeout);
    /// stop the run; chunks not taken are dropped
    void close();

    // When the stream has ended: warnings (and, strict=false, the error), blocks read, the
    // files segments came from (Path::file indexes it; each chunk has the files known then).
    /// warnings of the run (and with strict=False its error), once the stream has ended
    std::vector<Diagnostic> diagnostics() const;
    /// blocks read, once the stream has ended
    std::size_t blocks() const;
    /// the files segments came from (Path.file indexes it), once the stream has ended
    std::vector<std::string> files() const;
    // At any time: blocks read so far (every RunOptions::progress_every blocks), and segments
    // of the programmed path so far (counted, not kept).
    /// the dialect the program is read in: 'linuxcnc', 'fanuc', 'sinumerik', 'heidenhain'
    /// or 'rockwell'
    Dialect dialect() const { return program_ ? program_->dialect : *dialect_; }  // the program's
    /// blocks read so far (updated every 65536 blocks, and at the end), for a progress bar
    std::size_t blocks_read() const { return blocks_read_.load(std::memory_order_relaxed); }
    /// segments of the programmed path so far (counted, not kept)
    std::size_t programmed_segments() const { return programmed_.load(std::memory_order_relaxed); }

private:
    struct Cancelled {};
    class Chunker;
    void start();
    void produce();
    void deliver(Path&& p);  // from the run's thread; waits while a chunk is waiting

    std::string path_;
    std::optional<Dialect> dialect_;
    std::shared_ptr<const Program> program_;
    std::optional<ToolTable> tools_;
    StreamOptions options_;

    mutable std::mutex mu_;
    std::condition_variable cv_;
    std::deque<Path> ready_;
    bool finished_ = false, cancelled_ = false;
    std::exception_ptr error_;
    std::vector<Diagnostic> diagnostics_;
    std::size_t blocks_ = 0;
    std::vector<std::string> files_;
    std::atomic<std::size_t> blocks_read_{0}, programmed_{0};
    std::thread thread_;
};

}  // namespace toolcomp
