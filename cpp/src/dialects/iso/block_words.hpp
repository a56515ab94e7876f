#pragma once
// The words of one block sorted by meaning: one slot per letter, G codes by modal group,
// M codes by group. Built with LinuxCNC's checks (one word per letter, one code per group).
#include <array>
#include <cstdint>
#include <span>

#include "codes.hpp"
#include "toolcomp/control/machine.hpp"
#include "toolcomp/program/int_value.hpp"
#include "toolcomp/program/program.hpp"

namespace toolcomp::iso {

struct WordSlot {
    double value = 0;
    int column = 0;
    bool set = false;
};

// A word's slot: A..Z, then LinuxCNC's polar coordinates @ (radius) and ^ (angle), and its
// spindle choice $.
constexpr int letter_index(char c) { return c == '@' ? 26 : c == '^' ? 27 : c == '$' ? 28 : c - 'A'; }
// A letter's bit in BlockWords::letters.
constexpr std::uint32_t letter_bit(char c) { return std::uint32_t{1} << letter_index(c); }

struct BlockWords {
    int line = 0;
    // A..Z except G and M, @ and ^: the value and column of each letter in `letters` (the
    // others are never read, nor cleared for each block).
    struct Slot {
        double value;
        int column;
    };
    std::array<Slot, 29> letter;
    std::uint32_t letters = 0;  // letter_bit(c) for each letter the block has
    std::uint32_t g_groups = 0;         // bit of each G group with a code
    std::array<int, g_group_count> g;   // code10 per group, -1 when none
    std::array<int, g_group_count> g_column{};
    std::array<int, m_group_count> m;
    std::array<int, m_group_count> m_column{};
    int m_count = 0;
    std::int8_t thread_chamfer = -1;            // a builder code turning the thread chamfer on (1) / off (0)
    const MachineCode* machine_call = nullptr;  // a builder M code that runs a subprogram
    int machine_call_column = 0;
    int machine_call_number = 0;
    const MachineCode* machine_g = nullptr;  // LinuxCNC: the block's motion is a remapped G code
    std::uint32_t machine_words = 0;  // the block's letters its builder codes read (out of `letters`)

    static constexpr std::uint32_t kAxes = letter_bit('X') | letter_bit('Y') | letter_bit('Z') | letter_bit('A') |
                                           letter_bit('B') | letter_bit('C') | letter_bit('U') | letter_bit('V') |
                                           letter_bit('W') | letter_bit('@') | letter_bit('^');
    static constexpr std::uint32_t kPolar = letter_bit('@') | letter_bit('^');

    // The letter's word; an unset slot (value 0, column 0) when the block has none.
    WordSlot operator[](char c) const {
        if (!has(c)) return {};
        const Slot& s = letter[static_cast<std::size_t>(letter_index(c))];
        return {s.value, s.column, true};
    }
    void set(char c, double value, int column) {
        letter[static_cast<std::size_t>(letter_index(c))] = {value, column};
        letters |= letter_bit(c);
    }
    bool has(char c) const { return (letters & letter_bit(c)) != 0; }
    bool has_axis() const { return (letters & kAxes) != 0; }
    bool has_polar() const { return (letters & kPolar) != 0; }
    // A G code of a group other than motion (G0-G3, cycles), resp. an M code: a plain move
    // has neither, and execute() passes over what they would set.
    bool modal_codes() const { return (g_groups & ~(std::uint32_t{1} << g_motion)) != 0; }
    bool m_codes() const { return m_count != 0; }
    // Takes a word out of the block.
    void remove(char c) { letters &= ~letter_bit(c); }
    // Column of the first axis word (for error positions), or 0.
    int axis_column() const;
};

// The words of a block (their values computed), read by the control's rules (the
// profile's integer slack, G number reading, M code range). With a machine, its builder M codes are read: one that does nothing for the path leaves the block,
// the others stand for the standard code of their action (a Haas M88 is M8). `profile_block`:
// a block of a LinuxCNC lathe cycle's profile (U and W are words there).
BlockWords collect_words(std::span<const Word> words, int line, const ControlProfile& profile,
                         const Machine* machine = nullptr, bool profile_block = false);

// Integer words (T, D, H, L, P, Q, M, G x 10) convert through toolcomp::int_value
// (program/int_value.hpp; G10's P is truncated, LinuxCNC's reading).
using toolcomp::int_value;
using toolcomp::int_value_truncated;

}  // namespace toolcomp::iso
