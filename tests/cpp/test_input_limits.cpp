// Reading a file whole within a size limit, and the line-length limit (input_limits.hpp).
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sys/stat.h>
#include <unistd.h>

#include "toolcomp/program/diagnostic.hpp"
#include "toolcomp/program/input_limits.hpp"

using namespace toolcomp;
namespace fs = std::filesystem;

namespace {
int line_too_long_at(std::string_view text, std::size_t max, bool cr) {
    try {
        check_line_lengths(text, max, cr);
    } catch (const ParseError& e) {
        CHECK(e.code() == "line_too_long");
        return e.line();
    }
    return 0;
}
}  // namespace

TEST_CASE("read_file_limited reads regular files up to the limit and nothing else") {
    const fs::path dir = fs::temp_directory_path() / ("toolcomp_limits_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::string file = (dir / "p.ngc").string();
    std::ofstream(file, std::ios::binary) << "G0 X1\n";

    FileText ok = read_file_limited(file, 6);
    CHECK(ok.status == FileText::ok);
    CHECK(ok.text == "G0 X1\n");
    CHECK(ok.size == 6);

    FileText big = read_file_limited(file, 5);
    CHECK(big.status == FileText::too_large);
    CHECK(big.size == 6);
    CHECK(big.text.empty());
    CHECK(std::string(read_error_code(big)) == "input_too_large");
    CHECK(read_error_text(big, 5) == "it is 6 bytes, more than the limit of 5 bytes (max_bytes)");

    FileText d = read_file_limited(dir.string(), 100);
    CHECK(d.status == FileText::not_regular);
    CHECK(d.detail == "a directory");

    const std::string fifo = (dir / "fifo").string();
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    FileText f = read_file_limited(fifo, 100);  // returns at once, no writer needed
    CHECK(f.status == FileText::not_regular);
    CHECK(f.detail == "a FIFO (named pipe)");

    CHECK(read_file_limited("/dev/zero", 100).status == FileText::not_regular);
    CHECK(read_file_limited((dir / "missing").string(), 100).status == FileText::cannot_open);

    try {
        read_program_text(file, 5);
        FAIL("expected input_too_large");
    } catch (const ParseError& e) {
        CHECK(e.code() == "input_too_large");
        CHECK(std::string(e.what()) ==
              "Cannot read program file '" + file + "': it is 6 bytes, more than the limit of 5 bytes (max_bytes)");
    }
    fs::remove_all(dir);
}

TEST_CASE("byte counts in messages") {
    CHECK(byte_count_text(0) == "0 bytes");
    CHECK(byte_count_text(1023) == "1023 bytes");
    CHECK(byte_count_text(1536) == "1536 bytes (1.5 KiB)");
    CHECK(byte_count_text(kDefaultMaxProgramBytes) == "2147483648 bytes (2.0 GiB)");
    CHECK(byte_count_text(std::uint64_t{10} << 30) == "10737418240 bytes (10.0 GiB)");
}

TEST_CASE("check_line_lengths finds the first line over the limit and its number") {
    CHECK(line_too_long_at("abcd", 4, false) == 0);
    CHECK(line_too_long_at("abcde", 4, false) == 1);
    CHECK(line_too_long_at("ab\nabcd\nabcde\n", 4, false) == 3);
    CHECK(line_too_long_at("ab\r\nabcd\r\n", 4, false) == 0);  // CRs of the line end do not count
    // ISO: a lone CR is no line end
    CHECK(line_too_long_at("ab\rab\nabc", 4, false) == 1);
    // Sinumerik / Heidenhain: it is one
    CHECK(line_too_long_at("ab\rab\nabc", 4, true) == 0);
    CHECK(line_too_long_at("ab\rab\rabcde\n", 4, true) == 3);
    CHECK(line_too_long_at("a\r\r\nb\rc\nabcde", 4, true) == 4);  // "\r\r\n" is one line end
    CHECK(line_too_long_at("a\r\rabcde", 4, true) == 3);         // two lone CRs: two line ends
    CHECK(line_too_long_at(std::string(10, '\n') + "abcde", 4, false) == 11);
    CHECK(line_too_long_at("", 0, false) == 0);
}
