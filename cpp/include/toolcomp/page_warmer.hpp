#pragma once
// PageWarmer: fresh memory faulted in on another thread, ahead of the thread that fills it.
//
// The first write to a fresh page costs a page fault in which the kernel zeroes the page (2 MB
// at once for the columns' transparent huge pages): for a million-block run about 220 MB of
// Path columns, a large share of the run's own thread. A Path given a warmer asks it, a
// stretch of rows ahead of the rows being written, to fault in the pages of the next
// stretch with madvise(MADV_POPULATE_WRITE), on a thread of its own that runs in idle time
// only (SCHED_IDLE): the pages are made present and writable, their contents untouched. The warmer never writes, so it never
// races with the filling thread: where it lags behind, that thread faults the page itself,
// and a range freed meanwhile is refused (ENOMEM) or warmed for nothing. Without
// MADV_POPULATE_WRITE (Linux before 5.14, other systems) it does nothing.
#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

namespace toolcomp {

class PageWarmer {
public:
    PageWarmer() = default;
    PageWarmer(const PageWarmer&) = delete;
    PageWarmer& operator=(const PageWarmer&) = delete;
    ~PageWarmer();  // requests not yet served are dropped, the thread is joined

    // Queues [p, p + bytes) to be faulted in; returns at once. The thread starts with the
    // first request. Never fails: without memory or a thread the pages are left as they are.
    void warm(void* p, std::size_t bytes) noexcept;
    // Waits until every request made so far is served.
    void drain();
    // Whether the system can warm pages at all (else warm() does nothing).
    static bool available();

private:
    void loop();

    std::mutex mu_;
    std::condition_variable cv_;
    std::vector<std::pair<void*, std::size_t>> queue_;
    bool busy_ = false;  // a request taken from the queue is being served
    bool stop_ = false;
    std::thread thread_;
};

}  // namespace toolcomp
