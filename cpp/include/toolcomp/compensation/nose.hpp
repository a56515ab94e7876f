#pragma once
// Lathe tool-nose radius: where the imaginary tool tip P lies as seen from the nose centre C
// (spec §1.10, §4.4): P = C + r·(σx, σz), from the tip number (orientation) 0..9 as the
// tool table gives it. The number means different directions in different numberings.
#include "toolcomp/geometry/vec.hpp"

namespace toolcomp {

/// Numbering of lathe tool tip directions (orientation 0..9).
enum class TipConvention {
    /// LinuxCNC: 1 (-X,+Z), 2 (-X,-Z), 3 (+X,-Z), 4 (+X,+Z), 5 +Z, 6 -X, 7 -Z, 8 +X; 0 and 9 centre
    linuxcnc = 0,
    /// Fanuc/Haas: as linuxcnc with the sign of X flipped (1<->4, 2<->3, 6<->8)
    fanuc = 1,     // Fanuc/Haas: the same with the sign of X flipped (1<->4, 2<->3, 6<->8)
};

struct TipVector {
    int x = 0, z = 0;  // σx, σz ∈ {-1, 0, +1}; both 0 for tips 0 and 9 (centre programming)
};

TipVector tip_vector(int tip, TipConvention convention);

// The tip number of the other numbering for the same physical tool.
int convert_tip(int tip, TipConvention from, TipConvention to);

}  // namespace toolcomp
