#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <limits>

#include "toolcomp/column.hpp"

using toolcomp::Vec3Column;

TEST_CASE("Vec3Column stores nothing while every row equals the fill, then every row") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    Vec3Column c(nan, nan, nan);
    c.push(nan, nan, nan);
    c.push(nan, nan, nan);
    CHECK(c.uniform());
    CHECK(c.size() == 2);
    CHECK(std::isnan(c(1, 2)));
    c.push(0, 0, 1);  // differs: the two rows before are written out
    c.push(nan, nan, nan);
    REQUIRE_FALSE(c.uniform());
    CHECK(c.size() == 4);
    CHECK(std::isnan(c(0, 0)));
    CHECK(c(2, 2) == 1);
    CHECK(c.data()[3 * 2 + 2] == 1);
    CHECK(std::isnan(c(3, 1)));
}

TEST_CASE("Vec3Column tells -0.0 from 0.0 (bit for bit)") {
    Vec3Column c(0, 0, 1);
    c.push(-0.0, 0, 1);
    c.push(0, 0, 1);
    CHECK_FALSE(c.uniform());
    CHECK(std::signbit(c(0, 0)));
    CHECK_FALSE(std::signbit(c(1, 0)));
}

TEST_CASE("UniformColumn: the first row is the fill") {
    toolcomp::UniformColumn<std::int32_t, 1> tool;  // constructed with 0
    CHECK(tool.fill()[0] == 0);
    for (int i = 0; i < 5; ++i) tool.push(7);
    CHECK(tool.uniform());
    CHECK(tool.size() == 5);
    CHECK(tool(4) == 7);
    tool.push(3);
    REQUIRE_FALSE(tool.uniform());
    CHECK(tool.size() == 6);
    CHECK(tool.data()[0] == 7);
    CHECK(tool.data()[4] == 7);
    CHECK(tool.data()[5] == 3);
}
