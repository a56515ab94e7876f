#pragma once
// Path: a column store of segments (the numpy-facing result).
//
// Three-vectors are stored row-major (x0 y0 z0 x1 y1 z1 ...) so that Python sees (N, 3)
// float64 arrays without a copy. Three columns are kept as what they are and written out in
// full only when asked for (`starts()`, `centers()`, `feeds()`, once, then kept): a segment
// starts where the one before it ended, except at the first segment and at a jump (a new
// tool length offset moves the start in program coordinates), only arcs have a centre, and
// the feed changes now and then. That is 56 of the 87 bytes a segment on an ordinary
// program, and the memory a run writes costs time too (pages the kernel zeroes).
#include <atomic>
#include <cstdint>
#include <limits>
#include <mutex>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "toolcomp/column.hpp"
#include "toolcomp/control/rates.hpp"
#include "toolcomp/motion/motion.hpp"
#include "toolcomp/page_warmer.hpp"
#include "toolcomp/run_column.hpp"

namespace toolcomp {

/// N path segments as read-only numpy column views (no copies): lengths in mm, angles in
/// degrees, positions in program coordinates (work offsets not added, tool length offset in
/// `tool_offset`).
class Path : public MotionSink {
    static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

public:
    /// motion type of each segment, uint8 (N,): RAPID 0, LINE 1, ARC_CW 2, ARC_CCW 3
    Column<std::uint8_t> kind;
    /// end point of each segment, float64 (N, 3), mm, program coordinates
    Column<double> end;                   // 3 per segment
    /// active tool length offset, float64 (N, 3), mm (X Y Z)
    Vec3Column tool_offset{0, 0, 0};
    // machine = Rz(work_rotation) * end + work_offset + tool_offset (Motion::work_offset).
    /// where the work coordinates lie in the machine's, float64 (N, 3), mm: machine_end =
    /// end + work_offset + tool_offset (with a work_rotation, the end rotated first)
    Vec3Column work_offset{0, 0, 0};
    /// rotation of the work coordinates about Z, float64 (N,), degrees (LinuxCNC G10 L2 R);
    /// 0 elsewhere
    UniformColumn<double, 1> work_rotation;
    /// rotary axes A B C at the segment end, float64 (N, 3), degrees
    Vec3Column abc{0, 0, 0};
    /// surface normal of 3D-compensated segments (Heidenhain LN), unit length; NaN elsewhere
    Vec3Column normal{kNaN, kNaN, kNaN};  // unit surface normal (3D compensation)
    /// unit tool axis (tip towards the spindle)
    Vec3Column tool_axis{0, 0, 1};
    /// source line of the block, int32 (N,), 1-based; an inserted corner piece carries the
    /// line of the block after the corner
    Column<std::int32_t> line;
    /// number of the tool in the spindle, int32 (N,)
    UniformColumn<std::int32_t, 1> tool, turns;
    RunColumn<double> feed;  // mm/min, NaN for rapids: kept as runs of one value
    /// cutter radius compensation, int8 (N,): +1 left (G41/RL), -1 right (G42/RR), 0 off
    Column<std::int8_t> side;
    /// working plane of each segment: 0 XY (G17), 1 ZX (G18), 2 YZ (G19)
    UniformColumn<std::uint8_t, 1> plane;
    /// bool (N,): True where a compensation stage inserted the segment (corner arcs,
    /// extension blocks)
    Column<std::uint8_t> generated;  // bool as byte
    /// file of the block, int32 (N,): index into `files` (0 = the main program)
    UniformColumn<std::int32_t, 1> file;  // index into `files` of the file the block is in
    /// names of the files segments come from: the main program, then each called program or
    /// subprogram file in the order the run entered it
    std::vector<std::string> files;
    // The rates of the machine the path was run on, for the time it takes (Path.duration).
    MachineRates rates;

    Path() = default;
    // The first `rows` segments of `other`, stored as `other` stores them (room for no more).
    Path(const Path& other, std::size_t rows);
    Path(const Path&) = default;
    Path& operator=(const Path&) = default;
    Path(Path&&) = default;
    Path& operator=(Path&&) = default;

    /// number of segments
    std::size_t size() const { return kind.size(); }
    void reserve(std::size_t n);
    // reserve(n), or where the system refuses (an address-space limit, `ulimit -v`, strict
    // overcommit) half as much, down to none: a head start lost, not an error (the columns
    // grow as segments come). An empty Path gives back what a refused attempt took.
    void reserve_granted(std::size_t n);
    // Gives back the columns' memory beyond the segments (once the Path is complete).
    void release_unused() noexcept;
    void push(const Motion& m) override;
    // Whether push() stores the same row for `a` as for `b` after the same segments (the
    // fields push() reads, bit for bit).
    static bool same_segment(const Motion& a, const Motion& b);
    // Has `warmer` fault in the pages of the rows ahead of push() on its thread (large
    // reservations only; nullptr: no more). Neither copied nor moved with the Path.
    void warm_with(PageWarmer* warmer);
    // Segment i back as a Motion (for sampling, checks and later stages).
    Motion segment(std::size_t i) const;
    // The end of segment i in machine coordinates (mm): Rz(work_rotation) end + work_offset +
    // tool_offset.
    Vec3 machine_end_at(std::size_t i) const;
    // Start point and arc centre of segment i (NaN centre for rapids and lines).
    Vec3 start_at(std::size_t i) const;
    Vec3 center_at(std::size_t i) const;
    // Every segment's start point, resp. centre (3 per segment), feed: written out at the
    // first call and kept with the Path (thread-safe; a push() drops them).
    /// start point of each segment, float64 (N, 3), mm, program coordinates (written out at
    /// the first access: stored, a segment starts where the one before ended)
    std::span<const double> starts() const;
    /// arc centre, float64 (N, 3), mm, program coordinates; NaN for rapids and lines
    /// (written out at the first access: only arcs' are stored)
    std::span<const double> centers() const;
    /// feed rate, float64 (N,), mm/min; NaN for rapids (written out at the first access:
    /// stored where it changes)
    std::span<const double> feeds() const;
    // Bytes the columns hold (as stored, and what starts()/centers()/feeds() wrote out).
    /// bytes the columns hold as stored (start and center once written out included)
    std::size_t bytes() const;

