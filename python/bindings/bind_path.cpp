// Path columns as read-only numpy views over the C++ storage (no copies; start, center and
// feed over the rows the Path writes out once asked for); the array keeps the Path (and so the
// Result owning it) alive.
#include "bindings.hpp"

#include <cmath>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "toolcomp/analysis/cycle_time.hpp"
#include "toolcomp/path.hpp"

using namespace toolcomp;

namespace {
template <class T>
py::array view(py::handle owner, const T* data, std::size_t n, std::size_t width, py::dtype dtype = py::dtype::of<T>()) {
    std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(n)}, strides{static_cast<py::ssize_t>(sizeof(T) * width)};
    if (width > 1) {
        shape.push_back(static_cast<py::ssize_t>(width));
        strides.push_back(sizeof(T));
    }
    static const T dummy{};
    py::array a(dtype, shape, strides, data ? data : &dummy, owner);
    py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
    return a;
}
template <class T>
py::array view(py::handle owner, const Column<T>& v, std::size_t n, std::size_t width,
               py::dtype dtype = py::dtype::of<T>()) {
    return view(owner, v.empty() ? nullptr : v.data(), n, width, dtype);
}

// Rows written out by the Path when asked for (starts(), centers(), feeds()): kept with it.
template <std::span<const double> (Path::*rows)() const, int width>
py::array written(py::object self) {
    const Path& p = self.cast<const Path&>();
    std::span<const double> v;
    {
        py::gil_scoped_release nogil;  // a million rows take a few ms
        v = (p.*rows)();
    }
    return view(self, v.empty() ? nullptr : v.data(), p.size(), width);
}

// A Vec3Column: its rows, or while every row is the same, that one row repeated (stride 0).
py::array view3(py::handle owner, const Vec3Column& v) {
    const auto n = static_cast<py::ssize_t>(v.size());
    if (!v.uniform()) {
        py::array a(py::dtype::of<double>(), {n, py::ssize_t(3)}, {py::ssize_t(24), py::ssize_t(8)}, v.data(), owner);
        py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
        return a;
    }
    py::array_t<double> row(3);
    std::copy(v.fill(), v.fill() + 3, row.mutable_data());
    py::array a(py::dtype::of<double>(), {n, py::ssize_t(3)}, {py::ssize_t(0), py::ssize_t(8)}, row.data(), row);
    py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
    return a;
}

// A scalar UniformColumn the same way: its rows, or one value repeated (stride 0).
template <class T>
py::array view1(py::handle owner, const UniformColumn<T, 1>& v) {
    const auto n = static_cast<py::ssize_t>(v.size());
    py::array a;
    if (!v.uniform()) {
        a = py::array(py::dtype::of<T>(), {n}, {py::ssize_t(sizeof(T))}, v.data(), owner);
    } else {
        py::array_t<T> one(1);
        one.mutable_data()[0] = v.fill()[0];
        a = py::array(py::dtype::of<T>(), {n}, {py::ssize_t(0)}, one.data(), one);
    }
    py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
    return a;
}

auto column3(Vec3Column Path::*member) {
    return [member](py::object self) { return view3(self, self.cast<const Path&>().*member); };
}

template <class T>
auto column1(UniformColumn<T, 1> Path::*member) {
    return [member](py::object self) { return view1(self, self.cast<const Path&>().*member); };
}

template <class T>
auto column(Column<T> Path::*member, std::size_t width) {
    return [member, width](py::object self) {
        const Path& p = self.cast<const Path&>();
        return view(self, p.*member, p.size(), width);
    };
}
}  // namespace

