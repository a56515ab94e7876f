// The 840D's frames (see frame_value.hpp).
#include "frame_value.hpp"

#include <algorithm>
#include <cmath>

namespace toolcomp::sinumerik {

Mat3 rotation(int axis, double deg) {
    const double a = deg * kPi / 180, c = std::cos(a), s = std::sin(a);
    Mat3 r = Mat3::Identity();
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;  // x: (y, z), y: (z, x), z: (x, y)
    r(i, i) = c;
    r(i, j) = -s;
    r(j, i) = s;
    r(j, j) = c;
    return r;
}

Frame Frame::operator*(const Frame& inner) const {
    Frame f;
    f.a = a * inner.a;
    f.t = a * inner.t + t;
    f.inv = f.a.inverse();
    return f;
}

Mat3 FrameValue::rotation() const {
    return sinumerik::rotation(2, rt.z()) * sinumerik::rotation(1, rt.y()) * sinumerik::rotation(0, rt.x());
}

Mat3 FrameValue::linear() const {
    Mat3 d = Mat3::Zero();
    for (int i = 0; i < 3; ++i) d(i, i) = sc[i] * (mi[i] != 0 ? -1 : 1);
    return rotation() * d;
}

Frame FrameValue::frame() const {
    Frame f;
    f.a = linear();
    f.t = tr + fi;
    f.inv = f.a.inverse();
    return f;
}

double& FrameValue::at(int axis, Component c) {
    switch (c) {
        case comp_tr: return tr[axis];
        case comp_fi: return fi[axis];
        case comp_rt: return rt[axis];
        case comp_sc: return sc[axis];
        default: return mi[axis];
    }
}

namespace {

// The RPY angles (degrees) of a rotation R = Rz(c) Ry(b) Rx(a).
Vec3 rpy(const Mat3& r) {
    const double deg = 180 / kPi;
    const double b = std::asin(std::clamp(-r(2, 0), -1.0, 1.0));
    return Vec3(std::atan2(r(2, 1), r(2, 2)) * deg, b * deg, std::atan2(r(1, 0), r(0, 0)) * deg);
}

// The one axis a rotation turns about, or -1 (none or several).
int single_axis(const Vec3& rt) {
    int axis = -1;
    for (int i = 0; i < 3; ++i)
        if (rt[i] != 0) {
            if (axis >= 0) return -1;
            axis = i;
        }
    return axis;
}

Vec3 either(const Vec3& a, const Vec3& b) {
    Vec3 r;
    for (int i = 0; i < 3; ++i) r[i] = (a[i] != 0) != (b[i] != 0) ? 1 : 0;
    return r;
}

}  // namespace

std::optional<FrameValue> chain(const FrameValue& a, const FrameValue& b) {
    FrameValue r;
    const Mat3 la = a.linear();
    r.tr = a.tr + la * b.tr;
    r.fi = a.fi + la * b.fi;
    r.sc = a.sc.cwiseProduct(b.sc);
    r.mi = either(a.mi, b.mi);
    if (!b.turned()) {  // Ra Sa Ma Sb Mb = Ra (Sa Sb) (Ma Mb)
        r.rt = a.rt;
        return r;
    }
    if (a.sc.x() != a.sc.y() || a.sc.y() != a.sc.z()) return std::nullopt;  // would shear
    // Ra Sa Ma Rb Sb Mb = Ra (Ma Rb Ma) (Sa Sb) (Ma Mb): a uniform Sa commutes, Ma Rb Ma turns
    const int axis = single_axis(b.rt);
    if (a.mi == Vec3::Zero() && axis >= 0 && (single_axis(a.rt) == axis || !a.turned())) {
        r.rt = a.rt;
        r.rt[axis] += b.rt[axis];  // about one axis: the angles add up
        return r;
    }
    Mat3 ma = Mat3::Identity();
    for (int i = 0; i < 3; ++i) ma(i, i) = a.mi[i] != 0 ? -1 : 1;
    r.rt = rpy(a.rotation() * ma * b.rotation() * ma);
    return r;
}

int frame_indices(std::string_view name) {
    if (name == "$P_UIFR" || name == "$P_CHBFRAME") return 1;
    if (name == "$P_PFRAME" || name == "$P_IFRAME" || name == "$P_BFRAME" || name == "$P_ACTFRAME") return 0;
    return -1;
}

void rewrite_frame_components(expr::Expr& e) {
    auto axis = [&](const expr::Instr& in) -> int {
        if (in.op != expr::Op::variable || in.argc != 0) return -1;
        const std::string& n = e.names[in.name];
        return n == "X" ? 0 : n == "Y" ? 1 : n == "Z" ? 2 : -1;
    };
    auto component = [&](const expr::Instr& in) -> int {
        if (in.op != expr::Op::variable || in.argc != 0) return -1;
        const std::string& n = e.names[in.name];
        static constexpr std::string_view names[] = {"TR", "FI", "RT", "SC", "MI"};
        for (int c = 0; c < 5; ++c)
            if (n == names[c]) return c;
        return -1;
    };
    for (std::size_t i = 2; i < e.code.size(); ++i) {
        const expr::Instr& v = e.code[i];
        if (v.op != expr::Op::variable) continue;
        const int whole = frame_indices(e.names[v.name]);
        if (whole < 0 || v.argc != whole + 2) continue;
        const int ax = axis(e.code[i - 2]), c = component(e.code[i - 1]);
        if (ax < 0 || c < 0) continue;
        e.code[i - 2] = expr::Instr{expr::Op::number, 0, expr::Fn::sin, 0, static_cast<double>(ax)};
        e.code[i - 1] = expr::Instr{expr::Op::number, 0, expr::Fn::sin, 0, static_cast<double>(c)};
    }
}

}  // namespace toolcomp::sinumerik
