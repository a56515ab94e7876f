#pragma once
// The words of one block sorted by meaning: one slot per letter, G codes by modal group,
// M codes by group. Built with LinuxCNC's checks (one word per letter, one code per group).
#include <array>
#include <span>

#include "codes.hpp"
#include "toolcomp/program/int_value.hpp"
#include "toolcomp/program/program.hpp"

namespace toolcomp::iso {

struct WordSlot {  // 16 bytes: BlockWords clears 26 of them per block
    double value = 0;
    int column = 0;
    bool set = false;
};

struct BlockWords {
    int line = 0;
    std::array<WordSlot, 26> letter{};  // A..Z except G and M
    std::array<int, g_group_count> g;   // code10 per group, -1 when none
    std::array<int, g_group_count> g_column{};
    std::array<int, m_group_count> m;
    std::array<int, m_group_count> m_column{};
    int m_count = 0;

    const WordSlot& operator[](char c) const { return letter[c - 'A']; }
    bool has(char c) const { return letter[c - 'A'].set; }
    bool has_axis() const {
        return has('X') || has('Y') || has('Z') || has('A') || has('B') || has('C') || has('U') || has('V') ||
               has('W');
    }
    // Column of the first axis word (for error positions), or 0.
    int axis_column() const;
};

BlockWords collect_words(const Program& prog, const Block& block);
// The same for words whose values are already computed (programs with parameters).
BlockWords collect_words(std::span<const Word> words, int line, Dialect dialect);

// Integer words (T, D, H, L, P, Q, M, G x 10) convert through toolcomp::int_value
// (program/int_value.hpp; G10's P is truncated, LinuxCNC's reading).
using toolcomp::int_value;
using toolcomp::int_value_truncated;

}  // namespace toolcomp::iso
