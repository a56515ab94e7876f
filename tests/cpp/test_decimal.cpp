// parse_decimal against std::from_chars, bit for bit, on random decimal texts: 1 to 20
// digits, the point anywhere (or nowhere), leading and trailing zeros.
#include <catch2/catch.hpp>
#include <charconv>
#include <cstring>
#include <random>
#include <string>

#include "random_decimal.hpp"
#include "toolcomp/program/decimal.hpp"

TEST_CASE("parse_decimal rounds as from_chars does") {
    std::mt19937_64 rng(42);
    for (int k = 0; k < 200000; ++k) {
        const std::string s = random_decimal(rng);
        double a = -1, b = -2;
        REQUIRE(toolcomp::parse_decimal(s, a));
        const auto r = std::from_chars(s.data(), s.data() + s.size(), b);
        REQUIRE(r.ec == std::errc());
        INFO(s);
        REQUIRE(std::memcmp(&a, &b, sizeof a) == 0);
    }
}

TEST_CASE("parse_decimal refuses what is not a plain decimal") {
    double v = 0;
    CHECK_FALSE(toolcomp::parse_decimal("", v));
    CHECK_FALSE(toolcomp::parse_decimal(".", v));
    CHECK_FALSE(toolcomp::parse_decimal("1.2.3", v));
    CHECK_FALSE(toolcomp::parse_decimal("1e5", v));
    CHECK(toolcomp::parse_decimal("0.1", v));
    CHECK(v == 0.1);
    CHECK(toolcomp::parse_decimal("95.", v));
    CHECK(v == 95);
}
