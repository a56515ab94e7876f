#pragma once
// The control structure of one ISO program, found once before it runs: which block closes
// which O-word structure (LinuxCNC sub/if/while/do/repeat, by label) or Fanuc WHILE-DO/END
// loop (by identification number), where each subroutine, sequence number and Fanuc program
// number is. A structure that does not close is reported when the run reaches it, as the
// control does (a program may hold unbalanced text after its end).
#include <cstddef>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

#include "toolcomp/program/program.hpp"

namespace toolcomp::iso {

struct FlowInfo {
    static constexpr std::size_t npos = static_cast<std::size_t>(-1);
    // The links of a block with a control statement (npos where nothing applies). Kept only
    // for those blocks: a million-block CAM program without any costs nothing here.
    struct Links {
        // if / elseif -> the next branch (elseif, else or endif); else -> endif;
        // while <-> endwhile; do <-> its closing while; repeat <-> endrepeat; sub <-> endsub;
        // Fanuc WHILE..DO m <-> END m
        std::size_t partner = npos;
        std::size_t endif = npos;  // if / elseif / else: the endif of the chain
        std::size_t loop = npos;   // break / continue / return / endsub: the loop or sub they act on
        bool closes_do = false;    // an o-while that ends a do loop
    };
    std::unordered_map<std::size_t, Links> links;
    const Links& at(std::size_t block) const {
        static const Links none;
        auto it = links.find(block);
        return it == links.end() ? none : it->second;
    }
    std::map<std::size_t, std::string> errors;  // block -> why it does not fit the structure
    std::map<std::string, std::size_t> subs;    // LinuxCNC label -> sub block
    std::map<long, std::size_t> numbers;        // Fanuc: N number -> first block with it
    std::map<long, std::size_t> programs;       // Fanuc O number -> its block
    std::vector<std::pair<std::string, std::size_t>> numbered;  // LinuxCNC bare O<n>: label, block (in order)
};

inline constexpr const char* kNestedSub = "Nested subroutine definition";

FlowInfo scan_flow(const Program& prog);

// The control statement of a block (O-word, Fanuc WHILE/END/GOTO...), or nullptr.
const Statement* control_statement(const Program& prog, const Block& b);

}  // namespace toolcomp::iso
