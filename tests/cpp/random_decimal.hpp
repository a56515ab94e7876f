#pragma once
// Random decimal texts for the number tests: 1 to 20 digits (a fifth of them zeros, for
// leading and trailing zeros), the point anywhere or nowhere; no sign.
#include <random>
#include <string>

inline std::string random_decimal(std::mt19937_64& rng) {
    const int n = 1 + static_cast<int>(rng() % 20);
    std::string s;
    for (int i = 0; i < n; ++i) s.push_back(static_cast<char>('0' + (rng() % 10 < 2 ? 0 : rng() % 10)));
    const int point = static_cast<int>(rng() % (n + 2));  // n + 1: no point
    if (point <= n) s.insert(static_cast<std::size_t>(point), ".");
    return s;
}
