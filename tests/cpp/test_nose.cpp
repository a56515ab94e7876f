// Tip numbers: the direction of the imaginary tip from the nose centre (spec §4.4 tables).
#include <catch2/catch.hpp>

#include "toolcomp/compensation/nose.hpp"

using namespace toolcomp;

TEST_CASE("tip vectors in LinuxCNC and Fanuc/Haas numbering") {
    struct Row {
        int tip, lx, lz, fx, fz;
    };
    // spec 4.4: LinuxCNC 1 (-X,+Z) 2 (-X,-Z) 3 (+X,-Z) 4 (+X,+Z) 5 +Z 6 -X 7 -Z 8 +X;
    // Fanuc/Haas 1 (+X,+Z) 2 (+X,-Z) 3 (-X,-Z) 4 (-X,+Z) 5 +Z 6 +X 7 -Z 8 -X.
    const Row rows[] = {{1, -1, 1, 1, 1},  {2, -1, -1, 1, -1}, {3, 1, -1, -1, -1}, {4, 1, 1, -1, 1},
                        {5, 0, 1, 0, 1},   {6, -1, 0, 1, 0},   {7, 0, -1, 0, -1},  {8, 1, 0, -1, 0},
                        {0, 0, 0, 0, 0},   {9, 0, 0, 0, 0}};
    for (const Row& r : rows) {
        INFO("tip " << r.tip);
        auto l = tip_vector(r.tip, TipConvention::linuxcnc);
        auto f = tip_vector(r.tip, TipConvention::fanuc);
        CHECK((l.x == r.lx && l.z == r.lz));
        CHECK((f.x == r.fx && f.z == r.fz));
        // The same physical tool has the other number in the other numbering.
        auto same = tip_vector(convert_tip(r.tip, TipConvention::fanuc, TipConvention::linuxcnc), TipConvention::linuxcnc);
        CHECK((same.x == f.x && same.z == f.z));
    }
}
