#pragma once
// The rates a machine moves at, for the time a path takes (analysis/cycle_time.hpp).
#include <array>

namespace toolcomp {

// mm/min per axis X Y Z; 0: not given.
struct MachineRates {
    std::array<double, 3> rapid{0, 0, 0};     // 0: kDefaultRapidRate
    std::array<double, 3> max_feed{0, 0, 0};  // 0: no limit beyond the programmed feed
    double tool_change_seconds = 0;           // chip to chip, each tool change
};

// The rapid rate an axis is taken to run at where the machine gives none, mm/min.
inline constexpr double kDefaultRapidRate = 10000;

}  // namespace toolcomp
