#pragma once
// The overcut watch beside the radius stage. The watch only observes (programmed elements in,
// tool-centre elements in, warnings out), so the stage need not wait for it: its calls are
// recorded in batches, and once a run has filled one batch they are replayed by an
// OvercutWatch on a thread of its own, on the other core. A report's warnings are kept with
// the place the diagnostics had reached when the stage asked for the report; settle() waits
// for the thread and puts them in there. The diagnostics come out exactly as from a watch
// called directly. Short runs never start the thread: settle() replays their one batch.
// Without a thread (RunOptions::threads false) every call is replayed as it is made.
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <exception>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

#include "toolcomp/compensation/overcut.hpp"
#include "toolcomp/program/diagnostic.hpp"

namespace toolcomp {

class BackgroundWatch {
public:
    // `thread`: false replays each call as it is made, on the caller's thread.
    explicit BackgroundWatch(bool thread = true) : direct_(!thread) {}
    BackgroundWatch(const BackgroundWatch&) = delete;
    BackgroundWatch& operator=(const BackgroundWatch&) = delete;
    ~BackgroundWatch();  // what is not settled is abandoned

    // OvercutWatch's calls, in the stage's order (the frequent ones inline: a few stores).
    void configure(int neighbours, double tolerance);
    void programmed(const Element2& e, int line) {
        if (!on_) return;
        record({Op::programmed, false, line, 0, 0, 0, e});
        ++contour_count_;
    }
    void tangent_slack(double slack);
    void compensated(const Element2& e, int line, int file, double r, std::size_t settled) {
        if (on_) record({Op::compensated, false, line, file, r, settled, e});
    }
    // Programmed elements of the contour so far (OvercutWatch::compensated's `settled`).
    std::size_t contour_count() const { return contour_count_; }
    // OvercutWatch::report into `diags` at its present end (filled in by settle()).
    void report(const std::vector<Diagnostic>& diags, double mm, bool all) {
        if (all) contour_count_ = 0;  // the watch forgets the contour
        if (!(all ? since_all_ : since_report_)) return;  // it would find nothing new
        since_report_ = false;
        if (all) since_all_ = false;
        record({Op::report, all, 0, 0, mm, diags.size(), {}});
    }
    void scale(double f);
    // Replays every call made so far and merges the warnings into `diags`, the vector the
    // reports were asked for (only appended to since). The watch goes on afterwards.
    void settle(std::vector<Diagnostic>& diags);

    static constexpr std::size_t kBatch = 4096;  // calls handed over at once
    static constexpr std::size_t kQueued = 8;    // batches waiting at most (3 MB; then the stage waits)

private:
    enum class Op : std::uint8_t { configure, programmed, tangent_slack, compensated, report, scale };
    struct Call {
        Op op;
        bool all;
        int line, file;
        double a;
        std::size_t at;  // report: the diagnostics' size then; compensated: settled
        Element2 e;
    };
    void record(const Call& c) {
        if (c.op != Op::report) since_report_ = since_all_ = true;
        if (direct_) {
            apply(c);
            return;
        }
        batch_.push_back(c);
        if (batch_.size() >= kBatch) hand_over();
    }
    void hand_over();
    void apply(const Call& c);         // one call, as it is made (no thread)
    void apply_inline(const Call& c);  // the same, inlined into replay (background_watch.cpp)
    void replay(const std::vector<Call>& calls);
    void work();
    void stop();

    bool direct_ = false;  // no thread: every call is replayed as it is made
    bool on_ = false;  // the last configure switched the watch on (else elements are left out)
    // Calls since the last report / the last report of all: a report without any is left out
    // (it would find nothing).
    bool since_report_ = false, since_all_ = false;
    std::size_t contour_count_ = 0;  // as the watch will count them
    std::vector<Call> batch_;
    // Replaying side: the worker while it runs, settle() after it has been joined.
    OvercutWatch watch_;
    std::vector<Diagnostic> scratch_;
    std::vector<std::pair<std::size_t, Diagnostic>> found_;
    // Between the two.
    std::thread thread_;
    std::mutex mu_;
    std::condition_variable cv_;
    std::deque<std::vector<Call>> queued_;
    std::vector<std::vector<Call>> spare_;
    bool closing_ = false, abandon_ = false;
    bool inline_ = false;  // no thread could be started: batches are replayed by the stage
    std::exception_ptr error_;
};

}  // namespace toolcomp
