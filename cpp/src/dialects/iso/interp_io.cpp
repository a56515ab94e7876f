// LinuxCNC's digital and analog I/O, M62-M68: outputs set with motion (M62/M63, M67) or at
// once (M64/M65, M68), and M66, the wait for an input. None moves the tool: toolcomp checks
// their words as LinuxCNC does (convert_m) and goes on. M66's result, #5399, is the
// machine's input: reading it is refused (interp_params.cpp).
#include <cmath>
#include <string>

#include "interp.hpp"
#include "toolcomp/program/codes.hpp"

namespace toolcomp::iso {

namespace {
int round_to_int(double v) { return static_cast<int>(std::floor(v + 0.5)); }
}  // namespace

void Interp::io_code(const BlockWords& bw) {
    const int m = bw.m[m_io], col = bw.m_column[m_io];
    const std::string name = "M" + std::to_string(m / 10);
    if (m <= M65) {
        if (!bw.has('P')) fail(code::io_bad_words, "No valid P word with " + name, col);
        return;
    }
    if (m == M66) {
        const bool p = bw.has('P'), e = bw.has('E'), l = bw.has('L');
        if (p && e) fail(code::io_bad_words, "Invalid to select both a digital and an analog input with M66", col);
        if (bw['Q'].value <= 0 && l && round_to_int(bw['L'].value) > 0)
            fail(code::io_bad_words, "Zero timeout with wait type != immediate return", col);
        if (e && l && round_to_int(bw['L'].value) != 0)
            fail(code::io_bad_words, "Can't select analog input with wait type != immediate return", col);
        if ((p && round_to_int(bw['P'].value) < 0) || (e && round_to_int(bw['E'].value) < 0) || (!p && !e))
            fail(code::io_bad_words, "Need to have either a valid P or a valid E word with M66", col);
        return;
    }
    if (!bw.has('E') || round_to_int(bw['E'].value) < 0) fail(code::io_bad_words, "Invalid analog index with " + name, col);
}

}  // namespace toolcomp::iso
