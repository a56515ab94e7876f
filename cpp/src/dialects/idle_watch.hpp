#pragma once
// Blocks executed in a row without a move: a program that loops without moving the tool is
// almost surely a mistake (a WHILE whose condition never changes, a jump back to itself), and
// waiting for the block limit (100 million blocks) takes half a minute. Every interpreter
// asks after each block; beyond ControlProfile::no_motion_limit the run stops with
// "no_progress" at the block, while loops that cut run on to block_limit / max_segments.
#include <cstddef>
#include <string>

namespace toolcomp {

class IdleWatch {
public:
    // `moves`: the moves the interpreter has given its sink so far. True once more than
    // `limit` blocks in a row added none.
    bool too_long(std::size_t moves, std::size_t limit) {
        if (moves != moves_) {
            moves_ = moves;
            idle_ = 0;
            return false;
        }
        return ++idle_ > limit;
    }

private:
    std::size_t moves_ = 0, idle_ = 0;
};

inline std::string no_progress_text(std::size_t limit) {
    return "More than " + std::to_string(limit) +
           " blocks executed in a row without a move: an endless loop? (ControlProfile.no_motion_limit)";
}

}  // namespace toolcomp