    // Polyline with arcs chorded within `tolerance` (mm). The first point is the start of
    // segment 0; every point carries the index of the segment it ends.
    /// The path as an (M, 3) polyline with arcs chorded within `tolerance` mm, and the
    /// index of the segment each point belongs to.
    void sample(double tolerance, std::vector<double>& points, std::vector<std::int64_t>& seg) const;
    /// Path length in mm (arcs exact).
    double length(bool include_rapids = true) const;
    // Where a tool of radius r and corner radius r2 touches the surface at the end of each
    // segment with a surface normal (3D compensation); NaN rows elsewhere. mm.
    /// Where a tool of radius r and corner radius r2 at the segment ends touches the
    /// surface (segments with a normal; NaN elsewhere), (N, 3) mm.
    void contact_points(double r, double r2, std::vector<double>& out) const;

private:
    // A segment's values of the uniform columns.
    struct UniformRow {
        double tool_offset[3], work_offset[3], abc[3], normal[3], tool_axis[3];
        double work_rotation;
        std::int32_t tool, turns, file, plane;
    };
    // The last segment's row, and whether every uniform column was still uniform after it:
    // then a segment with the same row (bit for bit) only counts one more row in each.
    UniformRow last_{};
    bool all_uniform_ = false;
    bool same_row(const Motion& m, const Vec3& offset) const;
    void push_row(const Motion& m, const Vec3& offset);
    // Segments every column but the uniform ones has room for: push() checks once a segment.
    // A copy keeps the columns' capacity, and this with it; a moved-from Path has none.
    struct Room {
        std::size_t n = 0;
        Room() = default;
        Room(const Room&) = default;
        Room& operator=(const Room&) = default;
        Room(Room&& o) noexcept : n(std::exchange(o.n, 0)) {}
        Room& operator=(Room&& o) noexcept {
            n = std::exchange(o.n, 0);
            return *this;
        }
    } room_;
    // The warmer, the rows asked for, and the row at which push() asks for the next stretch.
    struct Warm {
        PageWarmer* by = nullptr;
        std::size_t rows = 0;
        std::size_t next = static_cast<std::size_t>(-1);
        std::size_t arcs = 0;  // arc centre rows asked for
        Warm() = default;
        Warm(const Warm&) {}
        Warm& operator=(const Warm&) {
            by = nullptr;
            rows = 0;
            next = static_cast<std::size_t>(-1);
            arcs = 0;
            return *this;
        }
    } warm_;
    void warm_ahead();

    // Start points: the rows whose start is not the end before them (bit for bit; row 0
    // always), with those starts. Centres: the arcs' only, in row order, and the arcs before
    // every kRankRows-th row (for center_at).
    static constexpr std::size_t kRankRows = 256;
    static bool arc_row(std::uint8_t k) {
        return k == static_cast<std::uint8_t>(MotionKind::arc_cw) || k == static_cast<std::uint8_t>(MotionKind::arc_ccw);
    }
    Column<std::uint64_t> jump_rows_;
    Column<double> jump_starts_;
    Column<double> arc_centers_;
    Column<std::uint64_t> arc_rank_;
    void push_jump(std::size_t row, const Vec3& from);
    // starts(), centers() and feeds() once written out (a column is written when it holds
    // fewer values than the Path asks of it): made at the first call (the first of two
    // threads to get there wins), moved with the Path, not copied (a copy writes its own),
    // dropped by push().
    struct Rows {
        std::mutex mutex;
        Column<double> starts, centers, feeds;
    };
    struct Written {
        mutable std::atomic<Rows*> rows{nullptr};
        Written() = default;
        Written(const Written&) {}
        Written(Written&& o) noexcept : rows(o.rows.exchange(nullptr)) {}
        Written& operator=(const Written& o) {
            if (this != &o) reset();
            return *this;
        }
        Written& operator=(Written&& o) noexcept {
            if (this != &o) {
                reset();
                rows = o.rows.exchange(nullptr);
            }
            return *this;
        }
        ~Written() { reset(); }
        void reset() noexcept { delete rows.exchange(nullptr); }
        Rows& get() const;
    } written_;
};

}  // namespace toolcomp
