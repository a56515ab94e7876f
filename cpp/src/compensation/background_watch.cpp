// The overcut watch replayed on its own thread (see background_watch.hpp).
#include "toolcomp/compensation/background_watch.hpp"

#include <system_error>

namespace toolcomp {

BackgroundWatch::~BackgroundWatch() {
    if (!thread_.joinable()) return;
    {
        std::lock_guard<std::mutex> lk(mu_);
        abandon_ = closing_ = true;
    }
    cv_.notify_all();
    thread_.join();
}

void BackgroundWatch::configure(int neighbours, double tolerance) {
    if (!direct_ && batch_.capacity() == 0) batch_.reserve(kBatch);
    on_ = neighbours > 0;
    record({Op::configure, false, neighbours, 0, tolerance, 0, {}});
}

void BackgroundWatch::tangent_slack(double slack) { record({Op::tangent_slack, false, 0, 0, slack, 0, {}}); }

void BackgroundWatch::scale(double f) { record({Op::scale, false, 0, 0, f, 0, {}}); }

[[gnu::always_inline]] inline void BackgroundWatch::apply_inline(const Call& c) {
    switch (c.op) {
        case Op::configure: watch_.configure(c.line, c.a); break;
        case Op::programmed: watch_.programmed(c.e, c.line); break;
        case Op::tangent_slack: watch_.tangent_slack(c.a); break;
        case Op::compensated: watch_.compensated(c.e, c.line, c.file, c.a, c.at); break;
        case Op::scale: watch_.scale(c.a); break;
        case Op::report:
            scratch_.clear();
            watch_.report(scratch_, c.a, c.all);
            for (Diagnostic& d : scratch_) found_.emplace_back(c.at, std::move(d));
            break;
    }
}

void BackgroundWatch::apply(const Call& c) { apply_inline(c); }

void BackgroundWatch::replay(const std::vector<Call>& calls) {
    for (const Call& c : calls) apply_inline(c);
}

// The full batch goes to the thread (started with the first one); while kQueued batches
// wait, the stage waits.
void BackgroundWatch::hand_over() {
    if (!thread_.joinable() && !inline_) {
        try {
            thread_ = std::thread(&BackgroundWatch::work, this);
        } catch (const std::system_error&) {
            inline_ = true;  // no thread to be had: the watch runs here, as it would directly
        }
    }
    if (inline_) {
        replay(batch_);
        batch_.clear();
        return;
    }
    std::vector<Call> next;
    {
        std::unique_lock<std::mutex> lk(mu_);
        cv_.wait(lk, [this] { return queued_.size() < kQueued || error_; });
        if (error_) {  // the thread has stopped; settle() reports why
            batch_.clear();
            return;
        }
        queued_.push_back(std::move(batch_));
        if (!spare_.empty()) {
            next = std::move(spare_.back());
            spare_.pop_back();
        }
    }
    cv_.notify_all();
    batch_ = std::move(next);
    batch_.clear();
    batch_.reserve(kBatch);
}

void BackgroundWatch::work() {
    std::unique_lock<std::mutex> lk(mu_);
    for (;;) {
        cv_.wait(lk, [this] { return !queued_.empty() || closing_; });
        if (abandon_ || queued_.empty()) return;
        std::vector<Call> calls = std::move(queued_.front());
        queued_.pop_front();
        lk.unlock();
        cv_.notify_all();  // room for the stage's next batch
        try {
            replay(calls);
        } catch (...) {
            lk.lock();
            error_ = std::current_exception();
            cv_.notify_all();
            return;
        }
        calls.clear();
        lk.lock();
        spare_.push_back(std::move(calls));
    }
}

void BackgroundWatch::settle(std::vector<Diagnostic>& diags) {
    if (thread_.joinable()) {
        {
            std::lock_guard<std::mutex> lk(mu_);
            closing_ = true;
        }
        cv_.notify_all();
        thread_.join();
        closing_ = false;
        queued_.clear();
    }
    if (error_) {
        std::exception_ptr e = error_;
        error_ = nullptr;
        batch_.clear();
        std::rethrow_exception(e);
    }
    replay(batch_);
    batch_.clear();
    if (found_.empty()) return;
    std::vector<Diagnostic> merged;
    merged.reserve(diags.size() + found_.size());
    std::size_t i = 0;
    for (auto& [at, d] : found_) {
        for (; i < at && i < diags.size(); ++i) merged.push_back(std::move(diags[i]));
        merged.push_back(std::move(d));
    }
    for (; i < diags.size(); ++i) merged.push_back(std::move(diags[i]));
    diags.swap(merged);
    found_.clear();
}

}  // namespace toolcomp
