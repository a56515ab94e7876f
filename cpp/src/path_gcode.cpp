// A Path as a G-code program without radius compensation (see path_text.hpp).
#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "fixed_text.hpp"
#include "toolcomp/path_text.hpp"

namespace toolcomp {

namespace {

using P3 = std::array<double, 3>;
constexpr double kTwoPi = 2 * 3.14159265358979323846;
constexpr int kPlaneAxes[3][3] = {{0, 1, 2}, {2, 0, 1}, {1, 2, 0}};  // first, second, applicate
constexpr const char* kPlaneWord[3] = {"G17", "G18", "G19"};
constexpr char kCentreWord[3] = {'I', 'J', 'K'};
// Full circles one arc may be written as, a block each (fanuc, grbl): beyond, the text
// would run to gigabytes.
constexpr int kMaxCircles = 1000000;

// x mod m with the sign of m (the remainder Python's % gives for floats).
double floor_mod(double x, double m) {
    double r = std::fmod(x, m);
    if (r != 0) {
        if ((m < 0) != (r < 0)) r += m;
    } else {
        r = std::copysign(0.0, m);
    }
    return r;
}

// The angle an arc sweeps, its turns included (a whole circle when it ends where it starts).
double sweep(const P3& s, const P3& e, const P3& c, int plane, bool ccw, int turns) {
    const int a = kPlaneAxes[plane][0], b = kPlaneAxes[plane][1];
    const double a0 = std::atan2(s[b] - c[b], s[a] - c[a]);
    const double a1 = std::atan2(e[b] - c[b], e[a] - c[a]);
    double d = floor_mod(ccw ? a1 - a0 : a0 - a1, kTwoPi);
    if (d < 1e-12) d = kTwoPi;
    return d + kTwoPi * turns;
}

class Writer {
public:
    Writer(const Path& path, const GcodeStyle& style)
        : path_(path),
          style_(style),
          starts_(path.starts()),
          centers_(path.centers()),
          feeds_(path.feeds()),
          ends_(path.end.data()) {}

    std::string write() {
        const std::size_t n = path_.size();
        check_jumps(n);
        out_.reserve(48 * n + 64);
        if (style_.target == GcodeStyle::Target::fanuc) out_ += "%\n";
        out_ += "G21 G90 G94 G40 G17";
        if (style_.target == GcodeStyle::Target::linuxcnc) out_ += " G91.1";
        out_ += '\n';
        if (n > 0) {
            const P3 pos = start(0);
            if (std::fabs(pos[0]) > 1e-9 || std::fabs(pos[1]) > 1e-9 || std::fabs(pos[2]) > 1e-9) {
                out_ += "G0";
                for (int k = 0; k < 3; ++k) {
                    out_ += ' ';
                    out_ += "XYZ"[k];
                    text::append(out_, num(pos[k]));
                }
                out_ += '\n';
            }
        }
        for (std::size_t i = 0; i < n; ++i) segment(i);
        out_ += style_.target == GcodeStyle::Target::fanuc ? "M30\n%\n" : "M2\n";
        return std::move(out_);
    }

private:
    text::Fixed num(double v) const { return text::fixed(v, style_.digits, /*trim=*/true); }

    P3 shifted(const double* row, std::size_t i) const {
        P3 p{row[0], row[1], row[2]};
        if (style_.tool_length)
            for (int k = 0; k < 3; ++k) p[static_cast<std::size_t>(k)] = p[static_cast<std::size_t>(k)] + path_.tool_offset(i, k);
        return p;
    }
    P3 start(std::size_t i) const { return shifted(starts_.data() + 3 * i, i); }
    P3 end(std::size_t i) const { return shifted(ends_ + 3 * i, i); }
    P3 centre(std::size_t i) const { return shifted(centers_.data() + 3 * i, i); }

    void check_jumps(std::size_t n) const {
        for (std::size_t i = 1; i < n; ++i) {
            const P3 s = start(i), e = end(i - 1);
            for (std::size_t k = 0; k < 3; ++k)
                if (std::fabs(s[k] - e[k]) > 1e-9)
                    throw std::invalid_argument(
                        "the path jumps before the move of line " + std::to_string(path_.line[i]) +
                        " (a work offset or, with tool_length=False, a tool length offset changed); it cannot be "
                        "written as one program");
        }
    }

    // " X.. Y.. Z..": X always, Y and Z where they differ from the start as written.
    void words_to(const P3& p, const P3& q) {
        for (std::size_t k = 0; k < 3; ++k) {
            const text::Fixed to = num(q[k]);
            if (k > 0 && to == num(p[k])) continue;
            out_ += ' ';
            out_ += "XYZ"[k];
            text::append(out_, to);
        }
    }

