// LinuxCNC's straight probe G38.2-G38.5 (interp_convert.cc: convert_probe). Where the probe
// stops depends on the part, which the program does not hold. toolcomp takes what the run
// was given for this probe (InterpretOptions::probes, in order) or, beyond them, a contact at
// the target (what LinuxCNC's preview shows), and says so:
//   * the move is a feed to the contact point (the target when there is none: G38.3 / G38.5
//     without contact), the program's point is there after it;
//   * #5061-#5069 hold that point in the program's coordinates of the active system (U V W:
//     0) and #5070 whether the probe met the part; they keep their values until the next probe;
//   * G38.2 / G38.4 without contact fail as the machine does.
#include <cstdio>

#include "interp.hpp"
#include "toolcomp/program/codes.hpp"

namespace toolcomp::iso {

void Interp::probe(const BlockWords& bw, int code) {
    const int col = bw.g[g_motion] >= 0 ? bw.g_column[g_motion] : bw.axis_column();
    const int type = code - 382;  // bit 0: no error without contact; bit 1: probe away from the part
    const std::string name = "G38." + std::to_string(code - 380);
    if (feed_ == 0) fail(code::probe_words, "Cannot probe with zero feed rate", col);
    if (st_.feed_mode == G95) fail(code::probe_words, "Cannot probe with feed per rev mode", col);
    const Vec6 target = find_end(bw);
    if ((type & 1) == 0 && target == pos_) fail(code::probe_words, "Start point too close to probe point", col);
    const bool given = probes_used_ < opts_.probes.size();
    const ProbeResult r = given ? opts_.probes[probes_used_] : ProbeResult{};
    ++probes_used_;
    Vec6 stop = target;
    if (given && r.contact)
        for (int i = 0; i < r.axes; ++i) stop[i] = i < 3 ? r.point[static_cast<std::size_t>(i)] / scale() : r.point[static_cast<std::size_t>(i)];
    if (given && !r.contact && (type & 1) == 0)
        fail(code::probe_no_contact,
             name + (type & 2 ? " move finished without breaking contact" : " move finished without making contact"), col);
    straight(MotionKind::line, stop, feed_);
    for (int i = 0; i < 6; ++i) probe_values_[static_cast<std::size_t>(i)] = stop[i];
    probe_values_[9] = !given || r.contact ? 1.0 : 0.0;
    probed_ = true;
    char where[96];
    std::snprintf(where, sizeof where, "X%.4f Y%.4f Z%.4f", target[0], target[1], target[2]);
    diags_.push_back({code::probe_move, Severity::warning,
                      name + " to " + where + ": the probe stops where it " + (type & 2 ? "leaves" : "touches") +
                          " the part; toolcomp takes it " +
                          (given ? std::string(r.contact ? "at the point given to the run" : "without contact, at the target")
                                 : std::string("at the target (give the run probes=[...] for the point)")),
                      {line_, col, file_name()}});
}

}  // namespace toolcomp::iso
