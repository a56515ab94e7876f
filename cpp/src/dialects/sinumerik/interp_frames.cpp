// The 840D's frame chain and frame variables: the basic frame ($P_BFRAME), the settable
// frames ($P_UIFR[n] in the data, activated by G500 / G54 ... G599 as $P_IFRAME), the
// programmable frame ($P_PFRAME: TRANS ... or assigned), the frame functions CTRANS, CFINE,
// CROT, CSCALE, CMIRROR chained with ':', frame components ($P_UIFR[1, X, TR]) and G58/G59.
// A move maps through basic : settable : programmable (actual_).
#include <cmath>

#include "interp.hpp"
#include "toolcomp/program/codes.hpp"
#include "toolcomp/program/int_value.hpp"
#include "toolcomp/program/text.hpp"

namespace toolcomp::sinumerik {

namespace {

constexpr int kSettableFrames = 100;  // G500 (0), G54-G57 (1-4), G505-G599 (5-99)

bool neutral(const FrameValue& f) {
    const FrameValue n;
    return f.tr == n.tr && f.fi == n.fi && f.rt == n.rt && f.sc == n.sc && f.mi == n.mi;
}

int as_index(double v) { return int_value(v); }

int geometry_axis(const std::string& word) {
    return word == "X" ? 0 : word == "Y" ? 1 : word == "Z" ? 2 : -1;
}

}  // namespace

void Interp::set_programmable(const Frame& f, std::optional<FrameValue> components) {
    frame_ = f;
    pframe_ = std::move(components);
    refresh_frames();
}

void Interp::select_settable(int n) {
    st_.settable = n;
    const auto it = uifr_.find(n);
    iframe_ = it == uifr_.end() ? FrameValue{} : it->second;
    refresh_frames();
}

void Interp::refresh_frames() {
    settable_neutral_ = neutral(iframe_) && neutral(bframe_);
    actual_ = settable_neutral_ ? frame_ : bframe_.frame() * iframe_.frame() * frame_;
}

// A frame variable's value: $P_UIFR[n], $P_PFRAME, $P_IFRAME, $P_BFRAME / $P_CHBFRAME[0], and
// (read only) $P_ACTFRAME.
FrameValue& Interp::frame_variable(const std::string& name, std::span<const double> idx, std::size_t whole, bool write,
                                   int column) {
    if (idx.size() < whole) fail(code::alarm_17020, "17020 " + name + " needs its index", column);
    const int n = whole ? as_index(idx[0]) : 0;
    if (name == "$P_UIFR") {
        if (n < 0 || n >= kSettableFrames) fail(code::alarm_17020, "17020 Illegal array index: $P_UIFR[" + std::to_string(n) + "]", column);
        return uifr_[n];
    }
    if (name == "$P_IFRAME") return iframe_;
    if (name == "$P_BFRAME" || name == "$P_CHBFRAME") {
        if (n != 0) fail(code::unsupported_word, name + "[" + std::to_string(n) + "]: toolcomp keeps one basic frame ($P_CHBFRAME[0])", column);
        return bframe_;
    }
    if (name == "$P_ACTFRAME") {
        if (write) fail(code::alarm_17070, "17070 Data write-protected: $P_ACTFRAME", column);
        std::optional<FrameValue> all = pframe_ ? chain(iframe_, *pframe_) : std::nullopt;
        if (all) all = chain(bframe_, *all);
        if (!all) fail(code::unsupported_word, "$P_ACTFRAME of a chain that shears (a scale that differs between the axes, then a rotation) is not supported by toolcomp", column);
        actframe_scratch_ = *all;
        return actframe_scratch_;
    }
    // $P_PFRAME
    if (!pframe_)
        fail(code::unsupported_word, "$P_PFRAME after a scale that differs between the axes and then a rotation is not supported by toolcomp", column);
    return *pframe_;
}

// $P_UIFR[1, X, TR], $P_PFRAME[Y, RT] ...: the component; translations in the program's unit.
std::optional<double> Interp::frame_component(const std::string& name, std::span<const double> idx) {
    const int whole = frame_indices(name);
    if (whole < 0) return std::nullopt;
    if (idx.size() != static_cast<std::size_t>(whole) + 2)
        fail(code::alarm_12550, "12550 " + name + " is a frame: read one component, " + name + (whole ? "[n, X, TR]" : "[X, TR]"));
    FrameValue& f = frame_variable(name, idx, whole, false, 0);
    const auto c = static_cast<Component>(as_index(idx[whole + 1]));
    const double v = f.at(as_index(idx[whole]), c);
    return c == comp_tr || c == comp_fi ? v / unit() : v;
}

bool Interp::set_frame_component(const std::string& name, std::span<const double> idx, double v, int column) {
    const int whole = frame_indices(name);
    if (whole < 0) return false;
    if (idx.size() != static_cast<std::size_t>(whole) + 2)
        fail(code::alarm_12550, "12550 " + name + " is a frame: assign it a frame (CTRANS(...)) or one component", column);
    FrameValue& f = frame_variable(name, idx, whole, true, column);
    const auto c = static_cast<Component>(as_index(idx[whole + 1]));
    if (c == comp_sc && v == 0) fail(code::scale_zero, "A frame's scale of zero", column);
    f.at(as_index(idx[whole]), c) = c == comp_tr || c == comp_fi ? v * unit() : c == comp_mi ? (v != 0) : v;
    if (pframe_ && &f == &*pframe_) set_programmable(pframe_->frame(), pframe_);
    else if (&f == &iframe_ || &f == &bframe_) refresh_frames();
    return true;  // $P_UIFR[n]: in the data, active with the next G500 / G54 ... selecting it
}

// $P_xxx = frame expression.
void Interp::frame_assign(const Token& t) {
    std::vector<double> idx;
    const std::string name = assignment_target(t, idx);
    const FrameValue v = frame_expression(t.text, t.column);
    if (name == "$P_PFRAME") return set_programmable(v.frame(), v);
    frame_variable(name, idx, static_cast<std::size_t>(frame_indices(name)), true, t.column) = v;
    if (name != "$P_UIFR") refresh_frames();
}

// Terms joined by ':', each chained after the ones before it.
FrameValue Interp::frame_expression(const std::string& text, int column) {
    std::optional<FrameValue> out = FrameValue{};
    std::size_t b = 0;
    int depth = 0;
    for (std::size_t i = 0; i <= text.size(); ++i) {
        const char ch = i < text.size() ? text[i] : ':';
        if (ch == '(' || ch == '[') ++depth;
        if (ch == ')' || ch == ']') --depth;
        if (ch != ':' || depth != 0) continue;
        const std::string term = text.substr(b, i - b);
        b = i + 1;
        FrameValue f;
        const std::size_t open = term.find_first_of("([");
        const std::string name = to_upper_ascii(term.substr(0, open));
        if (frame_indices(name) >= 0) {
            std::vector<double> idx;
            if (open != std::string::npos && term[open] == '[')
                for (const std::string& a : split_args(term.substr(open + 1, term.size() - open - 2))) idx.push_back(eval_text(a, column));
            if (idx.size() != static_cast<std::size_t>(frame_indices(name)))
                fail(code::alarm_17020, "17020 " + name + " takes " + std::to_string(frame_indices(name)) + " index here", column);
            f = frame_variable(name, idx, idx.size(), false, column);
        } else {
            if (open == std::string::npos || term[open] != '(' || term.back() != ')')
                fail(code::unsupported_word, "Frame " + term + " is not supported by toolcomp (CTRANS, CFINE, CROT, CSCALE, CMIRROR and frame variables are)", column);
            f = frame_function(name, term.substr(open + 1, term.size() - open - 2), column);
        }
        out = chain(*out, f);
        if (!out)
            fail(code::unsupported_word, "A chain of frames with a scale that differs between the axes, then a rotation, is not supported by toolcomp", column);
    }
    return *out;
}

// CTRANS(X, 10, Y, 20), CFINE(...), CROT(Z, 30), CSCALE(X, 2, Y, 2), CMIRROR(X, Y); () neutral.
FrameValue Interp::frame_function(const std::string& name, const std::string& args, int column) {
    if (name != "CTRANS" && name != "CFINE" && name != "CROT" && name != "CSCALE" && name != "CMIRROR")
        fail(code::unsupported_word, "Frame function " + name + " is not supported by toolcomp (CTRANS, CFINE, CROT, CSCALE, CMIRROR are)", column);
    FrameValue f;
    if (args.find_first_not_of(" \t") == std::string::npos) return f;
    const std::vector<std::string> a = split_args(args);
    const std::size_t step = name == "CMIRROR" ? 1 : 2;
    if (a.size() % step != 0) fail(code::syntax_error, name + " takes pairs of an axis and its value", column);
    for (std::size_t i = 0; i < a.size(); i += step) {
        const int axis = geometry_axis(to_upper_ascii(a[i]));
        if (axis < 0) fail(code::unsupported_word, name + " of the axis " + a[i] + " is not supported by toolcomp (X, Y, Z are)", column);
        if (name == "CMIRROR") {
            f.mi[axis] = 1;
            continue;
        }
        const double v = eval_text(a[i + 1], column);
        if (name == "CTRANS") f.tr[axis] = v * unit();
        else if (name == "CFINE") f.fi[axis] = v * unit();
        else if (name == "CROT") f.rt[axis] = v;
        else if (v == 0) fail(code::scale_zero, "CSCALE with a factor of zero", column);
        else f.sc[axis] = v;
    }
    return f;
}

// G58 X.. (the coarse translation of the programmable frame on the axes named, the additive
// part kept) and G59 X.. (the additive part on the axes named).
void Interp::programmable_offset(const BlockData& b, int g, int column) {
    if (!pframe_)
        fail(code::unsupported_word, "G" + std::to_string(g) + " after a frame chain that shears is not supported by toolcomp", column);
    FrameValue f = *pframe_;
    static constexpr char kAxes[3] = {'X', 'Y', 'Z'};
    for (int i = 0; i < 3; ++i)
        if (b[kAxes[i]].set) (g == G58 ? f.tr : f.fi)[i] = b[kAxes[i]].v * unit();
    set_programmable(f.frame(), f);
}

}  // namespace toolcomp::sinumerik
