#pragma once
// Helpers of the Heidenhain C++ tests: a body wrapped in BEGIN/END PGM with block numbers,
// run; segment points; the segments of a source line; the error code of a body.
#include <string>
#include <vector>

#include "run_helpers.hpp"
#include "toolcomp/program/diagnostic.hpp"

namespace tctest::hh {

using namespace toolcomp;

// "BEGIN PGM" on line 1: the k-th body line is source line k + 1.
inline std::string pgm(const std::string& body) {
    std::string out = "0 BEGIN PGM T MM\n";
    int n = 1;
    std::size_t pos = 0;
    while (pos < body.size()) {
        std::size_t nl = body.find('\n', pos);
        if (nl == std::string::npos) nl = body.size();
        if (nl > pos) out += std::to_string(n++) + " " + body.substr(pos, nl - pos) + "\n";
        pos = nl + 1;
    }
    return out + std::to_string(n) + " END PGM T MM\n";
}

inline Result run_h(const std::string& body) { return tctest::run_text(pgm(body), nullptr, Dialect::heidenhain); }

template <class Rows>
Vec3 col(const Rows& v, std::size_t i) { return {v[3 * i], v[3 * i + 1], v[3 * i + 2]}; }

// Indices of the segments produced by source line `line`.
inline std::vector<std::size_t> of_line(const Path& p, int line) {
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i < p.size(); ++i)
        if (p.line[i] == line) out.push_back(i);
    return out;
}

#define CHECK_XY(V_, X_, Y_)                                                      \
    do {                                                                          \
        const Vec3 v_ = (V_);                                                     \
        INFO(#V_ " = (" << v_.x() << ", " << v_.y() << ")");                      \
        CHECK(v_.x() == Approx(X_).margin(1e-9));                                 \
        CHECK(v_.y() == Approx(Y_).margin(1e-9));                                 \
    } while (0)

inline std::string error_of(const std::string& body, std::string* message = nullptr, int* line = nullptr) {
    try {
        run_h(body);
    } catch (const Error& e) {
        if (message) *message = e.what();
        if (line) *line = e.line();
        return e.code();
    }
    return "";
}

}  // namespace tctest::hh
