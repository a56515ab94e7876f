#include "toolcomp/compensation/surface.hpp"

#include "toolcomp/compensation/normal_offset.hpp"

namespace toolcomp {

void SurfaceCompensation::push(const Motion& m) {
    if (shifted_ || m.surface.active()) [[unlikely]]
        return displace(m);
    last_ = m.end;  // the common case: nothing to change, no copy
    out_.push(m);
}

// Kept out of push(): its copy of the move would give every move push()'s stack frame.
[[gnu::noinline]] void SurfaceCompensation::displace(const Motion& m) {
    Motion o = m;
    if (shifted_) o.start = last_;
    shifted_ = false;
    if (m.surface.active()) {
        const Vec3 d = delta_3d(m.surface.normal, m.tool_axis, m.surface.d_r, m.surface.d_r2);
        o.end += d;
        shifted_ = d.squaredNorm() > 0;
    }
    last_ = o.end;
    out_.push(o);
}

}  // namespace toolcomp
