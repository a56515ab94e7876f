// RunColumn: values kept as runs of equal bits, read back row by row and written out.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "toolcomp/run_column.hpp"

using namespace toolcomp;

namespace {
bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
}  // namespace

TEST_CASE("RunColumn: rows read back bit for bit, runs only where the bits change") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    // NaN, NaN (one run), 600 x3, -0.0, +0.0 (two runs), 600, then 1000 rows of 250
    std::vector<double> pushed{nan, nan, 600, 600, 600, -0.0, 0.0, 600};
    pushed.insert(pushed.end(), 1000, 250);
    RunColumn<double> c;
    for (double v : pushed) c.push(v);
    REQUIRE(c.size() == pushed.size());
    CHECK(c.runs() == 6);
    CHECK(c.bytes() == 6 * 16);
    std::vector<double> out(pushed.size(), 1.0);
    c.write(out.data());
    std::size_t wrong = 0;
    for (std::size_t i = 0; i < pushed.size(); ++i) wrong += !same_bits(c[i], pushed[i]) + !same_bits(out[i], pushed[i]);
    CHECK(wrong == 0);

    // pop_back takes a run back with its last row
    for (int i = 0; i < 1001; ++i) c.pop_back();
    CHECK(c.size() == 7);
    CHECK(c.runs() == 4);
    CHECK(same_bits(c[6], 0.0));
    c.push(0.0);
    CHECK(c.runs() == 4);

    // a move leaves an empty column behind, a copy keeps its rows
    RunColumn<double> copy = c, moved = std::move(c);
    CHECK(c.size() == 0);
    CHECK(moved.size() == 8);
    CHECK(copy.size() == 8);
    CHECK(same_bits(copy[7], 0.0));
    c.push(5);
    CHECK((c.size() == 1 && c[0] == 5));
}
