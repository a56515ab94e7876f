#pragma once
// Random lines near a dialect's plain grammar of words (a key, a sign, a number, blanks), with
// now and then what takes a line off it: for comparing a lexer's fast path with its general
// lexer on lines either may take.
#include <cstddef>
#include <random>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "toolcomp/program/program.hpp"

namespace toolcomp::test {

struct WordLineShape {
    std::vector<std::string> keys;  // what a word starts with
    std::string after_key;          // put after a key now and then (a blank, '=')
    int sign_percent = 20;          // how often a word has a sign
    bool blank_after_sign = false;  // now and then a blank after the sign ("Z + 5")
    int point_percent = 60;         // how often a number has a point
    bool decimal_comma = false;     // now and then a comma for the point
    std::string in_number;          // put inside a number now and then
    std::string odd;                // put after a word now and then
};

// `head` (a block number, blanks) and up to six words of `shape`.
inline std::string random_word_line(std::mt19937& rng, const WordLineShape& shape, std::string head) {
    std::uniform_int_distribution<int> pct(0, 99);
    auto pick = [&](const std::string& s) { return s[std::uniform_int_distribution<std::size_t>(0, s.size() - 1)(rng)]; };
    std::string line = std::move(head);
    const int words = pct(rng) % 7;
    for (int w = 0; w < words; ++w) {
        line += shape.keys[std::uniform_int_distribution<std::size_t>(0, shape.keys.size() - 1)(rng)];
        if (!shape.after_key.empty() && pct(rng) < 5) line += pick(shape.after_key);
        if (pct(rng) < shape.sign_percent) line += pct(rng) < 50 ? '-' : '+';
        if (shape.blank_after_sign && pct(rng) < 4) line += ' ';
        const int digits = pct(rng) < 3 ? 16 + pct(rng) % 4 : pct(rng) % 8;
        const int point = pct(rng) < shape.point_percent ? pct(rng) % (digits + 1) : -1;
        for (int k = 0; k < digits; ++k) {
            if (k == point) line += shape.decimal_comma && pct(rng) >= 95 ? ',' : '.';
            line += static_cast<char>('0' + pct(rng) % 10);
            if (!shape.in_number.empty() && pct(rng) < 2) line += pick(shape.in_number);
        }
        if (point == digits) line += '.';
        if (!shape.odd.empty() && pct(rng) < 6) line += pick(shape.odd);
        const int blanks = pct(rng) < 10 ? 0 : 1 + pct(rng) % 2;
        for (int k = 0; k < blanks; ++k) line += pct(rng) < 85 ? ' ' : '\t';
    }
    return line;
}

// Runs `check` (which throws on any difference between a lexer's fast path and its general
// lexer) on `lines` lines of `random_line`; returns how many of them `fast` took.
template <class RandomLine, class Fast, class Check>
int plain_lines_taken(int lines, std::mt19937& rng, RandomLine random_line, Fast fast, Check check) {
    int taken = 0;
    for (int i = 0; i < lines; ++i) {
        const std::string line = random_line(rng);
        INFO("line '" << line << "'");
        Program p;
        taken += fast(line, 1, p);
        check(line);
    }
    return taken;
}

}  // namespace toolcomp::test
