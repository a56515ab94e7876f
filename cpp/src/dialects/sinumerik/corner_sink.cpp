// The 840D's RND=, CHF= and CHR= corners (see corner_sink.hpp).
#include "corner_sink.hpp"

#include <cmath>
#include <string>

#include "toolcomp/geometry/element.hpp"
#include "toolcomp/geometry/fillet.hpp"
#include "toolcomp/program/codes.hpp"
#include "toolcomp/program/diagnostic.hpp"

namespace toolcomp::sinumerik {

namespace {

Element2 element(const Motion& m) {
    if (!m.is_arc()) return Element2::line(in_plane(m.start, m.plane), in_plane(m.end, m.plane));
    return Element2::arc(in_plane(m.start, m.plane), in_plane(m.end, m.plane), in_plane(m.center, m.plane),
                         m.kind == MotionKind::arc_ccw ? 1 : -1, m.turns);
}

const char* name(CornerKind k) { return k == CornerKind::rounding ? "RND" : k == CornerKind::chamfer_length ? "CHF" : "CHR"; }

[[noreturn]] void refuse(const char* code, const std::string& what, const CornerRequest& r, int file) {
    SourcePos at{r.line, r.column};
    at.file_index = file;
    throw ProgramError(code, what, at);
}

}  // namespace

void CornerSink::push(const Motion& m) {
    if (!held_ && !request_) return out_.push(m);  // no corner: straight on
    Motion next = m;
    if (held_) {
        Motion held = *held_;
        held_.reset();  // taken: an error in the corner leaves nothing held behind
        corner(held, next, held_request_);
    }
    if (request_) {
        held_ = next;
        held_request_ = *request_;
        request_.reset();
        return;
    }
    out_.push(next);
}

void CornerSink::abandon() {
    request_.reset();
    if (!held_) return;
    const Motion held = *held_;
    held_.reset();
    out_.push(held);
}

void CornerSink::control(const ControlEvent& e) {
    if (held_) refuse(code::corner_without_element, std::string(name(held_request_.kind)) + "= needs a path move after its block",
                      held_request_, held_->file);
    out_.control(e);
}

void CornerSink::finish() {
    if (held_) refuse(code::corner_without_element, std::string(name(held_request_.kind)) + "= needs a path move after its block",
                      held_request_, held_->file);
    out_.finish();
}

// held ends at the corner, next starts there: both cut back, the corner element between.
void CornerSink::corner(Motion& held, Motion& next, const CornerRequest& r) {
    const std::string what = name(r.kind);
    if (held.kind == MotionKind::rapid || next.kind == MotionKind::rapid)
        refuse(code::corner_next_to_rapid, what + "= needs path moves (G1, G2, G3) on both sides, not G0", r, held.file);
    if (next.plane != held.plane) refuse(code::corner_without_element, what + "= between moves in different planes", r, held.file);
    const int c = axes(held.plane).c;
    for (const Motion* e : {&held, &next})
        if (e->is_arc() && (e->turns != 0 || e->start[c] != e->end[c]))
            refuse(code::rounding_next_to_helix, what + "= next to a helix is not supported by toolcomp", r, held.file);
    const Element2 e1 = element(held), e2 = element(next);
    if (e1.length() < 1e-9 || e2.length() < 1e-9)
        refuse(code::corner_without_element, what + "= needs moves in the working plane on both sides", r, held.file);
    Motion piece = next;
    piece.line = r.line;
    piece.file = held.file;
    piece.turns = 0;
    if (r.kind == CornerKind::rounding) {
        const auto f = fillet(e1, e2, r.size);
        if (!f) refuse(code::rounding_too_large, "RND=" + std::to_string(r.size) + ": the rounding does not fit between the moves", r, held.file);
        piece.kind = f->dir > 0 ? MotionKind::arc_ccw : MotionKind::arc_cw;
        piece.start = with_plane(held.end, f->t1, held.plane);
        piece.end = with_plane(held.end, f->t2, held.plane);
        piece.center = with_plane(held.end, f->centre, held.plane);
    } else {
        if (held.is_arc() || next.is_arc())
            refuse(code::chamfer_next_to_arc, what + "= next to a circle is not supported by toolcomp (between straight moves it is)", r, held.file);
        const Vec2 t1 = e1.end_tangent(), t2 = e2.start_tangent();
        const double theta = turn_angle(t1, t2);  // the direction's change at the corner
        if (std::fabs(theta) < 1e-12) refuse(code::chamfer_not_permitted, what + "= between moves in one line", r, held.file);
        // CHR: legs of that length; CHF: the chamfer itself that long, legs size / (2 cos(theta / 2))
        const double legs = r.kind == CornerKind::chamfer_legs ? r.size : r.size / (2 * std::cos(theta / 2));
        if (!(legs < e1.length()) || !(legs < e2.length()))
            refuse(code::chamfer_not_permitted, what + "=: the chamfer is longer than the moves beside it", r, held.file);
        const Vec2 p = in_plane(held.end, held.plane);
        piece.kind = MotionKind::line;
        piece.center = Vec3::Constant(std::nan(""));
        piece.start = with_plane(held.end, p - legs * t1, held.plane);
        piece.end = with_plane(held.end, p + legs * t2, held.plane);
    }
    // the corner piece lies in the plane at the corner's height (both moves meet there)
    held.end = piece.start;
    next.start = piece.end;
    out_.push(held);
    out_.push(piece);
}

}  // namespace toolcomp::sinumerik
