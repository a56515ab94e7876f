// SharedPath and the Path prefix it starts from: the compensated path stored once it
// differs from the programmed one is, row for row, the Path the same segments pushed into an
// empty Path give.
#include <catch2/catch.hpp>

#include <cstring>
#include <vector>

#include "../../cpp/src/shared_path.hpp"
#include "toolcomp/path.hpp"

using namespace toolcomp;

namespace {
// Lines and arcs, a jump every 97th, the feed changing every 50th, a tool change at 400 and
// rotary axes that start to vary at 700 (the uniform columns stored from there).
Motion segment_no(int i) {
    Motion m;
    const bool arc = i % 3 == 1;
    m.kind = arc ? MotionKind::arc_ccw : (i % 11 == 0 ? MotionKind::rapid : MotionKind::line);
    m.start = Vec3(i, i % 4, 0);
    m.end = Vec3(i + 1, (i + 1) % 4, 0);
    if (i % 97 == 0) m.start.x() += 0.25;
    if (arc) m.center = Vec3(i + 0.5, 3, 0);
    m.feed = m.kind == MotionKind::rapid ? std::numeric_limits<double>::quiet_NaN() : 100 + 10 * (i / 50);
    m.line = i + 1;
    m.tool = i < 400 ? 1 : 2;
    if (i >= 700) m.abc = {0, 0, 0.5 * i};
    return m;
}

bool same_bits(const Vec3& a, const Vec3& b) { return std::memcmp(a.data(), b.data(), sizeof(Vec3)) == 0; }

// Every row of `a` is the row of `b`, bit for bit, and both store the same way (neither with
// rows written out yet).
void check_same(const Path& a, const Path& b) {
    REQUIRE(a.size() == b.size());
    std::size_t wrong = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const Motion x = a.segment(i), y = b.segment(i);
        wrong += !Path::same_segment(x, y) || !same_bits(x.center, y.center) || x.generated != y.generated;
    }
    CHECK(wrong == 0);
    CHECK(a.bytes() == b.bytes());
    CHECK(a.tool.uniform() == b.tool.uniform());
    CHECK(a.abc.uniform() == b.abc.uniform());
    if (a.size() == 0) return;  // nothing written out (and no memory to compare)
    const auto as = a.starts(), bs = b.starts(), ac = a.centers(), bc = b.centers(), af = a.feeds(), bf = b.feeds();
    CHECK(std::memcmp(as.data(), bs.data(), as.size_bytes()) == 0);
    CHECK(std::memcmp(ac.data(), bc.data(), ac.size_bytes()) == 0);
    CHECK(std::memcmp(af.data(), bf.data(), af.size_bytes()) == 0);
}
}  // namespace

TEST_CASE("Path prefix: the first rows stored as the whole stores them; pushing on gives the whole") {
    const int n = 1000;
    Path whole;
    for (int i = 0; i < n; ++i) whole.push(segment_no(i));
    for (int k : {0, 1, 2, 97, 98, 255, 256, 257, 399, 400, 401, 699, 700, 701, 999, 1000}) {
        INFO("prefix of " << k);
        Path prefix(whole, static_cast<std::size_t>(k));
        Path expected;
        for (int i = 0; i < k; ++i) expected.push(segment_no(i));
        check_same(prefix, expected);
        for (int i = k; i < n; ++i) prefix.push(segment_no(i));
        check_same(Path(prefix), Path(whole));  // copies: without the rows written out before
    }
}

namespace {
// Runs `steps` through an SharedPath: for each programmed segment, what the stages emit
// after it is stored (the same segment, another, none, two). Returns the compensated Path
// (the programmed one when unchanged) and checks it against the emitted segments pushed into
// an empty Path.
struct Step {
    int programmed;             // segment_no of the programmed segment
    std::vector<int> emitted;   // segment_no of what the stages emit then (offset by 5000: changed)
};
bool run_steps(const std::vector<Step>& steps) {
    Path nominal, path, expected;
    SharedPath unchanged(nominal, path, 4096);
    for (const Step& s : steps) {
        nominal.push(segment_no(s.programmed));
        unchanged.programmed(segment_no(s.programmed));
        for (int e : s.emitted) {
            Motion m = segment_no(e % 5000);
            if (e >= 5000) m.end.y() += 1e-9;  // a compensated segment: not the programmed one
            unchanged.push(m);
            expected.push(m);
        }
    }
    const bool same = unchanged.settle();
    check_same(same ? nominal : path, expected);
    return same;
}
}  // namespace

TEST_CASE("SharedPath: stored once while every segment passes unchanged, else the emitted segments") {
    std::vector<Step> all_same;
    for (int i = 0; i < 900; ++i) all_same.push_back({i, {i}});
    CHECK(run_steps(all_same));

    SECTION("one segment changed in the middle") {
        auto s = all_same;
        s[500].emitted = {5500};
        CHECK_FALSE(run_steps(s));
    }
    SECTION("a segment kept back and emitted with the next (a held move)") {
        auto s = all_same;
        s[300].emitted = {};
        s[301].emitted = {300, 301};
        CHECK_FALSE(run_steps(s));
    }
    SECTION("a segment more (a corner arc)") {
        auto s = all_same;
        s[256].emitted = {256, 5256};
        CHECK_FALSE(run_steps(s));
    }
    SECTION("the last segment kept back for good (a run ended by an error)") {
        auto s = all_same;
        s.back().emitted = {};
        CHECK_FALSE(run_steps(s));
    }
    SECTION("the first segment changed") {
        auto s = all_same;
        s[0].emitted = {5000};
        CHECK_FALSE(run_steps(s));
    }
    SECTION("nothing at all") { CHECK(run_steps({})); }
}
