#include "flow.hpp"

#include <algorithm>
#include <cmath>

namespace toolcomp::iso {

namespace {
bool is_control(Stmt k) { return k != Stmt::assign && k != Stmt::if_then; }

}  // namespace

const Statement* control_statement(const Program& prog, const Block& b) {
    for (const Statement& s : prog.statements(b))
        if (is_control(s.kind)) return &s;
    return nullptr;
}

FlowInfo scan_flow(const Program& prog) {
    const std::size_t n = prog.size();
    FlowInfo f;
    const bool fanuc = prog.dialect == Dialect::fanuc;
    struct Open {
        std::size_t block;
        Stmt kind;
        std::string label;
        std::vector<std::size_t> branches;  // if: the if and its elseif/else blocks
    };
    std::vector<Open> stack;
    std::vector<std::pair<std::size_t, int>> fanuc_loops;  // WHILE block, DO number
    auto innermost = [&](const std::string& label, bool loops_only) -> Open* {
        for (auto it = stack.rbegin(); it != stack.rend(); ++it) {
            const bool loop = it->kind == Stmt::o_while || it->kind == Stmt::o_do || it->kind == Stmt::o_repeat;
            if (it->label == label && (!loops_only || loop)) return &*it;
        }
        return nullptr;
    };
    for (std::size_t k = 0; k < n; ++k) {
        const Block& b = prog.blocks()[k];
        if (fanuc)
            for (const Word& w : prog.words(b))
                if (w.letter == 'N' && w.expr < 0 && std::fabs(w.value) < 1e9) f.numbers.emplace(std::lround(w.value), k);
        if (b.statement_count == 0) continue;
        const Statement* s = control_statement(prog, b);
        if (!s) continue;
        // LinuxCNC's words: "<line>: <what>: '<the source line>'".
        auto error = [&](const std::string& m) { f.errors.emplace(k, m); };
        auto quoted = [&](const std::string& what) { return std::to_string(b.line) + ": " + what + ": '" + s->text + "'"; };
        auto close = [&](Stmt opener) {
            if (!stack.empty() && stack.back().label == s->label && stack.back().kind == opener) return &stack.back();
            Open* same = innermost(s->label, false);
            if (same) {
                static constexpr const char* kNames[] = {"", "sub", "", "", "", "if", "", "", "", "while", "", "do", "repeat"};
                const auto kind = static_cast<std::size_t>(same->kind);
                const char* found = kind < std::size(kNames) ? kNames[kind] : "";
                const std::string where = std::string(found) + "' in line " + std::to_string(prog.blocks()[same->block].line) + ")";
                const std::string at = std::to_string(b.line) + ": ";
                // LinuxCNC's three wordings: endif; else / elseif; the other ends.
                if (s->kind == Stmt::o_endif)
                    error(at + "no matching label: '#" + s->label + "' (found '" + where + ": '" + s->text + "'");
                else if (s->kind == Stmt::o_else || s->kind == Stmt::o_elseif)
                    error(at + "no matching 'if' label: '" + s->text + "' (found '" + where);
                else
                    error(at + "no matching label: '" + s->text + "' (found '" + where);
            } else {
                error(quoted("undefined O-word label"));
            }
            return static_cast<Open*>(nullptr);
        };
        switch (s->kind) {
            case Stmt::o_sub:
                // Within another sub's definition (an if or a loop may hold one). Reported when
                // the run passes over the outer definition, as LinuxCNC reads it then.
                if (std::any_of(stack.begin(), stack.end(), [](const Open& o) { return o.kind == Stmt::o_sub; })) {
                    error(kNestedSub);
                    break;
                }
                f.subs.emplace(s->label, k);
                stack.push_back({k, s->kind, s->label, {}});
                break;
            case Stmt::o_if:
                stack.push_back({k, s->kind, s->label, {k}});
                break;
            case Stmt::o_do: case Stmt::o_repeat:
                stack.push_back({k, s->kind, s->label, {}});
                break;
            case Stmt::o_while:
                if (!stack.empty() && stack.back().kind == Stmt::o_do && stack.back().label == s->label) {
                    f.links[k].closes_do = true;
                    f.links[k].partner = stack.back().block;
                    f.links[stack.back().block].partner = k;
                    stack.pop_back();
                } else {
                    stack.push_back({k, s->kind, s->label, {}});
                }
                break;
            case Stmt::o_elseif: case Stmt::o_else:
                if (Open* o = close(Stmt::o_if)) {
                    f.links[o->branches.back()].partner = k;
                    o->branches.push_back(k);
                }
                break;
            case Stmt::o_endif:
                if (Open* o = close(Stmt::o_if)) {
                    f.links[o->branches.back()].partner = k;
                    for (std::size_t br : o->branches) f.links[br].endif = k;
                    stack.pop_back();
                }
                break;
            case Stmt::o_endsub: {
                // A definition ends at its endsub, whatever is still open inside it (LinuxCNC
                // reads on from there: an endif after it belongs to nothing).
                auto sub = std::find_if(stack.rbegin(), stack.rend(), [](const Open& o) { return o.kind == Stmt::o_sub; });
                if (sub == stack.rend()) {
                    error(quoted("not in a subroutine definition"));
                    break;
                }
                if (sub->label != s->label) {
                    close(Stmt::o_sub);
                    break;
                }
                f.links[sub->block].partner = k;
                f.links[k].partner = sub->block;
                f.links[k].loop = sub->block;
                stack.erase(std::prev(sub.base()), stack.end());
                break;
            }
            case Stmt::o_endwhile: case Stmt::o_endrepeat: {
                const Stmt opener = s->kind == Stmt::o_endwhile ? Stmt::o_while : Stmt::o_repeat;
                if (Open* o = close(opener)) {
                    f.links[o->block].partner = k;
                    f.links[k].partner = o->block;
                    stack.pop_back();
                }
                break;
            }
            case Stmt::o_break: case Stmt::o_continue:
                if (Open* o = innermost(s->label, true)) {
                    f.links[k].loop = o->block;
                } else if (Open* other = innermost(s->label, false)) {
                    error(std::to_string(b.line) + ": no matching while/do label: '" + s->text + "' (found '" +
                          (other->kind == Stmt::o_if ? "if" : "sub") + "' in line " +
                          std::to_string(prog.blocks()[other->block].line) + ")");
                } else {
                    error(quoted("undefined O-word label"));
                }
                break;
            case Stmt::o_return:
                if (Open* o = innermost(s->label, false); o && o->kind == Stmt::o_sub)
                    f.links[k].loop = o->block;
                else if (!stack.empty() && stack.front().kind == Stmt::o_sub)
                    f.links[k].loop = stack.front().block;  // LinuxCNC returns even with the wrong label
                break;  // outside a sub definition: a return from the called file, checked when run
            case Stmt::program_number:
                if (prog.dialect != Dialect::linuxcnc) f.programs.emplace(std::stol(s->label), k);
                else f.numbered.emplace_back(s->label, k);
                break;
            case Stmt::while_do:
                fanuc_loops.push_back({k, s->loop});
                break;
            case Stmt::end_loop:
                if (fanuc_loops.empty() || fanuc_loops.back().second != s->loop) {
                    error("END " + std::to_string(s->loop) + " without WHILE [...] DO " + std::to_string(s->loop));
                } else {
                    f.links[fanuc_loops.back().first].partner = k;
                    f.links[k].partner = fanuc_loops.back().first;
                    fanuc_loops.pop_back();
                }
                break;
            default:
                break;
        }
    }
    return f;
}

}  // namespace toolcomp::iso
