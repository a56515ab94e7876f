#pragma once
// The M functions of the Heidenhain dialect by name. The interpreter compares M functions by
// these names only.

namespace toolcomp::heidenhain {

enum MFunction : int {
    M0 = 0, M1 = 1, M2 = 2, M3 = 3, M4 = 4, M5 = 5, M6 = 6, M8 = 8, M9 = 9, M13 = 13, M14 = 14, M30 = 30,
    M89 = 89, M90 = 90, M91 = 91, M92 = 92, M97 = 97, M98 = 98, M99 = 99, M107 = 107, M108 = 108, M120 = 120,
    M126 = 126, M127 = 127, M128 = 128, M129 = 129, M140 = 140,
};

}  // namespace toolcomp::heidenhain
