#pragma once
// LENTOAX(_AXIND, _MATRIX, _COORD): on which geometry axis each tool length component acts
// (spec §3.2). _AXIND[i] is the 1-based geometry axis (1 X, 2 Y, 3 Z) of L(i+1): standard
// milling in G17 gives (3, 2, 1). _MATRIX row i is the unit vector of L(i+1). Frames,
// mirroring and toolholder rotations are not modelled, so every coordinate system gives the
// axis-parallel result and the status is 0; an unknown coordinate system is status -1
// (value assumed [U]: the manual excerpt gives no status table).
#include <array>
#include <string_view>

#include <Eigen/Core>

#include "toolcomp/tools/sinumerik_edge.hpp"

namespace toolcomp::sinumerik {

struct LentoaxResult {
    int status = 0;
    std::array<int, 3> axind{0, 0, 0};
    Eigen::Matrix<double, 3, 3, Eigen::RowMajor> matrix = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>::Zero();
};

// coord: "MCS"/"M", "BCS"/"B", "WCS"/"W" (default), "KCS"/"K", "TCS"/"T", any case.
LentoaxResult lentoax(int tool_type, Plane plane, const SinumerikLengthSettings& s = {},
                      std::string_view coord = "W");

}  // namespace toolcomp::sinumerik
