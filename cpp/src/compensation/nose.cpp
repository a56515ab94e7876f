#include "toolcomp/compensation/nose.hpp"

namespace toolcomp {

TipVector tip_vector(int tip, TipConvention convention) {
    TipVector v;
    switch (tip) {
        case 1: v = {-1, +1}; break;
        case 2: v = {-1, -1}; break;
        case 3: v = {+1, -1}; break;
        case 4: v = {+1, +1}; break;
        case 5: v = {0, +1}; break;
        case 6: v = {-1, 0}; break;
        case 7: v = {0, -1}; break;
        case 8: v = {+1, 0}; break;
        default: return {};  // 0, 9: the centre itself is programmed
    }
    if (convention == TipConvention::fanuc) v.x = -v.x;
    return v;
}

int convert_tip(int tip, TipConvention from, TipConvention to) {
    if (from == to) return tip;
    switch (tip) {
        case 1: return 4;
        case 4: return 1;
        case 2: return 3;
        case 3: return 2;
        case 6: return 8;
        case 8: return 6;
        default: return tip;
    }
}

}  // namespace toolcomp