void bind_path(py::module_& m) {
    py::class_<Path, std::shared_ptr<Path>>(
        m, "Path", pydoc::Path)
        .def("__len__", &Path::size, pydoc::Path_size)
        .def_property_readonly("kind", column(&Path::kind, 1), pydoc::Path_kind)
        .def_property_readonly("start", &written<&Path::starts, 3>, pydoc::Path_starts)
        .def_property_readonly("end", column(&Path::end, 3), pydoc::Path_end)
        .def_property_readonly("center", &written<&Path::centers, 3>, pydoc::Path_centers)
        .def_property_readonly("nbytes", &Path::bytes, pydoc::Path_bytes)
        .def_property_readonly("abc", column3(&Path::abc), pydoc::Path_abc)
        .def_property_readonly("line", column(&Path::line, 1), pydoc::Path_line)
        .def_property_readonly("file", column1(&Path::file), pydoc::Path_file)
        .def_readonly("files", &Path::files, pydoc::Path_files)
        .def_property_readonly("tool", column1(&Path::tool), pydoc::Path_tool)
        .def_property_readonly("feed", &written<&Path::feeds, 1>, pydoc::Path_feeds)
        .def_property_readonly("side", column(&Path::side, 1), pydoc::Path_side)
        .def_property_readonly("generated",
                               [](py::object self) {
                                   const Path& p = self.cast<const Path&>();
                                   return view(self, p.generated, p.size(), 1, py::dtype("bool"));
                               },
                               pydoc::Path_generated)
        .def_property_readonly("tool_offset", column3(&Path::tool_offset), pydoc::Path_tool_offset)
        .def_property_readonly("work_offset", column3(&Path::work_offset), pydoc::Path_work_offset)
        .def_property_readonly("work_rotation", column1(&Path::work_rotation), pydoc::Path_work_rotation)
        /// @pydoc Path.machine_end
        /// end point of each segment in machine coordinates, float64 (N, 3), mm: the
        /// spindle's gauge point, as the control's machine position shows it (a new
        /// array at each access)
        .def_property_readonly(
            "machine_end",
            [](const Path& p) {
                auto* v = new std::vector<double>(3 * p.size());
                for (std::size_t i = 0; i < p.size(); ++i) {
                    const Vec3 e = p.machine_end_at(i);
                    for (int k = 0; k < 3; ++k) (*v)[3 * i + static_cast<std::size_t>(k)] = e[k];
                }
                py::capsule c(v, [](void* x) { delete static_cast<std::vector<double>*>(x); });
                return py::array_t<double>({static_cast<py::ssize_t>(p.size()), py::ssize_t(3)}, v->data(), c);
            },
            pydoc::Path_machine_end)
        .def_property_readonly("plane", column1(&Path::plane), pydoc::Path_plane)
        /// @pydoc Path.turns
        /// arcs: extra full turns (LinuxCNC P word - 1)
        .def_property_readonly("turns", column1(&Path::turns), pydoc::Path_turns)
        .def_property_readonly("normal", column3(&Path::normal), pydoc::Path_normal)
        .def_property_readonly("tool_axis", column3(&Path::tool_axis), pydoc::Path_tool_axis)
        .def(
            "contact_points",
            [](const Path& p, double r, double r2) {
                if (!std::isfinite(r) || !(r2 >= 0) || r2 > r)
                    throw py::value_error("contact_points: need 0 <= r2 <= r, finite");
                auto* v = new std::vector<double>();
                p.contact_points(r, r2, *v);
                py::capsule c(v, [](void* x) { delete static_cast<std::vector<double>*>(x); });
                return py::array_t<double>({static_cast<py::ssize_t>(p.size()), py::ssize_t(3)}, v->data(), c);
            },
            py::arg("r"), py::arg("r2"), pydoc::Path_contact_points)
        .def(
            "sample",
            [](const Path& p, double tolerance) {
                if (!(tolerance > 0)) throw py::value_error("tolerance must be > 0");
                auto* pts = new std::vector<double>();
                auto* seg = new std::vector<std::int64_t>();
                {
                    py::gil_scoped_release nogil;
                    p.sample(tolerance, *pts, *seg);
                }
                py::capsule pc(pts, [](void* v) { delete static_cast<std::vector<double>*>(v); });
                py::capsule sc(seg, [](void* v) { delete static_cast<std::vector<std::int64_t>*>(v); });
                py::ssize_t n = static_cast<py::ssize_t>(seg->size());
                py::array_t<double> a({n, py::ssize_t(3)}, pts->data(), pc);
                py::array_t<std::int64_t> b({n}, seg->data(), sc);
                return py::make_tuple(a, b);
            },
            py::arg("tolerance") = 0.01, pydoc::Path_sample)
        .def("length", &Path::length, py::arg("include_rapids") = true, pydoc::Path_length)
        /// @pydoc Path.duration
        /// Seconds each segment takes on the machine the path was run on: rapids at its
        /// rapid rates (10 m/min per axis where it gives none), feed moves at their
        /// feed, slowed where an axis would pass its max_feed; no acceleration
        /// (doc/cycle-time.md). NaN for a feed move without a positive feed.
        .def_property_readonly(
            "duration",
            [](const Path& p) {
                auto* v = new std::vector<double>();
                {
                    py::gil_scoped_release nogil;
                    *v = segment_seconds(p, p.rates);
                }
                py::capsule c(v, [](void* x) { delete static_cast<std::vector<double>*>(x); });
                return py::array_t<double>({static_cast<py::ssize_t>(v->size())}, v->data(), c);
            },
            pydoc::Path_duration)
        .def_property_readonly("tool_changes", &tool_changes, pydoc::tool_changes)
        .def("__repr__", [](const Path& p) { return "Path(" + std::to_string(p.size()) + " segments)"; });
}
