#pragma once
// Where a run starts when nothing says where the machine stands (no RunOptions::start, no
// machine): each axis where the program first sends it, so that a path begins at the
// program's first position, not at a machine zero the program knows nothing of.
//
// The program's beginning is interpreted twice, from two machine positions. An axis whose
// coordinate at the end of a move is the same from both was set by the program there (an
// absolute value, G53, G28, a tool change position); the run then starts that axis where that
// move begins less the move's own travel in it, so the move has none. The beginning ends
// where cutter radius compensation comes on (what it does must not depend on a guessed start).
// An axis the program does not set before that, or sets first with an arc, starts at the
// machine's zero, as every axis does when the beginning holds a rotated coordinate system (the
// axes are not apart there).
#include <functional>

#include "toolcomp/run.hpp"

namespace toolcomp {

// Interprets the program's beginning with `options` into `sink` (may throw anything).
using Beginning = std::function<void(const RunOptions& options, MotionSink& sink)>;

// `options` with its start set: as given, the machine's, or the program's first positions.
RunOptions with_start(const RunOptions& options, const Beginning& beginning);

}  // namespace toolcomp
