#include "toolcomp/compensation/surface.hpp"

#include "toolcomp/compensation/three_d.hpp"

namespace toolcomp {

void SurfaceCompensation::push(const Motion& m) {
    if (!shifted_ && !m.surface.active()) {  // the common case: nothing to change, no copy
        last_ = m.end;
        out_.push(m);
        return;
    }
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
