// Path: segments pushed, copied and moved keep their rows; a Path copied or moved from can
// take more segments (its room follows its columns' capacity). PageWarmer: pages faulted in
// ahead of a Path being filled, its rows unchanged.
#include <catch2/catch.hpp>

#include <sys/mman.h>

#include <cstring>
#include <utility>
#include <vector>

#include "toolcomp/page_warmer.hpp"
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

TEST_CASE("PageWarmer: pages faulted in, what is written left as it is") {
    if (!PageWarmer::available()) {
        WARN("no MADV_POPULATE_WRITE on this system: nothing to check");
        return;
    }
    const std::size_t bytes = std::size_t{8} << 20;
    void* raw = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);  // fresh
    REQUIRE(raw != MAP_FAILED);
    auto* p = static_cast<unsigned char*>(raw);
    p[0] = 7;
    p[bytes / 2 + 5] = 9;
    const auto resident = [&] {
        std::vector<unsigned char> in(bytes / 4096);
        REQUIRE(mincore(raw, bytes, in.data()) == 0);
        std::size_t n = 0;
        for (unsigned char c : in) n += c & 1;
        return n;
    };
    CHECK(resident() < bytes / 4096);
    {
        PageWarmer w;
        w.warm(p + 100, bytes - 200);  // not page aligned: the pages around it
        w.drain();
        CHECK(resident() == bytes / 4096);
    }
    CHECK(p[0] == 7);
    CHECK(p[bytes / 2 + 5] == 9);
    std::size_t nonzero = 0;
    for (std::size_t i = 0; i < bytes; ++i) nonzero += p[i] != 0;
    CHECK(nonzero == 2);
    munmap(raw, bytes);
}

TEST_CASE("Path: rows written while a warmer faults the pages ahead are the rows pushed") {
    const int n = 700'000;  // past the reservation a warmer is used for
    Path warmed, plain;
    warmed.reserve(300'000);  // grows twice while warmed
    plain.reserve(300'000);
    {
        PageWarmer w;
        warmed.warm_with(&w);
        for (int i = 0; i < n; ++i) {
            Motion m = move_to(i);
            m.tool = 1 + i / 200'000;
            warmed.push(m);
            plain.push(m);
        }
        warmed.warm_with(nullptr);
    }
    REQUIRE(warmed.size() == plain.size());
    for (auto col : {&Path::start, &Path::end, &Path::center, &Path::feed})
        CHECK(std::memcmp((warmed.*col).data(), (plain.*col).data(), (plain.*col).size() * sizeof(double)) == 0);
    CHECK(std::memcmp(warmed.line.data(), plain.line.data(), plain.line.size() * sizeof(std::int32_t)) == 0);
    CHECK(std::memcmp(warmed.kind.data(), plain.kind.data(), plain.kind.size()) == 0);
    CHECK(warmed.tool(699'999) == 4);
    CHECK(warmed.end[3 * 699'999] == 699'999);
}
