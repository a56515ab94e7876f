#pragma once
// How long a path takes on its machine: an estimate from the programmed feeds and the
// machine's rates, without acceleration (doc/cycle-time.md).
//
// A rapid runs every axis at its rapid rate and takes as long as its slowest axis (the
// moves are coordinated, as on LinuxCNC and with Fanuc's linear rapids). A feed move runs at
// its feed along the path, slowed where an axis would pass its highest feed: a line by each
// axis's share of the move, an arc by the lower highest feed of its plane's two axes (each
// runs at the full path speed somewhere on a quarter turn) and its helix axis by its share.
#include <cstddef>
#include <vector>

#include "toolcomp/control/rates.hpp"
#include "toolcomp/path.hpp"

namespace toolcomp {

// Seconds each segment takes (NaN for a feed move whose feed is not a positive number).
std::vector<double> segment_seconds(const Path& path, const MachineRates& rates);

// How often the tool in the spindle changes along the path: each time the tool column
// changes from one segment to the next, and once before the first segment when it has a
// tool (the run starts with none).
/// how often the tool changes along the path (a first tool counts: the run starts with none)
std::size_t tool_changes(const Path& path);

}  // namespace toolcomp
