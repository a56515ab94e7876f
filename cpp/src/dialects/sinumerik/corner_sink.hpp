#pragma once
// The 840D's contour corners RND= (a rounding arc), CHF= (a chamfer of that length) and CHR=
// (a chamfer whose legs have that length), programmed in a block for the corner at its end:
// the block's move is held until the next move is known, both are cut back to the corner
// element, and the three go on in order. A control event between them ends the hold (the
// corner needs the next path move): an error, as is a corner next to a rapid or a helix.
#include <optional>

#include "toolcomp/motion/motion.hpp"

namespace toolcomp::sinumerik {

enum class CornerKind { rounding, chamfer_length, chamfer_legs };

struct CornerRequest {
    CornerKind kind;
    double size;      // mm
    int line, column;
};

class CornerSink : public MotionSink {
public:
    explicit CornerSink(MotionSink& out) : out_(out) {}
    // The next move pushed ends at a corner of this kind.
    void request(const CornerRequest& r) { request_ = r; }
    // A run stopped by an error: the held move goes on as programmed (the path up to the error).
    void abandon();
    void push(const Motion& m) override;
    void control(const ControlEvent& e) override;
    void finish() override;

private:
    void corner(Motion& held, Motion& next, const CornerRequest& r);
    MotionSink& out_;
    std::optional<CornerRequest> request_;  // for the move pushed next
    std::optional<Motion> held_;            // a move whose corner waits for the next move
    CornerRequest held_request_{};
};

}  // namespace toolcomp::sinumerik
