// parse_decimal against std::from_chars, bit for bit, on random decimal texts: 1 to 20
// digits, the point anywhere (or nowhere), leading and trailing zeros.
#include <catch2/catch.hpp>
#include <charconv>
#include <cstring>
#include <random>
#include <string>

#include "random_decimal.hpp"
#include "toolcomp/program/decimal.hpp"
#include "toolcomp/program/expr.hpp"

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

TEST_CASE("expr::read_number: signs, digits and EX exponents as from_chars reads them, and where it stops") {
    std::mt19937_64 rng(7);
    for (int k = 0; k < 100000; ++k) {
        const char* signs[] = {"", "-", "+"};
        const std::string sign = signs[rng() % 3];
        std::string text = sign + random_decimal(rng);
        std::string expected = sign == "+" ? text.substr(1) : text;  // from_chars takes no '+'
        const bool ex = rng() % 4 == 0;
        if (ex) {
            const std::string e = std::string(rng() % 2 ? "-" : "") + std::to_string(rng() % 30);
            text += "EX" + e;
            expected += "e" + e;
        }
        text += "*2";  // what follows the number is not read
        std::size_t pos = 0;
        double a = -1, b = -2;
        INFO(text);
        REQUIRE(toolcomp::expr::read_number(text, pos, a, /*ex_exponent=*/true));
        CHECK(pos == text.size() - 2);
        const auto r = std::from_chars(expected.data(), expected.data() + expected.size(), b);
        REQUIRE(r.ec == std::errc());
        REQUIRE(std::memcmp(&a, &b, sizeof a) == 0);
    }
    std::size_t pos = 0;
    double v = 0;
    CHECK_FALSE(toolcomp::expr::read_number("-.", pos, v, true));
    CHECK_FALSE(toolcomp::expr::read_number("X1", pos, v, true));
    CHECK(toolcomp::expr::read_number("2EX", pos, v, true));  // EX without digits: not an exponent
    CHECK((v == 2 && pos == 1));
    pos = 0;
    CHECK(toolcomp::expr::read_number("3EX2", pos, v, false));  // exponents off (LinuxCNC)
    CHECK((v == 3 && pos == 1));
    pos = 0;
    CHECK_FALSE(toolcomp::expr::read_number("1EX999", pos, v, true));  // out of range
    CHECK(pos == 0);
    CHECK(toolcomp::expr::read_number("-1.25.5", pos, v, true));  // a second point ends the number
    CHECK((v == -1.25 && pos == 5));
    pos = 0;
    CHECK(toolcomp::expr::read_number("0.1234567890123456789Y", pos, v, false));  // past 15 digits: from_chars
    CHECK((v == 0.1234567890123456789 && pos == 21));
}
