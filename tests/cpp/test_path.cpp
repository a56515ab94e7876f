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
    CHECK(std::memcmp(warmed.end.data(), plain.end.data(), plain.end.size() * sizeof(double)) == 0);
    for (auto rows : {&Path::starts, &Path::centers})
        CHECK(std::memcmp((warmed.*rows)().data(), (plain.*rows)().data(), 3 * n * sizeof(double)) == 0);
    CHECK(std::memcmp(warmed.feeds().data(), plain.feeds().data(), n * sizeof(double)) == 0);
    CHECK(std::memcmp(warmed.line.data(), plain.line.data(), plain.line.size() * sizeof(std::int32_t)) == 0);
    CHECK(std::memcmp(warmed.kind.data(), plain.kind.data(), plain.kind.size()) == 0);
    CHECK(warmed.tool(699'999) == 4);
    CHECK(warmed.end[3 * 699'999] == 699'999);
}

namespace {
// A contour of lines and arcs that runs on from end to end, with a jump (a new tool length
// offset moves the start) every 97th segment and a -0.0 start after a +0.0 end every 89th.
Motion contour(int i) {
    Motion m;
    const bool arc = i % 3 != 0 && i % 7 != 0;
    m.kind = arc ? (i % 2 ? MotionKind::arc_ccw : MotionKind::arc_cw) : MotionKind::line;
    m.start = Vec3(i, i % 5, 0);
    m.end = Vec3(i + 1, (i + 1) % 5, 0);
    if (i % 97 == 0) m.start.y() += 0.5;
    if (i % 89 == 0) m.start.z() = -0.0;
    if (arc) m.center = Vec3(i + 0.5, 10 + i, -1);
    m.line = i + 1;
    return m;
}
void check_contour(const Path& p, int n) {
    REQUIRE(p.size() == static_cast<std::size_t>(n));
    const auto starts = p.starts(), centers = p.centers();
    REQUIRE(starts.size() == 3 * static_cast<std::size_t>(n));
    REQUIRE(centers.size() == 3 * static_cast<std::size_t>(n));
    std::size_t mismatched = 0;
    for (int i = 0; i < n; ++i) {
        const Motion m = contour(i);
        const auto r = static_cast<std::size_t>(i);
        const Vec3 s = p.start_at(r), c = p.center_at(r);
        // bit for bit: -0.0 stays -0.0, a line's centre is NaN
        mismatched += std::memcmp(s.data(), m.start.data(), sizeof(Vec3)) != 0;
        mismatched += std::memcmp(starts.data() + 3 * r, m.start.data(), sizeof(Vec3)) != 0;
        mismatched += std::memcmp(p.segment(r).start.data(), m.start.data(), sizeof(Vec3)) != 0;
        if (m.is_arc()) {
            mismatched += c != m.center;
            mismatched += Vec3(centers[3 * r], centers[3 * r + 1], centers[3 * r + 2]) != m.center;
        } else {
            mismatched += !(std::isnan(c.x()) && std::isnan(c.y()) && std::isnan(c.z()));
            mismatched += !std::isnan(centers[3 * r]) + !std::isnan(centers[3 * r + 2]);
        }
    }
    CHECK(mismatched == 0);
    if (n > 90) {
        CHECK(std::signbit(p.start_at(89).z()));
        CHECK(!std::signbit(p.start_at(90).z()));
    }
}
}  // namespace

TEST_CASE("Path: starts kept as jumps and centres as arcs' read back as pushed, written out when asked") {
    Path p;
    const int n = 3 * 256 + 41;  // several rank stretches and a part one
    for (int i = 0; i < n; ++i) p.push(contour(i));
    check_contour(p, n);
    // Fewer bytes than 9 doubles a segment before starts and centres are written out, 6 more after.
    Path fresh;
    for (int i = 0; i < n; ++i) fresh.push(contour(i));
    const std::size_t stored = fresh.bytes();
    CHECK(stored < 60 * static_cast<std::size_t>(n));
    (void)fresh.starts();
    (void)fresh.centers();
    CHECK(fresh.bytes() == stored + 48 * static_cast<std::size_t>(n));

    // A push after the rows were written out: they are written anew.
    p.push(contour(n));
    check_contour(p, n + 1);
    // A copy writes its own; a move takes them along.
    Path copy = p;
    copy.push(contour(n + 1));
    check_contour(copy, n + 2);
    check_contour(p, n + 1);
    Path moved = std::move(p);
    check_contour(moved, n + 1);
    for (int i = 0; i < 5; ++i) p.push(contour(i));
    check_contour(p, 5);
}

TEST_CASE("Path: arc centres across rank stretches of arcs only and of lines only") {
    Path p;
    std::vector<Motion> pushed;
    for (int i = 0; i < 2000; ++i) {
        Motion m;
        const bool arc = (i / 300) % 2 == 0;  // 300 arcs, 300 lines, ...
        m.kind = arc ? MotionKind::arc_cw : MotionKind::line;
        m.start = Vec3(i, 0, 0);
        m.end = Vec3(i + 1, 0, 0);
        if (arc) m.center = Vec3(i + 0.5, -i, 0);
        p.push(m);
        pushed.push_back(m);
    }
    std::size_t mismatched = 0;
    for (std::size_t i = 0; i < pushed.size(); ++i) {
        const Vec3 c = p.center_at(i);
        mismatched += pushed[i].is_arc() ? c != pushed[i].center : !std::isnan(c.y());
    }
    CHECK(mismatched == 0);
}
