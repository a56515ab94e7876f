#include "toolcomp/page_warmer.hpp"

#include <cerrno>
#include <cstdint>
#if defined(__linux__)
#include <pthread.h>
#include <sched.h>
#include <sys/mman.h>
#endif

namespace toolcomp {

namespace {
constexpr std::size_t kPage = 4096;

#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
// Faults the pages of [p, p + bytes) in, writable; false when the kernel does not know how.
bool populate(void* p, std::size_t bytes) {
    const auto from = reinterpret_cast<std::uintptr_t>(p) / kPage * kPage;
    const auto to = (reinterpret_cast<std::uintptr_t>(p) + bytes + kPage - 1) / kPage * kPage;
    return madvise(reinterpret_cast<void*>(from), to - from, MADV_POPULATE_WRITE) == 0 || errno != EINVAL;
}
#else
bool populate(void*, std::size_t) { return false; }
#endif
}  // namespace

bool PageWarmer::available() {
    static const bool yes = [] {
        // A page of our own, asked for once: EINVAL means the kernel has no MADV_POPULATE_WRITE.
        alignas(kPage) static char probe[kPage];
        return populate(probe, kPage);
    }();
    return yes;
}

PageWarmer::~PageWarmer() {
    {
        std::lock_guard<std::mutex> lock(mu_);
        stop_ = true;
        queue_.clear();
    }
    cv_.notify_all();
    if (thread_.joinable()) thread_.join();
}

void PageWarmer::warm(void* p, std::size_t bytes) noexcept {
    if (bytes == 0 || !available()) return;
    try {
        {
            std::lock_guard<std::mutex> lock(mu_);
            queue_.emplace_back(p, bytes);
            if (!thread_.joinable()) {
                thread_ = std::thread([this] {
#if defined(__linux__) && defined(SCHED_IDLE)
                    // Idle time only: the run's other threads (the overcut watch, the next
                    // piece's parse) come first; pages it does not reach, the run faults in.
                    sched_param none{};
                    pthread_setschedparam(pthread_self(), SCHED_IDLE, &none);
#endif
                    loop();
                });
            }
        }
        cv_.notify_all();
    } catch (...) {
        // No memory for the request or no thread to be had: warming is a head start only,
        // the filling thread faults its pages itself.
        std::lock_guard<std::mutex> lock(mu_);
        if (!thread_.joinable()) queue_.clear();
    }
}

void PageWarmer::drain() {
    std::unique_lock<std::mutex> lock(mu_);
    cv_.wait(lock, [this] { return queue_.empty() && !busy_; });
}

void PageWarmer::loop() {
    std::unique_lock<std::mutex> lock(mu_);
    for (;;) {
        cv_.wait(lock, [this] { return stop_ || !queue_.empty(); });
        if (stop_) return;
        const auto [p, bytes] = queue_.front();
        queue_.erase(queue_.begin());
        busy_ = true;
        lock.unlock();
        populate(p, bytes);  // a range freed meanwhile: ENOMEM, nothing done
        lock.lock();
        busy_ = false;
        if (queue_.empty()) cv_.notify_all();  // drain()
    }
}

}  // namespace toolcomp
