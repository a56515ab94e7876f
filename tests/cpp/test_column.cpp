#include <catch2/catch.hpp>

#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <thread>

#include "toolcomp/column.hpp"

using toolcomp::Vec3Column;

TEST_CASE("Vec3Column stores nothing while every row equals the fill, then every row") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    Vec3Column c(nan, nan, nan);
    c.push(nan, nan, nan);
    c.push(nan, nan, nan);
    CHECK(c.uniform());
    CHECK(c.size() == 2);
    CHECK(std::isnan(c(1, 2)));
    c.push(0, 0, 1);  // differs: the two rows before are written out
    c.push(nan, nan, nan);
    REQUIRE_FALSE(c.uniform());
    CHECK(c.size() == 4);
    CHECK(std::isnan(c(0, 0)));
    CHECK(c(2, 2) == 1);
    CHECK(c.data()[3 * 2 + 2] == 1);
    CHECK(std::isnan(c(3, 1)));
}

TEST_CASE("Vec3Column tells -0.0 from 0.0 (bit for bit)") {
    Vec3Column c(0, 0, 1);
    c.push(-0.0, 0, 1);
    c.push(0, 0, 1);
    CHECK_FALSE(c.uniform());
    CHECK(std::signbit(c(0, 0)));
    CHECK_FALSE(std::signbit(c(1, 0)));
}

TEST_CASE("UniformColumn: the first row is the fill") {
    toolcomp::UniformColumn<std::int32_t, 1> tool;  // constructed with 0
    CHECK(tool.fill()[0] == 0);
    for (int i = 0; i < 5; ++i) tool.push(7);
    CHECK(tool.uniform());
    CHECK(tool.size() == 5);
    CHECK(tool(4) == 7);
    tool.push(3);
    REQUIRE_FALSE(tool.uniform());
    CHECK(tool.size() == 6);
    CHECK(tool.data()[0] == 7);
    CHECK(tool.data()[4] == 7);
    CHECK(tool.data()[5] == 3);
}

#if defined(__linux__)
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

namespace {
// How many of the pages [p, p + bytes) are in memory.
std::size_t resident_pages(const void* p, std::size_t bytes) {
    const std::size_t page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
    std::vector<unsigned char> in((bytes + page - 1) / page);
    REQUIRE(mincore(const_cast<void*>(p), bytes, in.data()) == 0);
    std::size_t n = 0;
    for (unsigned char c : in) n += c & 1;
    return n;
}
}  // namespace

TEST_CASE("Column: release_unused gives back the pages beyond the rows and keeps the rows") {
    toolcomp::Column<double> c;
    c.reserve(1 << 20);  // 8 MB mapped
    for (int i = 0; i < 3 * (1 << 16); ++i) c.push_back(i * 0.5);  // 1.5 MB written
    const std::size_t page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
    std::fill(c.data() + c.size(), c.data() + c.capacity(), 1.0);  // touch the capacity too
    const std::size_t used = c.size() * sizeof(double), cap = c.capacity() * sizeof(double);
    REQUIRE(resident_pages(c.data(), cap) == cap / page);
    toolcomp::release_unused(c);
    CHECK(resident_pages(c.data(), used) == used / page);
    CHECK(resident_pages(reinterpret_cast<const char*>(c.data()) + used, cap - used) == 0);
    for (int i = 0; i < 3 * (1 << 16); i += 997) REQUIRE(c[i] == i * 0.5);
    for (int i = 0; i < 1000; ++i) c.push_back(-i);  // grows into the given-back pages
    CHECK(c[3 * (1 << 16) + 999] == -999.0);
    CHECK(c[3 * (1 << 16) - 1] == (3 * (1 << 16) - 1) * 0.5);
}

TEST_CASE("Column: release_unused leaves heap columns and partly used pages alone") {
    toolcomp::Column<double> small(1000, 2.0);  // on the heap
    toolcomp::release_unused(small);
    CHECK(small[999] == 2.0);
    toolcomp::Column<std::uint8_t> bytes;
    bytes.reserve(1 << 20);
    bytes.resize(4097, 7);  // the second page is partly used: it stays
    toolcomp::release_unused(bytes);
    CHECK(bytes[4096] == 7);
    CHECK(resident_pages(bytes.data(), 8192) == 2);
}
#endif

TEST_CASE("Column: a value or range taken from the column itself survives its growth") {
    toolcomp::Column<double> c;
    c.push_back(1.5);
    while (c.size() < c.capacity()) c.push_back(2.5);
    const std::size_t full = c.size();
    c.push_back(c.front());  // full: the column moves while the value is read from it
    REQUIRE(c.size() == full + 1);
    CHECK(c.back() == 1.5);

    toolcomp::Column<int> d;
    for (int i = 0; i < 8; ++i) d.push_back(i);
    REQUIRE(d.size() == d.capacity());
    d.insert(d.end(), d.begin(), d.end());  // doubles the column from its own rows
    REQUIRE(d.size() == 16);
    for (int i = 0; i < 16; ++i) CHECK(d[static_cast<std::size_t>(i)] == i % 8);
    d.resize(100, d[3]);
    CHECK(d[99] == 3);
}

#if defined(__linux__)
TEST_CASE("column memory: a mapping freed is kept for the next allocation of its size") {
    const std::size_t bytes = (std::size_t{5} << 20) + 12345;  // three 2 MB pages
    void* a = toolcomp::detail::column_allocate(bytes);
    static_cast<char*>(a)[bytes - 1] = 1;  // written: its pages are in memory
    toolcomp::detail::column_deallocate(a, bytes);
    void* b = toolcomp::detail::column_allocate(bytes - 1000);  // the same three pages
    CHECK(b == a);
    void* c = toolcomp::detail::column_allocate(bytes);  // none kept any more: a new mapping
    CHECK(c != a);
    toolcomp::detail::column_deallocate(c, bytes);
    void* d = toolcomp::detail::column_allocate(std::size_t{8} << 20);  // another size: not the kept one
    CHECK(d != c);
    toolcomp::detail::column_deallocate(d, std::size_t{8} << 20);
    toolcomp::detail::column_deallocate(b, bytes - 1000);
}

TEST_CASE("column memory: a process forked while another thread allocates can allocate") {
    // The kept mappings' lock, held by the other thread at the moment of a fork, would stay
    // held in the child: the child would hang at its first allocation (alarm: fails).
    const std::size_t bytes = std::size_t{4} << 20;
    std::atomic<bool> stop{false};
    std::thread churn([&] {
        while (!stop) toolcomp::detail::column_deallocate(toolcomp::detail::column_allocate(bytes), bytes);
    });
    int bad = 0;
    for (int i = 0; i < 30; ++i) {
        const pid_t pid = fork();
        if (pid == 0) {
            alarm(10);
            toolcomp::detail::column_deallocate(toolcomp::detail::column_allocate(bytes), bytes);
            _exit(0);
        }
        int status = 0;
        waitpid(pid, &status, 0);
        bad += !(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    }
    stop = true;
    churn.join();
    CHECK(bad == 0);
}
#endif
