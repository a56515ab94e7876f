#include "block_words.hpp"
#include "toolcomp/program/codes.hpp"

#include <climits>
#include <cmath>
#include <string>

#include "toolcomp/program/text.hpp"
#include "whole_numbers.hpp"

namespace toolcomp::iso {

namespace {

[[noreturn]] void fail(const char* code, const std::string& msg, int line, int column) {
    throw ProgramError(code, msg, {line, column});
}

std::string code_text(char letter, int code10) {
    std::string s(1, letter);
    s += std::to_string(code10 / 10);
    if (code10 % 10) s += "." + std::to_string(code10 % 10);
    return s;
}

// LinuxCNC's read_g: ten times the value, taken as the integer it is within 0.001 of
// (rounding up from 0.999 above the one below), else out of range; G99.9 at most.
int linuxcnc_g_code(const BlockWords& bw, const Word& w) {
    const double v10 = 10.0 * w.value;
    double code = std::floor(v10);
    if (v10 - code > 0.999)
        code = std::ceil(v10);
    else if (v10 - code > 0.001)
        fail(code::g_code_out_of_range, "G-code out of range", bw.line, w.column);
    if (code > 999) fail(code::g_code_out_of_range, "G-code out of range", bw.line, w.column);
    if (code < 0) fail(code::negative_g_code, "Negative g code used", bw.line, w.column);
    return static_cast<int>(code);
}

// The letters a LinuxCNC REMAP argspec reads (either case), as letter bits.
std::uint32_t argspec_letters(const std::string& argspec) {
    std::uint32_t bits = 0;
    for (char c : argspec)
        if (ascii_alpha(c)) bits |= letter_bit(ascii_upper(c));
    return bits;
}

void add_g(BlockWords& bw, const Word& w, const ControlProfile& profile, const Machine* machine,
           std::uint32_t& taken) {
    int code = 0;
    if (profile.linuxcnc_g_numbers) {
        code = linuxcnc_g_code(bw, w);
    } else {
        double v10 = w.value * 10;
        if (w.value < 0) fail(code::negative_g_code, "Negative g code used", bw.line, w.column);
        code = int_value(v10);
        if (code > 9999) fail(code::g_code_out_of_range, "G-code out of range", bw.line, w.column);
        if (std::fabs(v10 - code) > 1e-6) fail(code::unknown_g_code, "Unknown g code used", bw.line, w.column);
    }
    int group = g_group(code, profile);
    if (group == kUnknown && machine)
        if (const MachineCode* remap = machine->g_code(code)) {  // LinuxCNC REMAP: the block's motion
            group = g_motion;
            bw.machine_g = remap;
            taken |= argspec_letters(remap->argspec);
        }
    if (group == kUnknown) fail(code::unknown_g_code, "Unknown g code used", bw.line, w.column);
    if (group == kUnsupported)
        fail(code::unsupported_g_code, code_text('G', code) + " is not supported by toolcomp", bw.line, w.column);
    if (bw.g[group] >= 0) {
        // LinuxCNC lets G80 stand beside another motion code; the other code wins. On Fanuc
        // the last code of a modal group in a block is the one that counts.
        if (profile.last_g_code_wins && group != g_nonmodal) {
            // replaced below
        } else if (group == g_motion && (code == G80 || bw.g[group] == G80)) {
            if (code == G80) return;
        } else {
            fail(code::modal_group_conflict, "Two g codes used from same modal group", bw.line, w.column);
        }
    }
    bw.g[group] = code;
    bw.g_column[group] = w.column;
    bw.g_groups |= std::uint32_t{1} << group;
}

void add_m(BlockWords& bw, const Word& w, const ControlProfile& profile, const Machine* machine,
           std::uint32_t& taken) {
    // Whole first, then the sign of the integer it reads as (M-0.00005 is M0 on LinuxCNC).
    if (!whole_word(w.value, profile.integer_word_slack)) fail(code::non_integer_value, "Non integer value for integer", bw.line, w.column);
    int m = int_value(w.value);
    if (m < 0) fail(code::negative_m_code, "Negative m code used", bw.line, w.column);
    if (machine)
        if (const MachineCode* code = machine->m_code(m)) {
            for (char c : code->words) taken |= letter_bit(c);
            taken |= argspec_letters(code->argspec);
            if (++bw.m_count > 4) fail(code::too_many_m_codes, "Too many m codes on line", bw.line, w.column);
            const int number = m;
            m = standard_m_code(code->action);
            if (code->action == MCodeAction::thread_chamfer_on || code->action == MCodeAction::thread_chamfer_off) {
                if (bw.thread_chamfer >= 0) fail(code::modal_group_conflict, "Two M codes for the thread chamfer in one block", bw.line, w.column);
                bw.thread_chamfer = code->action == MCodeAction::thread_chamfer_on ? 1 : 0;
            }
            if (code->action == MCodeAction::subprogram) {
                if (bw.machine_call) fail(code::too_many_m_codes, "Two M codes that run subprograms in one block", bw.line, w.column);
                bw.machine_call = code;
                bw.machine_call_column = w.column;
                bw.machine_call_number = number;
            }
            if (m < 0) return;  // a builder code without effect on the path, or a subprogram call
            --bw.m_count;        // counted again below
        }
    if (m > profile.max_m_code && profile.max_m_code < 99999)
        fail(code::m_code_out_of_range, "M-code greater than " + std::to_string(profile.max_m_code) + ": M" + std::to_string(m),
             bw.line, w.column);
    if (m > 99999) fail(code::unknown_m_code, "Unknown m code used: M" + std::to_string(m), bw.line, w.column);
    int group = m_group(m * 10, profile);
    if (group == kUnknown) fail(code::unknown_m_code, "Unknown m code used: M" + std::to_string(m), bw.line, w.column);
    if (group == kUnsupported)
        fail(code::unsupported_m_code, "M" + std::to_string(m) + " is not supported by toolcomp", bw.line, w.column);
    if (++bw.m_count > 4) fail(code::too_many_m_codes, "Too many m codes on line", bw.line, w.column);
    if (bw.m[group] >= 0)
        fail(code::modal_group_conflict, "Two m codes used from same modal group", bw.line, w.column);
    bw.m[group] = m * 10;
    bw.m_column[group] = w.column;
}

}  // namespace

int BlockWords::axis_column() const {
    int col = 0;
    for (char c : {'X', 'Y', 'Z', 'A', 'B', 'C', 'U', 'V', 'W', '@', '^'})
        if (has(c) && (col == 0 || (*this)[c].column < col)) col = (*this)[c].column;
    return col;
}

BlockWords collect_words(std::span<const Word> words, int line, const ControlProfile& profile,
                         const Machine* machine, bool profile_block) {
    const bool slack = profile.integer_word_slack;
    BlockWords bw;
    bw.line = line;
    bw.g.fill(-1);
    bw.m.fill(-1);
    std::uint32_t taken = 0;  // letters the machine's builder codes of the block read
    for (const Word& w : words) {
        if (w.letter == 'G') {
            add_g(bw, w, profile, machine, taken);
        } else if (w.letter == 'M') {
            add_m(bw, w, profile, machine, taken);
        } else {
            // LinuxCNC reads U and W only in the profile of a lathe cycle (the reader's error).
            if ((w.letter == 'U' || w.letter == 'W') && profile.profile_cycles && !profile_block)
                fail(code::bad_character, std::string("Bad character '") + ascii_lower(w.letter) + "' used", bw.line, w.column);
            if (bw.has(w.letter)) {
                if (w.letter == '$')
                    fail(code::spindle_choice, "Multiple spindle choice ($) words on one line", bw.line, w.column);
                char lower = ascii_lower(w.letter);
                fail(code::multiple_words, std::string("Multiple ") + lower + " words on one line", bw.line, w.column);
            }
            if (w.letter == 'T') {
                if (!whole_word(w.value, slack))
                    fail(code::non_integer_value, "Non integer value for integer", bw.line, w.column);
                if (int_value(w.value) < 0)
                    fail(code::negative_tool, "Negative tool id (tool not found)", bw.line, w.column);
            }
            if (w.letter == 'L' && !whole_word(w.value, slack))
                fail(code::non_integer_value, "Non integer value for integer", bw.line, w.column);
            if (w.letter == 'L' && int_value(w.value) < 0 && profile.negative_l_refused)
                fail(code::negative_l_word, "Negative l word used", bw.line, w.column);
            if (w.letter == 'F' && w.value < 0) fail(code::negative_feed, "Negative f word used", bw.line, w.column);
            if (w.letter == 'S' && w.value < 0)
                fail(code::negative_spindle_speed, "Negative spindle speed used", bw.line, w.column);
            bw.set(w.letter, w.value, w.column);
        }
    }
    bw.machine_words = bw.letters & taken;
    bw.letters &= ~taken;
    return bw;
}

}  // namespace toolcomp::iso