    void segment(std::size_t i) {
        const auto k = static_cast<MotionKind>(path_.kind[i]);
        const int line = path_.line[i];
        if (style_.comments && (!have_line_ || line != line_)) {
            have_line_ = true;
            line_ = line;
            out_ += "(line ";
            text::append_int(out_, line);
            out_ += ")\n";
        }
        const bool arc = k == MotionKind::arc_cw || k == MotionKind::arc_ccw;
        if (!arc && k != MotionKind::rapid && k != MotionKind::line)
            throw std::invalid_argument("segment " + std::to_string(i) + " (line " + std::to_string(line) + ") has kind " +
                                        std::to_string(static_cast<int>(k)) + ", which has no G-code form");
        std::string plane_word;
        if (arc && path_.plane(i) != plane_) {
            plane_ = path_.plane(i);
            plane_word = kPlaneWord[plane_];
            plane_word += ' ';
        }
        std::string rot;
        for (int j = 0; j < 3; ++j) {
            const double v = path_.abc(i, j);
            const text::Fixed t = num(v);
            if (!(t == num(abc_[static_cast<std::size_t>(j)]))) {
                rot += ' ';
                rot += "ABC"[j];
                text::append(rot, t);
            }
            abc_[static_cast<std::size_t>(j)] = v;
        }
        const P3 s = start(i), e = end(i);
        if (k == MotionKind::rapid) {
            out_ += "G0";
            words_to(s, e);
            out_ += rot;
            out_ += '\n';
            return;
        }
        std::string f;
        const double feed = feeds_[i];
        // A feed move whose rate is not known (G96 at the spindle axis without a speed limit
        // D) would run at the F before it: refused.
        if (std::isnan(feed))
            throw std::invalid_argument("the move of line " + std::to_string(line) +
                                        " has no known feed rate (constant surface speed at the spindle axis "
                                        "without a speed limit); it cannot be written with an F word");
        {
            const text::Fixed t = num(feed);
            if (!(t == num(feed_))) {
                f = " F";
                text::append(f, t);
                feed_ = feed;
            }
        }
        if (k == MotionKind::line) {
            out_ += plane_word;
            out_ += "G1";
            words_to(s, e);
            out_ += rot;
            out_ += f;
            out_ += '\n';
            return;
        }
        arc_blocks(i, k == MotionKind::arc_ccw, s, e, plane_word, rot, f);
    }

    void arc_blocks(std::size_t i, bool ccw, const P3& s, const P3& e, std::string& plane_word, const std::string& rot,
                    std::string& f) {
        const P3 c = centre(i);
        const int a = kPlaneAxes[plane_][0], b = kPlaneAxes[plane_][1], h = kPlaneAxes[plane_][2];
        const int turns = path_.turns(i);
        const bool linuxcnc = style_.target == GcodeStyle::Target::linuxcnc;
        // Without P the turns are full circles first, the third axis shared out by angle.
        P3 p = s;
        const int circles = linuxcnc ? 0 : std::max(0, turns);
        if (circles > kMaxCircles)
            throw std::invalid_argument("the arc of line " + std::to_string(path_.line[i]) + " makes " +
                                        std::to_string(turns) + " extra turns, a block each in this dialect; "
                                        "export it for linuxcnc (one block with P)");
        const double total = circles > 0 ? sweep(s, e, c, plane_, ccw, turns) : 0;
        for (int piece = 0; piece <= circles; ++piece) {
            P3 q = e;
            if (piece < circles) {
                q = p;
                q[static_cast<std::size_t>(h)] += (e[static_cast<std::size_t>(h)] - s[static_cast<std::size_t>(h)]) * (kTwoPi / total);
            }
            out_ += plane_word;
            out_ += ccw ? "G3" : "G2";
            words_to(p, q);
            for (int ax : {a, b}) {
                out_ += ' ';
                out_ += kCentreWord[ax];
                text::append(out_, num(c[static_cast<std::size_t>(ax)] - p[static_cast<std::size_t>(ax)]));
            }
            if (linuxcnc && turns != 0) {
                out_ += " P";
                text::append_int(out_, turns + 1);
            }
            if (piece == circles) out_ += rot;
            out_ += f;
            out_ += '\n';
            plane_word.clear();
            f.clear();
            p = q;
        }
    }

    const Path& path_;
    const GcodeStyle& style_;
    std::span<const double> starts_, centers_, feeds_;
    const double* ends_;
    std::string out_;
    int plane_ = 0;
    double feed_ = std::nan("");
    P3 abc_{0, 0, 0};
    bool have_line_ = false;
    int line_ = 0;
};

}  // namespace

std::string gcode_text(const Path& path, const GcodeStyle& style) {
    if (style.digits < 0 || style.digits > 30)
        throw std::invalid_argument("digits must be 0..30, not " + std::to_string(style.digits));
    return Writer(path, style).write();
}

}  // namespace toolcomp
