#pragma once
// The compensated Path while it is the programmed one. A program without compensation (CAM
// output in tool-centre coordinates, most of what a shop runs) comes out of the stages as
// it went in: every programmed segment passes, unchanged, one for one. Storing it twice is
// half the run's memory and the writing of every row again. This sink sits in front of the
// compensated Path and stores nothing while each segment it is given is the one the
// programmed Path stored last (Path::same_segment, bit for bit); at the first that is not
// (or a programmed segment the stages kept back, or one more) the compensated Path becomes
// the programmed one's segments so far, and from then on segments are pushed into it.
#include <cstddef>

#include "toolcomp/motion/motion.hpp"
#include "toolcomp/page_warmer.hpp"
#include "toolcomp/path.hpp"

namespace toolcomp {

class SharedPath : public MotionSink {
public:
    // `room`: segments to reserve in `path` once it takes its own.
    SharedPath(const Path& nominal, Path& path, std::size_t room) : nominal_(nominal), path_(path), room_(room) {}

    // The programmed Path has stored `m` (the stages are given it next).
    void programmed(const Motion& m) {
        if (!same_) return;
        if (pending_) return diverge();  // the one before it was kept back
        last_ = m;
        pending_ = true;
    }
    void push(const Motion& m) override {
        if (same_ && pending_ && Path::same_segment(last_, m)) {
            pending_ = false;
            ++rows_;
            return;
        }
        diverge();
        path_.push(m);
    }
    // Whether the compensated path is the programmed one (every segment passed unchanged);
    // else it is in `path`.
    bool settle() {
        if (same_ && (pending_ || rows_ != nominal_.size())) diverge();
        return same_;
    }
    void warm_with(PageWarmer* warmer) {
        warmer_ = warmer;
        if (!same_) path_.warm_with(warmer);
    }

private:
    void diverge() {
        if (!same_) return;
        same_ = false;
        path_ = Path(nominal_, rows_);
        path_.reserve_granted(room_);
        path_.warm_with(warmer_);
    }

    const Path& nominal_;
    Path& path_;
    std::size_t room_;
    PageWarmer* warmer_ = nullptr;
    bool same_ = true;      // every segment so far is the programmed path's
    bool pending_ = false;  // last_ is stored in the programmed Path, not yet given here
    std::size_t rows_ = 0;  // segments given here so far
    Motion last_;
};

}  // namespace toolcomp
