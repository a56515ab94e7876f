#pragma once
// The parameters of a running ISO program: numbered (#1 ... ) and, LinuxCNC, named
// (#<name> local to the subroutine that set it, #<_name> global). Pure storage: which numbers
// are system parameters computed from the interpreter's state is the interpreter's business
// (interp_params.cpp).
//
// LinuxCNC: #1-#5601, all defined (0 until set); #1-#30 are the arguments of a subroutine
// call, saved and restored around it. Fanuc Macro B: #0 is always vacant; #1-#33 are the
// locals of each macro call level (G65), vacant until set; #100-#199 and #500-#999 common
// variables, vacant until set. A vacant value is NaN here (expr::Syntax::vacant).
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "toolcomp/dialects/iso/interpreter.hpp"

namespace toolcomp::iso {

class ParameterStore {
public:
    static constexpr double kVacant = std::numeric_limits<double>::quiet_NaN();

    explicit ParameterStore(bool fanuc);
    bool fanuc() const { return fanuc_; }
    // Highest numbered parameter that is storage (above: system parameters or out of range).
    int last_stored() const { return fanuc_ ? 999 : 5601; }
    int locals() const { return fanuc_ ? 33 : 30; }

    double get(int n) const;
    void set(int n, double v);
    bool stored(int n) const { return n >= 1 && n <= last_stored() && !(fanuc_ && n > 33 && n < 100) &&
                                      !(fanuc_ && n > 199 && n < 500); }

    // Named parameters (LinuxCNC); `name` without the brackets, folded to lower case.
    const double* named(const std::string& name) const;
    void set_named(const std::string& name, double v);

    // A subroutine (LinuxCNC o-call, Fanuc G65) starts: the locals are saved and replaced
    // by `args` (the rest 0, or vacant on Fanuc); a new scope of local named parameters.
    void enter(const std::vector<double>& args);
    void enter_fanuc(const std::array<double, 34>& locals);
    void leave();
    // A call that shares #1-#30 with its caller (LinuxCNC M98): only named locals are its own.
    void enter_scope() { scopes_.emplace_back(); }
    void leave_scope() {
        if (scopes_.size() > 1) scopes_.pop_back();
    }
    std::size_t depth() const { return saved_.size(); }

    // Values to start from (numbered); the values at the end.
    void load(const ParameterValues& values);
    ParameterValues snapshot() const;

private:
    bool fanuc_;
    std::vector<double> numbered_;                  // index = number
    std::vector<std::vector<double>> saved_;        // locals of the callers
    std::map<std::string, double> globals_;         // #<_name>
    std::vector<std::map<std::string, double>> scopes_{1};  // #<name>, innermost last
};

}  // namespace toolcomp::iso
