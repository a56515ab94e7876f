// Path: segments pushed, copied and moved keep their rows; a Path copied or moved from can
// take more segments (its room follows its columns' capacity).
#include <catch2/catch.hpp>

#include <utility>

#include "toolcomp/path.hpp"

using namespace toolcomp;

namespace {
Motion move_to(int i) {
    Motion m;
    m.kind = MotionKind::line;
    m.start = Vec3(i - 1, 0, 0);
    m.end = Vec3(i, 2.0 * i, -1);
    m.line = i;
    m.feed = 100 + i;
    m.tool = i >= 1500 ? 2 : 1;  // the tool column stops being uniform half way
    return m;
}
void check_rows(const Path& p, int from, int to) {
    REQUIRE(p.size() == static_cast<std::size_t>(to - from));
    for (int i = from; i < to; ++i) {
        const std::size_t r = static_cast<std::size_t>(i - from);
        INFO("row " << r);
        CHECK(p.end[3 * r] == i);
        CHECK(p.end[3 * r + 1] == 2.0 * i);
        CHECK(p.line[r] == i);
        CHECK(p.feed[r] == 100 + i);
        CHECK(p.tool(r) == (i >= 1500 ? 2 : 1));
    }
}
}  // namespace

TEST_CASE("Path: rows past the first reservation, in a copy and after a move") {
    Path a;
    for (int i = 0; i < 3000; ++i) a.push(move_to(i));
    check_rows(a, 0, 3000);

    Path copy = a;
    copy.push(move_to(3000));
    check_rows(copy, 0, 3001);
    check_rows(a, 0, 3000);

    Path moved = std::move(a);
    check_rows(moved, 0, 3000);
    // The moved-from Path has no columns left: pushing reserves anew.
    Path& empty = a;
    for (int i = 0; i < 1100; ++i) empty.push(move_to(i));
    check_rows(empty, 0, 1100);

    Path assigned;
    assigned.push(move_to(0));
    assigned = std::move(moved);
    check_rows(assigned, 0, 3000);
    for (int i = 0; i < 10; ++i) moved.push(move_to(i));
    check_rows(moved, 0, 10);
}
