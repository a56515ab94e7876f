// Inputs the fuzz targets (fuzz/, `make fuzz`) once crashed on, replayed through the same
// code: tests/programs/fuzz_regressions/<target>/<file>, where <target> names the function
// of fuzz/fuzz_targets.hpp and the file holds the fuzzer's input byte for byte (for
// iso_parse and pipeline its first byte selects dialect and mode). Each must end in success
// or a toolcomp::Error; never another exception (and, in `make test-sanitize`, never a
// sanitizer report).
#include <catch2/catch.hpp>

#include "fuzz_targets.hpp"
#include "toolcomp/geometry/arc.hpp"

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#ifndef TOOLCOMP_TEST_DATA
#define TOOLCOMP_TEST_DATA "tests/programs"
#endif

using namespace toolcomp;
namespace fs = std::filesystem;

namespace {

using Runner = fuzz::Outcome (*)(const std::uint8_t*, std::size_t);

const std::map<std::string, Runner>& runners() {
    static const std::map<std::string, Runner> m = {
        {"iso_parse", &fuzz::iso_parse},
        {"heidenhain_parse", &fuzz::heidenhain_parse},
        {"sinumerik_parse", &fuzz::sinumerik_parse},
        {"pipeline", &fuzz::pipeline},
        {"table_linuxcnc", [](const std::uint8_t* d, std::size_t n) { return fuzz::table(TableFormat::linuxcnc, d, n); }},
        {"table_csv", [](const std::uint8_t* d, std::size_t n) { return fuzz::table(TableFormat::csv, d, n); }},
        {"table_json", [](const std::uint8_t* d, std::size_t n) { return fuzz::table(TableFormat::json, d, n); }},
        {"table_heidenhain",
         [](const std::uint8_t* d, std::size_t n) { return fuzz::table(TableFormat::heidenhain, d, n); }},
        {"table_sinumerik",
         [](const std::uint8_t* d, std::size_t n) { return fuzz::table(TableFormat::sinumerik, d, n); }},
        {"tc_dp", &fuzz::tc_dp},
    };
    return m;
}

std::string bytes_of(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

}  // namespace

TEST_CASE("saved fuzz inputs end in a result or a toolcomp::Error", "[fuzz]") {
    const fs::path root = fs::path(TOOLCOMP_TEST_DATA) / "fuzz_regressions";
    REQUIRE(fs::is_directory(root));
    int replayed = 0;
    for (const auto& dir : fs::directory_iterator(root)) {
        if (!dir.is_directory()) continue;
        const std::string target = dir.path().filename().string();
        INFO("target folder " << target);
        REQUIRE(runners().count(target) == 1);
        std::vector<fs::path> files;
        for (const auto& f : fs::directory_iterator(dir.path()))
            if (f.is_regular_file()) files.push_back(f.path());
        std::sort(files.begin(), files.end());
        for (const fs::path& f : files) {
            INFO("input " << f.string());
            const std::string data = bytes_of(f);
            fuzz::Outcome outcome = fuzz::Outcome::ok;
            CHECK_NOTHROW(outcome = runners().at(target)(reinterpret_cast<const std::uint8_t*>(data.data()), data.size()));
            CHECK((outcome == fuzz::Outcome::ok || outcome == fuzz::Outcome::error));
            ++replayed;
        }
    }
    CHECK(replayed > 0);
}

TEST_CASE("integer words beyond the int range are refused, not wrapped", "[fuzz]") {
    auto run_text = [](const std::string& text, Dialect d = Dialect::linuxcnc) {
        const Program p = parse_program(text, d);
        return run(p, &fuzz::pipeline_tools());
    };
    // T4294967297 wrapped round to tool 1 before.
    CHECK_THROWS_WITH(run_text("G21\nT4294967297 M6\nM2\n"), Catch::Contains("not found"));
    CHECK_THROWS_AS(run_text("G21\nM4294967299\nM2\n", Dialect::fanuc), ProgramError);
    CHECK_THROWS_AS(run_text("G21\nM99999999999999999999\nM2\n"), ProgramError);
    CHECK_THROWS_AS(run_text("G21\nG10 L2 P1e12 X1\nM2\n"), Error);
    CHECK_THROWS_AS(run_text("G21\nG10 L2 P99999999999 X1\nM2\n"), ProgramError);
    CHECK_THROWS_AS(run_text("G21\nG10 L99999999999 P1 X1\nM2\n"), ProgramError);
    // A full circle of 2^31 - 1 turns is one segment: it runs (or is refused), it does not wrap.
    try {
        const Result r = run_text("G21\nG0 X0 Y0\nG2 X0 Y0 I1 P99999999999 F100\nM2\n");
        CHECK(r.path.size() >= 1);
    } catch (const Error&) {
    }
    CHECK_THROWS_AS(run_text("G21\nG41 D99999999999\nM2\n"), ProgramError);
    CHECK_THROWS_AS(run_text("G21\nG43 H99999999999\nM2\n"), ProgramError);
    CHECK_THROWS_AS(run_text("G21\nM61 Q99999999999\nM2\n"), ProgramError);
}

TEST_CASE("canned cycle repeats count toward the block limit", "[fuzz]") {
    ControlProfile prof = profile_for(Dialect::linuxcnc);
    prof.block_limit = 1000;
    RunOptions opt;
    opt.profile = prof;
    const Program p = parse_program("G21 G17 G91 F100\nG0 Z10\nG81 X1 Y0 Z-5 R2 L2147483647\nM2\n", Dialect::linuxcnc);
    CHECK_THROWS_WITH(run(p, nullptr, opt), Catch::Contains("block_limit") || Catch::Contains("blocks executed"));
    const Program few = parse_program("G21 G17 G91 F100\nG0 Z10\nG81 X1 Y0 Z-5 R2 L50\nM2\n", Dialect::linuxcnc);
    CHECK(run(few, nullptr, opt).ok());
}

TEST_CASE("arc_chords refuses counts that do not fit in memory", "[fuzz]") {
    Arc a;
    a.start = {1, 0, 0};
    a.end = {1, 0, 0};
    a.center = {0, 0, 0};
    a.turns = 1000000;
    CHECK(arc_chords(a, 0.1) > 1000000);
    CHECK_THROWS_AS(arc_chords(a, 1e-9), Error);
}
