// LinuxCNC 2.9's Fanuc-style numbered subprograms (profile.numbered_subprograms): a bare
// O<n> line begins one, M98 P<n> [L<count>] as a line's first word calls it, M99 as a line's
// first word returns. As LinuxCNC reads them (interp_o_word.cc, interp_convert.cc):
//   * the sub: <n>.ngc on the search path first, else the first O<n> after the call in the
//     running file, remembered for the calls after;
//   * nothing is passed: #1-#30 are the caller's, changed by the sub for good; named locals
//     (#<x>) belong to the call;
//   * L repeats the call by running the M98 line again (its P is read each time);
//   * only the call runs: the line's other words are read, not run;
//   * M99 in the main program ends it as M2 does (LinuxCNC's task loops there instead).
#include <cmath>

#include "interp.hpp"
#include "whole_numbers.hpp"
#include "toolcomp/program/codes.hpp"

namespace toolcomp::iso {

void Interp::numbered_call(std::size_t k) {
    Frame& caller = frames_.back();
    const Program& p = caller.prog();
    const Block& b = p.blocks()[k];
    const BlockWords bw = collect_words(syntax_ ? block_words(b) : p.words(b), b.line, profile_, opts_.machine);
    const double pv = bw['P'].value;
    if (!d_word_whole(pv, profile_.integer_word_slack))
        fail(code::non_integer_value, "Non integer value for integer", bw['P'].column);
    const std::string label = std::to_string(int_value(pv));
    if (bw.has('L')) {  // the count lives in the caller; the M98 line runs again while passes remain
        if (caller.m98_loop < 0) caller.m98_loop = int_value(bw['L'].value);
        if (caller.m98_loop == 0) {  // L0: no call (LinuxCNC 2.9 leaves a call level open here)
            caller.m98_loop = -1;
            return;
        }
        if (--caller.m98_loop > 0) caller.pc = k;
        else caller.m98_loop = -1;
    }
    const LoadedProgram* where = load(label + ".ngc");
    std::size_t block = FlowInfo::npos;
    auto first_after = [&](const LoadedProgram* lp, std::size_t from) {
        for (const auto& [l, at] : lp->flow.numbered)
            if (l == label && (from == FlowInfo::npos || at > from)) return at;
        return FlowInfo::npos;
    };
    auto mixed = [&](const LoadedProgram* lp, std::size_t from, std::size_t found) {
        auto s = lp->flow.subs.find(label);
        if (s != lp->flow.subs.end() && (from == FlowInfo::npos || s->second > from) && s->second < found)
            fail(code::o_word_structure, "'O.... sub' subroutine must be called with 'O.... call'");
    };
    if (where) {
        block = first_after(where, FlowInfo::npos);
        mixed(where, FlowInfo::npos, block);
        if (block == FlowInfo::npos)
            fail(code::unknown_o_word, "EOF in file:" + where->prog->name + " seeking o-word: o<" + label + "> from line: 0");
    } else if (auto r = numbered_found_.find(label); r != numbered_found_.end()) {
        where = r->second.first;
        block = r->second.second;
    } else {
        where = caller.at;
        block = first_after(where, k);
        mixed(where, k, block);
        if (block == FlowInfo::npos)
            fail(code::unknown_o_word, "EOF in file:" + p.name + " seeking o-word: o<" + label + "> from line: " +
                                       std::to_string(line_));
        numbered_found_.emplace(label, std::make_pair(where, block));
    }
    enter_sub(Frame::m98, where, block);
    params_.enter_scope();
}

// M99 as the first word of a line in a subprogram: back to the caller (the line after the
// call, or the M98 line again while its L passes remain). Only a comment may follow it.
void Interp::numbered_return(std::size_t k) {
    const Frame& f = frames_.back();
    const Program& p = f.prog();
    for (const Word& w : p.words(p.blocks()[k]))
        if (w.letter != 'N' && !(w.letter == 'M' && w.value == written(M99)))
            fail(code::bad_o_word, "Unexpected character after O-word", w.column);
    if (f.kind == Frame::o_call)
        fail(code::o_word_structure, "'O.... endsub' or 'O.... return' must follow 'O.... sub' subroutine definition");
    const ModalSnapshot saved = f.saved;
    const int call_line = f.call_line;
    frames_.pop_back();
    params_.leave_scope();
    restore_on_return(saved, call_line);
}

}  // namespace toolcomp::iso
