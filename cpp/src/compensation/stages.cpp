#include "toolcomp/compensation/stages.hpp"

namespace toolcomp {

void CompensationChain::push(const Motion& m) {
    if (m.radius.side != 0 && !profile_.radius_comp_supported)
        throw CompensationError("radius_comp_not_supported",
                                "Cutter radius compensation (G41/G42) is not supported by toolcomp yet", {m.line, 0});
    out_.push(m);
}

}  // namespace toolcomp
