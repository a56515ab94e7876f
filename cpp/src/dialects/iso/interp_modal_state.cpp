// LinuxCNC's M70-M73 (profile.modal_state_codes), as its 2.9 interpreter runs them
// (interp_convert.cc: save_settings, restore_settings, gen_settings, gen_m_codes):
//   * M70 saves the modal state in the running call level; M73 too, and in a subroutine the
//     state comes back when it returns (endsub, return, M99); M71 forgets the saved state
//     (a return then restores nothing); M72 restores it, and may be repeated;
//   * a restore is G-code: the differences between the saved and the present state written
//     as LinuxCNC writes them (" F%.1f", " S%.0f", bare G41/G43 that take the spindle's
//     tool, M codes each on a line of their own) and run as blocks, so each has its effects
//     and its errors; units first, in a block of their own;
//   * the motion mode, offsets' values, the tool and parameters are not part of the state;
//   * the rest of an M72 block is not run once the restore ran anything (LinuxCNC's
//     nested blocks overwrite the block being run): toolcomp warns.

#include "interp.hpp"
#include "toolcomp/dialects/iso/lexer.hpp"
#include "toolcomp/program/codes.hpp"
#include "toolcomp/program/text.hpp"

namespace toolcomp::iso {

namespace {

std::string g_text(int code10) {
    return " G" + std::to_string(code10 / 10) + (code10 % 10 ? "." + std::to_string(code10 % 10) : "");
}

}  // namespace

ModalSnapshot Interp::snapshot() const {
    ModalSnapshot s;
    s.g.fill(-1);
    s.g[3] = st_.plane == Plane::xy ? G17 : st_.plane == Plane::zx ? G18 : G19;
    s.g[4] = radius_.side > 0 ? G41 : radius_.side < 0 ? G42 : G40;  // G41.1/G42.1 as G41/G42
    s.g[5] = st_.inch ? G20 : G21;
    s.g[6] = st_.incremental ? G91 : G90;
    s.g[7] = st_.feed_mode == G93 ? G93 : st_.feed_mode == G94 ? G94 : G95;
    s.g[8] = st_.coord_system <= 6 ? G53 + 10 * st_.coord_system : G59 + st_.coord_system - 6;
    s.g[9] = tlo_.isZero(0) ? G49 : G43;  // any offset applied: G43 (G43.1, G43.2 among them)
    s.g[10] = st_.retract_initial ? G98 : G99;
    s.g[11] = st_.path_control;
    s.g[13] = spindles_[0].css ? G96 : G97;
    s.g[14] = st_.arc_absolute ? G90_1 : G91_1;
    s.g[15] = st_.diameter ? G7 : G8;
    s.g[16] = g92_on_ ? G92_3 : G92_2;
    s.m.fill(-1);
    s.m[2] = spindles_[0].turning > 0 ? M3 : spindles_[0].turning < 0 ? M4 : M5;
    s.m[4] = machine_.mist ? M7 : machine_.flood ? -1 : M9;
    s.m[5] = machine_.flood ? M8 : -1;
    // LinuxCNC 2.9.0 tests its per-spindle override array as a truth value: always true, so
    // the slot says M48 or M51, never M49 or M50.
    s.m[6] = machine_.feed_override ? M48 : M51;
    s.m[7] = machine_.adaptive_feed ? M52 : -1;
    s.m[8] = machine_.feed_hold ? M53 : -1;
    s.feed = st_.feed_mode == G93 ? feed_ : feed_ / scale();
    s.speed = spindles_[0].speed;
    s.tolerance = tolerance_;
    s.naivecam = naivecam_;
    return s;
}

// M70-M73 of block `bw`; true when an M72 restore ran something (the rest of the block is
// then not run).
bool Interp::modal_state(const BlockWords& bw) {
    ModalSnapshot& saved = frames_.back().saved;
    const int code = bw.m[m_spindle];
    if (code == M70 || code == M73) {
        // M73 in a subroutine arms the restore on return; it stays armed (M71, M70 after it).
        const bool on_return = saved.restore_on_return || (code == M73 && frames_.size() > 1);
        saved = snapshot();
        saved.valid = true;
        saved.restore_on_return = on_return;
        return false;
    }
    if (code == M71) {
        saved.valid = false;  // a restore on return stays armed for a later M70
        return false;
    }
    if (!saved.valid)
        fail(code::modal_state_invalid, "Cannot restore context from invalid stack frame - missing M70/M73?",
             bw.m_column[m_spindle]);
    if (!restore_modal(ModalSnapshot(saved), bw.m_column[m_spindle])) return false;
    std::string rest;
    auto add = [&rest](const char* what) { rest += (rest.empty() ? "" : ", ") + std::string(what); };
    if (bw.m[m_coolant] >= 0 || bw.m[m_override] >= 0) add("coolant or override codes");
    const std::uint32_t before = (1u << g_feed_mode) | (1u << g_spindle_mode);
    if ((bw.g_groups & ~before) != 0) add("G codes");
    if (bw.has_axis()) add("axis words");
    if (bw.m[m_stop] >= 0) add("program stop or end");
    if (!rest.empty())
        diags_.push_back({code::modal_restore_rest_lost, Severity::warning,
                          "M72 restored modal state: the rest of the block (" + rest + ") is not run, as LinuxCNC 2.9 does",
                          {line_, bw.m_column[m_spindle], file_name()}});
    return true;
}

// Runs `text` as LinuxCNC's restore does: each line a block of its own.
void Interp::run_restore_text(const std::string& text, int column) {
    std::size_t from = 0;
    while (from < text.size()) {
        std::size_t to = text.find('\n', from);
        if (to == std::string::npos) to = text.size();
        const std::string piece = text.substr(from, to - from);
        from = to + 1;
        if (piece.empty()) continue;
        try {
            const Program p = parse(piece, prog_.dialect, "<restore>", true);
            for (const Block& b : p.blocks()) execute(collect_words(p.words(b), line_, profile_, opts_.machine));
        } catch (const Error& e) {
            fail(code::modal_restore_failed,
                 "M7x: restore_settings failed executing: '" + piece + "': " + e.what(), column);
        }
    }
}

bool Interp::restore_modal(const ModalSnapshot& saved, int column) {
    bool ran = false;
    if (saved.g[5] != (st_.inch ? 200 : 210)) {  // units first, so that F is read in them
        run_restore_text(saved.g[5] == G20 ? "G20" : "G21", column);
        ran = true;
    }
    const ModalSnapshot now = snapshot();
    const bool always = profile_.restore_feed_speed_always;
    std::string text;
    if (always || saved.feed != now.feed) text += printf_number(" F%.1f", saved.feed);
    if (always || saved.speed != now.speed) text += printf_number(" S%.0f", saved.speed);
    bool g64 = saved.tolerance != now.tolerance || saved.naivecam != now.naivecam;
    for (int slot : {3, 4, 6, 7, 8, 9, 10, 11, 13, 14, 15, 16}) {
        const int v = saved.g[static_cast<std::size_t>(slot)];
        if (v == now.g[static_cast<std::size_t>(slot)] || v < 0) continue;
        if (slot == 11 && v == G64) g64 = true;  // written last, with its P and Q
        else text += g_text(v);
    }
    if (g64 && saved.g[11] == G64)
        text += saved.tolerance < 0 ? std::string(" G64")
              : saved.naivecam < 0  ? printf_number(" G64 P%f", saved.tolerance)
                                    : printf_number(" G64 P%f", saved.tolerance) + printf_number(" Q%f", saved.naivecam);
    for (int slot : {2, 4, 5, 6, 7, 8}) {
        const int v = saved.m[static_cast<std::size_t>(slot)];
        if (v != now.m[static_cast<std::size_t>(slot)] && v >= 0) text += "M" + std::to_string(v / 10) + "\n";
    }
    if (text.empty()) return ran;
    run_restore_text(text, column);
    return true;
}

// The end of a subroutine whose level M73 saved: its state back in the caller.
void Interp::restore_on_return(const ModalSnapshot& saved, int call_line) {
    if (!saved.valid || !saved.restore_on_return) return;
    try {
        restore_modal(saved, 0);
    } catch (const Error& e) {  // back in the main program: the call's line is the outermost call's
        if (frames_.size() > 1 || !profile_.errors_at_outermost_call) throw;
        throw_at(e, SourcePos{call_line, 0, {}});
    }
}

}  // namespace toolcomp::iso
