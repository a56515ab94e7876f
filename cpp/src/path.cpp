#include "toolcomp/path.hpp"

#include "toolcomp/compensation/normal_offset.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <new>
#include <type_traits>

namespace toolcomp {

namespace {
template <class V>
void put3(V& v, const Vec3& p) {
    v.push_back(p.x());
    v.push_back(p.y());
    v.push_back(p.z());
}
void put3(double* out, const Vec3& p) {
    out[0] = p.x();
    out[1] = p.y();
    out[2] = p.z();
}
Vec3 get3(const Column<double>& v, std::size_t i) { return {v[3 * i], v[3 * i + 1], v[3 * i + 2]}; }
Vec3 get3(const Vec3Column& v, std::size_t i) { return {v(i, 0), v(i, 1), v(i, 2)}; }
}  // namespace

void Path::reserve(std::size_t n) {
    if (n <= room_.n) return;
    kind.reserve(n);
    // Room for a centre on every row: address space only, the rows not written take no
    // memory (and are given back by release_unused()). Jumps are few: they grow as needed.
    for (auto* v : {&end, &arc_centers_}) v->reserve(3 * n);
    arc_rank_.reserve(n / kRankRows + 1);
    for (auto* v : {&tool_offset, &work_offset, &abc, &normal, &tool_axis}) v->reserve(n);
    file.reserve(n);
    work_rotation.reserve(n);
    line.reserve(n);
    tool.reserve(n);
    turns.reserve(n);
    side.reserve(n);
    plane.reserve(n);
    generated.reserve(n);
    room_.n = n;
    warm_.rows = std::min(warm_.rows, size());  // the columns may have moved: fresh memory
    warm_.arcs = std::min(warm_.arcs, arc_centers_.size() / 3);
    if (warm_.by) warm_.next = size();
}

void Path::reserve_granted(std::size_t n) {
    for (; n >= size() + 1024; n /= 2) {
        try {
            reserve(n);
            return;
        } catch (const std::bad_alloc&) {
            if (size() == 0) *this = Path();
        }
    }
}

namespace {
constexpr std::size_t kWarmStretch = std::size_t{1} << 16;  // rows asked for at once
}

void Path::warm_with(PageWarmer* warmer) {
    warm_ = Warm{};
    if (!warmer || room_.n < 4 * kWarmStretch) return;  // small: the zeroing is not worth a thread
    warm_.by = warmer;
    warm_.rows = size();
    warm_.next = size();
}

// Two stretches ahead of the row being written, asked for one stretch before the last one
// asked for is reached.
void Path::warm_ahead() {
    while (warm_.rows < room_.n && warm_.rows < size() + 2 * kWarmStretch) {
        const std::size_t from = warm_.rows, to = std::min(room_.n, from + kWarmStretch), n = to - from;
        warm_.by->warm(end.data() + 3 * from, 3 * n * sizeof(double));
        warm_.by->warm(line.data() + from, n * sizeof(std::int32_t));
        warm_.by->warm(kind.data() + from, n);
        warm_.by->warm(side.data() + from, n);
        warm_.by->warm(generated.data() + from, n);
        warm_.rows = to;
    }
    // Arc centres: at most one a row, so as far ahead of the arcs written as the rows are.
    const std::size_t arcs = arc_centers_.size() / 3, arcs_to = std::min(room_.n, arcs + 2 * kWarmStretch);
    if (warm_.arcs < arcs_to) {
        const std::size_t from = std::max(warm_.arcs, arcs);
        warm_.by->warm(arc_centers_.data() + 3 * from, 3 * (arcs_to - from) * sizeof(double));
        warm_.arcs = arcs_to;
    }
    warm_.next = warm_.rows < room_.n ? warm_.rows - kWarmStretch : static_cast<std::size_t>(-1);
}

void Path::release_unused() noexcept {
    toolcomp::release_unused(kind);
    for (auto* v : {&end, &jump_starts_, &arc_centers_}) toolcomp::release_unused(*v);
    feed.release_unused();
    toolcomp::release_unused(jump_rows_);
    toolcomp::release_unused(arc_rank_);
    for (auto* v : {&tool_offset, &work_offset, &abc, &normal, &tool_axis}) v->release_unused();
    for (auto* v : {&file, &tool, &turns}) v->release_unused();
    work_rotation.release_unused();
    plane.release_unused();
    toolcomp::release_unused(line);
    toolcomp::release_unused(side);
    toolcomp::release_unused(generated);
}

// Whether a segment's uniform values are the last segment's, bit for bit (the tool length
// offset as it is stored, in mm): compared field by field from the Motion, without building
// its row. A surface normal (3D compensation) is stored normalised: those segments take the
// long way.
bool Path::same_row(const Motion& m, const Vec3& offset) const {
    const auto bits = [](double x) { return std::bit_cast<std::uint64_t>(x); };
    std::uint64_t diff = 0;
    for (int i = 0; i < 3; ++i) {
        diff |= bits(offset[i]) ^ bits(last_.tool_offset[i]);
        diff |= bits(m.work_offset[i] * m.unit) ^ bits(last_.work_offset[i]);
        diff |= bits(m.abc[static_cast<std::size_t>(i)]) ^ bits(last_.abc[i]);
        diff |= bits(m.surface.normal[i]) ^ bits(last_.normal[i]);
        diff |= bits(m.tool_axis[i]) ^ bits(last_.tool_axis[i]);
    }
    diff |= bits(m.work_rotation) ^ bits(last_.work_rotation);
    const std::uint32_t ints = static_cast<std::uint32_t>((m.tool ^ last_.tool) | (m.turns ^ last_.turns) |
                                                          (m.file ^ last_.file) |
                                                          (static_cast<std::int32_t>(m.plane) ^ last_.plane));
    return (diff | ints) == 0 && !m.surface.active();
}

void Path::push(const Motion& m) {
    // Everything is read from the Motion first and the byte columns are written last: a byte
    // store may alias anything, so after one the compiler reloads what it had in registers.
    const double u = m.unit;
    const auto k = static_cast<std::uint8_t>(m.kind);
    const std::int8_t sd = m.radius.side;
    const std::uint8_t gen = m.generated ? 1 : 0;
    const Vec3 off = m.tool_offset * u;
    if (size() >= room_.n) reserve(std::max<std::size_t>(2 * room_.n, 1024));
    if (size() >= warm_.next) [[unlikely]]
        warm_ahead();
    if (written_.rows.load(std::memory_order_relaxed)) [[unlikely]]
        written_.reset();
    const std::size_t row = size();
    const Vec3 from = m.start * u, to = m.end * u;
    // A start that is not the end before it, bit for bit, is kept (a jump).
    const bool jump = row == 0 || std::memcmp(from.data(), end.data() + 3 * row - 3, 3 * sizeof(double)) != 0;
    const bool arc = m.is_arc(), ranked = row % kRankRows == 0;
    // These two may throw (where a run of the feed starts, at a jump): before anything is
    // written, the feed taken back when the jump cannot be kept.
    feed.push(m.feed);
    if (jump) [[unlikely]] {
        try {
            push_jump(row, from);
        } catch (...) {
            feed.pop_back();
            throw;
        }
    }
    if (ranked) arc_rank_.push_unchecked(arc_centers_.size() / 3);
    if (arc) put3(arc_centers_.append_unchecked(3), Vec3(m.center * u));
    put3(end.append_unchecked(3), to);
    line.push_unchecked(m.line);
    if (all_uniform_ && same_row(m, off)) {  // the common case
        for (auto* c : {&tool_offset, &work_offset, &abc, &normal, &tool_axis}) c->push_same();
        for (auto* c : {&tool, &turns, &file}) c->push_same();
        work_rotation.push_same();
        plane.push_same();
    } else {
        push_row(m, off);
    }
    kind.push_unchecked(k);
    side.push_unchecked(sd);
    generated.push_unchecked(gen);
}

void Path::push_jump(std::size_t row, const Vec3& from) {
    jump_rows_.push_back(row);
    try {
        jump_starts_.insert(jump_starts_.end(), from.data(), from.data() + 3);
    } catch (...) {
        jump_rows_.pop_back();
        throw;
    }
}

namespace {
// The bits in which two values differ (0: the same, bit for bit), without a branch.
template <class T>
std::uint64_t differ(const T& a, const T& b) {
    if constexpr (std::is_floating_point_v<T>)
        return std::bit_cast<std::uint64_t>(a) ^ std::bit_cast<std::uint64_t>(b);
    else
        return static_cast<std::uint64_t>(a != b);
}
std::uint64_t differ3(const Vec3& a, const Vec3& b) { return differ(a.x(), b.x()) | differ(a.y(), b.y()) | differ(a.z(), b.z()); }
}  // namespace

// Every field push(), same_row() and push_row() read (a centre only matters on arcs).
bool Path::same_segment(const Motion& a, const Motion& b) {
    std::uint64_t d = differ(a.unit, b.unit) | differ(a.kind, b.kind) | differ(a.plane, b.plane) |
                      differ(a.radius.side, b.radius.side) | differ(a.generated, b.generated) |
                      differ3(a.start, b.start) | differ3(a.end, b.end) | differ(a.line, b.line) |
                      differ(a.feed, b.feed) | differ(a.turns, b.turns) | differ(a.file, b.file) |
                      differ(a.tool, b.tool) | differ3(a.tool_offset, b.tool_offset) |
                      differ3(a.work_offset, b.work_offset) | differ(a.work_rotation, b.work_rotation) |
                      differ3(a.surface.normal, b.surface.normal) | differ3(a.tool_axis, b.tool_axis);
    for (std::size_t i = 0; i < 3; ++i) d |= differ(a.abc[i], b.abc[i]);
    if (a.is_arc()) d |= differ3(a.center, b.center);
    return d == 0;
}

Path::Path(const Path& o, std::size_t rows)
    : kind(o.kind.data(), rows),
      end(o.end.data(), 3 * rows),
      tool_offset(o.tool_offset, rows),
      work_offset(o.work_offset, rows),
      work_rotation(o.work_rotation, rows),
      abc(o.abc, rows),
      normal(o.normal, rows),
      tool_axis(o.tool_axis, rows),
      line(o.line.data(), rows),
      tool(o.tool, rows),
      turns(o.turns, rows),
      feed(o.feed, rows),
      side(o.side.data(), rows),
      plane(o.plane, rows),
      generated(o.generated.data(), rows),
      file(o.file, rows),
      files(o.files),
      rates(o.rates) {
    const std::size_t jumps = static_cast<std::size_t>(
        std::lower_bound(o.jump_rows_.begin(), o.jump_rows_.end(), static_cast<std::uint64_t>(rows)) -
        o.jump_rows_.begin());
    jump_rows_.insert(jump_rows_.end(), o.jump_rows_.data(), o.jump_rows_.data() + jumps);
    jump_starts_.insert(jump_starts_.end(), o.jump_starts_.data(), o.jump_starts_.data() + 3 * jumps);
    const std::size_t ranks = (rows + kRankRows - 1) / kRankRows;
    arc_rank_.insert(arc_rank_.end(), o.arc_rank_.data(), o.arc_rank_.data() + ranks);
    std::size_t arcs = 0;
    for (std::size_t i = 0; i < rows; ++i) arcs += arc_row(kind[i]);
    arc_centers_.insert(arc_centers_.end(), o.arc_centers_.data(), o.arc_centers_.data() + 3 * arcs);
    room_.n = rows;
    // The last segment's uniform row, as push() left it.
    if (rows > 0) {
        const std::size_t r = rows - 1;
        for (int k = 0; k < 3; ++k) {
            last_.tool_offset[k] = tool_offset(r, k);
            last_.work_offset[k] = work_offset(r, k);
            last_.abc[k] = abc(r, k);
            last_.normal[k] = normal(r, k);
            last_.tool_axis[k] = tool_axis(r, k);
        }
        last_.work_rotation = work_rotation(r);
        last_.tool = tool(r);
        last_.turns = turns(r);
        last_.file = file(r);
        last_.plane = plane(r);
    }
    all_uniform_ = rows > 0 && tool_offset.uniform() && work_offset.uniform() && work_rotation.uniform() && abc.uniform() && normal.uniform() && tool_axis.uniform() &&
                   tool.uniform() && turns.uniform() && file.uniform() && plane.uniform();
}

// The uniform values of a segment that differs from the last one (or follows one that did).
void Path::push_row(const Motion& m, const Vec3& off) {
    const Vec3 n = m.surface.active() ? Vec3(m.surface.normal.normalized()) : m.surface.normal;
    UniformRow r;
    for (int i = 0; i < 3; ++i) {
        r.tool_offset[i] = off[i];
        r.work_offset[i] = m.work_offset[i] * m.unit;
        r.abc[i] = m.abc[static_cast<std::size_t>(i)];
        r.normal[i] = n[i];
        r.tool_axis[i] = m.tool_axis[i];
    }
    r.work_rotation = m.work_rotation;
    r.tool = m.tool;
    r.turns = m.turns;
    r.file = m.file;
    r.plane = static_cast<std::int32_t>(m.plane);
    try {
        tool_offset.push(r.tool_offset);
        work_offset.push(r.work_offset);
        work_rotation.push(&r.work_rotation);
        abc.push(r.abc);
        normal.push(r.normal);
        tool_axis.push(r.tool_axis);
        tool.push(r.tool);
        turns.push(r.turns);
        file.push(r.file);
        plane.push(static_cast<std::uint8_t>(r.plane));
    } catch (...) {
        // A uniform column could not grow: the row written before is taken back, so that
        // the columns checked only through kind's size never run past their room.
        const std::size_t row = end.size() / 3 - 1;
        for (int i = 0; i < 3; ++i) end.pop_back();
        if (!jump_rows_.empty() && jump_rows_.back() == row) {
            jump_rows_.pop_back();
            for (int i = 0; i < 3; ++i) jump_starts_.pop_back();
        }
        if (row % kRankRows == 0) arc_rank_.pop_back();
        if (m.is_arc())
            for (int i = 0; i < 3; ++i) arc_centers_.pop_back();
        line.pop_back();
        feed.pop_back();
        throw;
    }
    all_uniform_ = tool_offset.uniform() && work_offset.uniform() && work_rotation.uniform() && abc.uniform() && normal.uniform() && tool_axis.uniform() &&
                   tool.uniform() && turns.uniform() && file.uniform() && plane.uniform();
    last_ = r;
}

Motion Path::segment(std::size_t i) const {
    Motion m;
    m.kind = static_cast<MotionKind>(kind[i]);
    m.plane = static_cast<Plane>(plane(i));
    m.start = start_at(i);
    m.end = get3(end, i);
    m.center = center_at(i);
    m.turns = turns(i);
    m.abc = {abc(i, 0), abc(i, 1), abc(i, 2)};
    m.feed = feed[i];
    m.line = line[i];
    m.file = file(i);
    m.tool = tool(i);
    m.tool_offset = get3(tool_offset, i);
    m.work_offset = get3(work_offset, i);
    m.work_rotation = work_rotation(i);
    m.surface.normal = get3(normal, i);
    m.tool_axis = get3(tool_axis, i);
    m.radius.side = side[i];
    m.generated = generated[i] != 0;
    return m;
}

Vec3 Path::machine_end_at(std::size_t i) const {
    Vec3 p = get3(end, i);
    if (const double r = work_rotation(i); r != 0) {
        const double c = std::cos(r * kPi / 180), s = std::sin(r * kPi / 180), x = p.x(), y = p.y();
        p.x() = c * x - s * y;
        p.y() = s * x + c * y;
    }
    return p + get3(work_offset, i) + get3(tool_offset, i);
}

void Path::sample(double tolerance, std::vector<double>& points, std::vector<std::int64_t>& seg) const {
    points.clear();
    seg.clear();
    if (size() == 0) return;
    put3(points, start_at(0));
    seg.push_back(0);
    for (std::size_t i = 0; i < size(); ++i) {
        Motion m = segment(i);
        if (i > 0 && (m.start - get3(end, i - 1)).norm() > tol::length) {
            put3(points, m.start);  // a jump (should not happen in a continuous path)
            seg.push_back(static_cast<std::int64_t>(i));
        }
        if (m.is_arc()) {
            Arc a = m.arc();
            int n = arc_chords(a, tolerance);
            for (int k = 1; k <= n; ++k) {
                put3(points, arc_point(a, static_cast<double>(k) / n));
                seg.push_back(static_cast<std::int64_t>(i));
            }
        } else {
            put3(points, m.end);
            seg.push_back(static_cast<std::int64_t>(i));
        }
    }
}

double Path::length(bool include_rapids) const {
    double total = 0;
    for (std::size_t i = 0; i < size(); ++i) {
        if (!include_rapids && kind[i] == static_cast<std::uint8_t>(MotionKind::rapid)) continue;
        Motion m = segment(i);
        total += m.is_arc() ? arc_length(m.arc()) : (m.end - m.start).norm();
    }
    return total;
}

void Path::contact_points(double r, double r2, std::vector<double>& out) const {
    out.assign(3 * size(), std::numeric_limits<double>::quiet_NaN());
    for (std::size_t i = 0; i < size(); ++i) {
        const Vec3 n = get3(normal, i);
        if (std::isnan(n.x())) continue;
        const Vec3 c = contact_point(get3(end, i), n, get3(tool_axis, i), r, r2);
        out[3 * i] = c.x(), out[3 * i + 1] = c.y(), out[3 * i + 2] = c.z();
    }
}

}  // namespace toolcomp
