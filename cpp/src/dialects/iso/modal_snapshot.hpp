#pragma once
// LinuxCNC's M70/M73 snapshot of the modal state, one per call level (interp_modal_state.cpp).
#include <array>

namespace toolcomp::iso {

struct ModalSnapshot {
    // G codes x 10 by LinuxCNC's slots (3 plane, 4 radius comp, 5 units, 6 distance, 7 feed
    // mode, 8 coordinate system, 9 length offset, 10 retract, 11 path control, 13 spindle
    // mode, 14 arc distance, 15 lathe diameter, 16 G92 applied), -1 where unused.
    std::array<int, 17> g{};
    // M codes x 10 by slot (2 spindle, 4 mist, 5 flood, 6 overrides, 7 adaptive feed, 8 feed
    // hold); -1 where unused or (4, 5, 7, 8) where the restore leaves the slot alone.
    std::array<int, 9> m{};
    double feed = 0;   // program units per minute (G93: the inverse-time rate)
    double speed = 0;  // S
    double tolerance = 0, naivecam = 0;  // G64 P and Q, as given
    bool valid = false;              // M70 or M73 saved it, no M71 since
    bool restore_on_return = false;  // M73 in a subroutine: restored when it returns
};

}  // namespace toolcomp::iso
