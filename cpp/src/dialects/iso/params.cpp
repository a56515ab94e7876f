#include "params.hpp"

namespace toolcomp::iso {

ParameterStore::ParameterStore(bool fanuc)
    : fanuc_(fanuc), numbered_(static_cast<std::size_t>(last_stored()) + 1, fanuc ? kVacant : 0.0) {
    if (!fanuc) numbered_[5599] = 1;  // LinuxCNC: (DEBUG, ...) output on until a program says 0
}

double ParameterStore::get(int n) const { return numbered_[static_cast<std::size_t>(n)]; }

void ParameterStore::set(int n, double v) { numbered_[static_cast<std::size_t>(n)] = v; }

const double* ParameterStore::named(const std::string& name) const {
    if (!name.empty() && name[0] == '_') {
        auto it = globals_.find(name);
        return it == globals_.end() ? nullptr : &it->second;
    }
    auto it = scopes_.back().find(name);
    return it == scopes_.back().end() ? nullptr : &it->second;
}

void ParameterStore::set_named(const std::string& name, double v) {
    if (!name.empty() && name[0] == '_')
        globals_[name] = v;
    else
        scopes_.back()[name] = v;
}

void ParameterStore::enter(const std::vector<double>& args) {
    const auto n = static_cast<std::size_t>(locals());
    saved_.emplace_back(numbered_.begin() + 1, numbered_.begin() + 1 + static_cast<std::ptrdiff_t>(n));
    for (std::size_t k = 0; k < n; ++k) numbered_[k + 1] = k < args.size() ? args[k] : (fanuc_ ? kVacant : 0.0);
    scopes_.emplace_back();
}

void ParameterStore::enter_fanuc(const std::array<double, 34>& locals) {
    enter(std::vector<double>(locals.begin() + 1, locals.end()));
}

void ParameterStore::leave() {
    if (saved_.empty()) return;
    const std::vector<double>& s = saved_.back();
    std::copy(s.begin(), s.end(), numbered_.begin() + 1);
    saved_.pop_back();
    scopes_.pop_back();
}

void ParameterStore::load(const ParameterValues& values) {
    for (const auto& [n, v] : values)
        if (stored(n)) numbered_[static_cast<std::size_t>(n)] = v;
}

ParameterValues ParameterStore::snapshot() const {
    ParameterValues out;
    for (int n = 1; n <= last_stored(); ++n) {
        const double v = numbered_[static_cast<std::size_t>(n)];
        const double unset = n == 5599 ? 1.0 : 0.0;  // LinuxCNC's start values
        if (fanuc_ ? !std::isnan(v) : v != unset) out[n] = v;
    }
    return out;
}

}  // namespace toolcomp::iso
