// Plane geometry queries over numpy arrays for toolcomp's Python helpers (private to _core).
#include "bindings.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <optional>

#include "toolcomp/geometry/segment_tree.hpp"

using namespace toolcomp;

namespace {
using Points = py::array_t<double, py::array::c_style | py::array::forcecast>;

std::span<const Vec2> as_points(const Points& a, const char* name) {
    if (a.ndim() != 2 || a.shape(1) != 2) throw py::value_error(std::string(name) + " must be an (N, 2) array");
    static_assert(sizeof(Vec2) == 2 * sizeof(double));
    return {reinterpret_cast<const Vec2*>(a.data()), static_cast<std::size_t>(a.shape(0))};
}
}  // namespace

void bind_geometry(py::module_& m) {
    /// @pydoc _nearest_segments
    /// For each element p0[i]..p1[i] (a segment, or where turn[i] is not 0 an arc about
    /// centers[i]: +1 counter-clockwise, -1 clockwise, +-2 a whole circle), its distance to
    /// the nearest segment q0[j]q1[j] and the point of the element where it is taken, where
    /// that distance is below `limit` (inf and 0 elsewhere).
    m.def(
        "_nearest_segments",
        [](const Points& p0, const Points& p1, const Points& q0, const Points& q1, double limit,
           const std::optional<Points>& centers, const std::optional<py::array_t<std::int8_t, py::array::c_style | py::array::forcecast>>& turn) {
            const auto a0 = as_points(p0, "p0"), a1 = as_points(p1, "p1");
            const auto b0 = as_points(q0, "q0"), b1 = as_points(q1, "q1");
            if (a0.size() != a1.size() || b0.size() != b1.size())
                throw py::value_error("segment ends must come in pairs of the same length");
            std::span<const Vec2> c;
            const std::int8_t* t = nullptr;
            if (centers.has_value() != turn.has_value()) throw py::value_error("centers and turn go together");
            if (centers) {
                c = as_points(*centers, "centers");
                if (c.size() != a0.size() || turn->ndim() != 1 || static_cast<std::size_t>(turn->shape(0)) != a0.size())
                    throw py::value_error("centers (N, 2) and turn (N,) must come with every first segment");
                t = turn->data();
            }
            const auto n = static_cast<py::ssize_t>(a0.size());
            py::array_t<double> dist(n), at({n, py::ssize_t(2)});
            double* d = dist.mutable_data();
            double* x = at.mutable_data();
            {
                py::gil_scoped_release nogil;
                const SegmentTree tree(b0, b1);
                for (std::size_t i = 0; i < a0.size(); ++i) {
                    const int k = t ? t[i] : 0;
                    const SegmentGap g = k == 0 ? tree.nearest(a0[i], a1[i], limit)
                                                : tree.nearest(PlaneArc{a0[i], a1[i], c[i], k, k == 2 || k == -2}, limit);
                    const bool near = g.distance < limit;
                    d[i] = near ? g.distance : INFINITY;
                    x[2 * i] = near ? g.at.x() : 0.0;
                    x[2 * i + 1] = near ? g.at.y() : 0.0;
                }
            }
            return py::make_tuple(dist, at);
        },
        py::arg("p0"), py::arg("p1"), py::arg("q0"), py::arg("q1"), py::arg("limit"), py::arg("centers") = py::none(),
        py::arg("turn") = py::none(), pydoc::_nearest_segments);
}
