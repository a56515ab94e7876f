// ShortText: a token's text in 8 bytes, in place up to 6 characters, on the heap beyond.
#include <catch2/catch.hpp>

#include <string>
#include <utility>
#include <vector>

#include "toolcomp/program/short_text.hpp"

using toolcomp::ShortText;

TEST_CASE("ShortText holds texts of every length, in place and on the heap") {
    for (std::size_t n = 0; n <= 40; ++n) {
        std::string s;
        for (std::size_t i = 0; i < n; ++i) s += static_cast<char>('A' + i % 26);
        INFO("length " << n);
        const ShortText t(s);
        CHECK(t.size() == n);
        CHECK(t.empty() == (n == 0));
        CHECK(t == s);
        CHECK(std::string(t.c_str()) == s);  // NUL-terminated
        ShortText copy(t);
        CHECK(copy == t);
        ShortText moved(std::move(copy));
        CHECK(moved == s);
        CHECK(copy.empty());  // NOLINT: a moved-from text is empty
        ShortText assigned("x");
        assigned = moved;
        CHECK(assigned == s);
        assigned = ShortText("short");
        CHECK(assigned == "short");
        ShortText grown("G");
        grown.append(s);
        CHECK(grown == "G" + s);
    }
}

TEST_CASE("ShortText: assign and append from its own text, edits, comparisons, concatenation") {
    ShortText t("X100.25");
    t.assign(std::string_view(t).substr(1));  // its own characters
    CHECK(t == "100.25");
    ShortText long_text("ABCDEFGHIJKLMNOPQRSTUVWXYZ");
    long_text.assign(std::string_view(long_text).substr(20));
    CHECK(long_text == "UVWXYZ");
    ShortText a("ABCDE");  // 5, then 7 characters: from in place to the heap
    a.append(std::string_view(a).substr(0, 2));
    CHECK(a == "ABCDEAB");
    ShortText six("ABCDEF");  // 6: in place, full
    six.append(std::string_view(six).substr(5));
    CHECK(six == "ABCDEFF");
    CHECK(std::string(six.c_str()) == "ABCDEFF");
    a.clear();
    CHECK(a.empty());
    ShortText k;
    k.assign(3, 'G');
    CHECK(k == "GGG");
    k[0] = 'X';
    CHECK(k == "XGG");
    CHECK(k.front() == 'X');
    CHECK(k.back() == 'G');
    CHECK(k.substr(1) == "GG");
    CHECK(k.starts_with("XG"));
    CHECK(k.find('G') == 1);
    CHECK(ShortText("ABC") < ShortText("ABD"));
    CHECK("N" + ShortText("10") == "N10");
    CHECK(ShortText("CR") + "=" == "CR=");
    CHECK(std::string("T") + ShortText("1") == "T1");
    std::vector<ShortText> v(100, ShortText("A LONGER TEXT THAN FIFTEEN"));
    v.resize(1000);  // moved on growth
    CHECK(v[99] == "A LONGER TEXT THAN FIFTEEN");
    CHECK(v[999].empty());
    static_assert(sizeof(ShortText) == 8);
}
