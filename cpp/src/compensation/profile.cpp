#include "toolcomp/compensation/profile.hpp"

namespace toolcomp {

ControlProfile profile_for(Dialect d) {
    ControlProfile p;
    p.name = std::string(dialect_name(d));
    switch (d) {
        case Dialect::fanuc:
            // Fanuc "tool length compensation type A": the H value acts on Z; G44 subtracts.
            p.length_axes = LengthAxes::z_only;
            p.length_subtract_word = true;
            break;
        default:
            break;
    }
    return p;
}

}  // namespace toolcomp
