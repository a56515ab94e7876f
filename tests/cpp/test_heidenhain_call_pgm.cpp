// Heidenhain CALL PGM: the called program is looked up in RunOptions::search_path only and
// run inline (Q parameters and position shared, compensation cancelled by the call), its
// moves carry the line numbers of the called file.
#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "heidenhain_helpers.hpp"
#include "toolcomp/program/diagnostic.hpp"

using namespace toolcomp;
using tctest::hh::col;
namespace fs = std::filesystem;

namespace {

const std::string kData = std::string(TOOLCOMP_TEST_DATA) + "/heidenhain";
const std::string kTables = std::string(TOOLCOMP_TEST_DATA) + "/tables";  // holds no programs

// A fresh directory under the system temp directory, removed at scope exit.
struct TempDir {
    fs::path path;
    TempDir() {
        static std::atomic<int> n{0};
        const auto stamp = std::chrono::steady_clock::now().time_since_epoch().count();
        path = fs::temp_directory_path() / ("toolcomp_hh_call_" + std::to_string(stamp) + "_" + std::to_string(n++));
        fs::create_directories(path);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
    void write(const std::string& name, const std::string& text) const {
        std::ofstream(path / name, std::ios::binary) << text;
    }
    std::string str() const { return path.string(); }
};

Result run_file(const std::string& file, const std::vector<std::string>& search_path,
                std::optional<ControlProfile> profile = std::nullopt) {
    RunOptions o;
    o.search_path = search_path;
    o.profile = std::move(profile);
    return run(read_program(file), nullptr, o);
}

Result run_text_in(const std::string& text, const std::vector<std::string>& search_path) {
    RunOptions o;
    o.search_path = search_path;
    o.start = Vec3::Zero();  // the paths below count the first move from machine zero
    return run(parse_program(text, Dialect::heidenhain), nullptr, o);
}

struct Caught {
    std::string code, message;
    int line = 0, column = 0;
    ErrorKind kind = ErrorKind::generic;
};

template <class F>
Caught caught(F&& f) {
    Caught c;
    try {
        f();
    } catch (const Error& e) {
        c = {e.code(), e.what(), e.line(), e.column(), e.kind()};
    }
    return c;
}

const std::string kMainHead = "0 BEGIN PGM M MM\n1 TOOL DEF 1 L+0 R+2\n2 TOOL CALL 1 Z\n3 L X+0 Y-10 Z+0 R0 F100\n";

}  // namespace

TEST_CASE("heidenhain CALL PGM runs the called program inline with shared Q parameters", "[heidenhain][call_pgm]") {
    // call_main.h: Q1 = 10, CALL PGM SUB1, L X+Q2 Y+0, CALL PGM SUB1. sub1.h (file name in
    // lower case, found as SUB1 + ".h"): L X+Q1 IY+5; Q2 = Q1 + 7; Q1 = Q1 + 1.
    // First call: (10,5), Q2 = 17, Q1 = 11; main: (17,0); second call: (11,5).
    const Result r = run_file(kData + "/call_main.h", {kData});
    const Path& p = r.path;
    REQUIRE(p.size() == 3);
    CHECK(col(p.end, 0) == Vec3(10, 5, 0));
    CHECK(col(p.end, 1) == Vec3(17, 0, 0));
    CHECK(col(p.starts(), 2) == Vec3(17, 0, 0));  // the position carries into the called program
    CHECK(col(p.end, 2) == Vec3(11, 5, 0));
    // Lines: source line 2 of sub1.h, source line 7 of call_main.h, line 2 of sub1.h again.
    CHECK(std::vector<std::int32_t>(p.line.begin(), p.line.end()) == std::vector<std::int32_t>{2, 7, 2});
    CHECK(r.ok());
}

TEST_CASE("heidenhain CALL PGM looks only in the search path, in order", "[heidenhain][call_pgm]") {
    SECTION("the second directory") {
        const Result r = run_file(kData + "/call_main.h", {kTables, kData});
        CHECK(r.path.size() == 3);
    }
    SECTION("not in the search path: the program's own directory is not searched") {
        const Caught c = caught([] { run_file(kData + "/call_main.h", {kTables}); });
        CHECK(c.kind == ErrorKind::program);
        CHECK(c.code == "call_pgm_not_found");
        CHECK(c.line == 6);  // "5 CALL PGM SUB1" is source line 6, CALL in column 3
        CHECK(c.column == 3);
        CHECK_THAT(c.message, Catch::Contains("SUB1") && Catch::Contains("not found") && Catch::Contains(kTables));
    }
    SECTION("no search path") {
        const Caught c = caught([] { run_file(kData + "/call_main.h", {}); });
        CHECK(c.code == "call_pgm_not_found");
        CHECK(c.line == 6);
        CHECK_THAT(c.message, Catch::Contains("no search path"));
    }
}

TEST_CASE("heidenhain CALL PGM names: suffix, case, TNC drive, no way out", "[heidenhain][call_pgm]") {
    auto main_calling = [](const std::string& name) {
        return "0 BEGIN PGM M MM\n1 TOOL DEF 1 L+0 R+0\n2 TOOL CALL 1 Z\n3 FN 0: Q1 = +1\n4 L X+0 Y+0 Z+0 R0 F100\n"
               "5 CALL PGM " + name + "\n6 END PGM M MM\n";
    };
    for (const std::string name : {"sub1.h", "SUB1.H", "Sub1", "TNC:\\SUB1.H", "\"SUB1\""}) {
        INFO(name);
        const Result r = run_text_in(main_calling(name), {kData});
        REQUIRE(r.path.size() == 1);
        CHECK(col(r.path.end, 0) == Vec3(1, 5, 0));
    }
    // A relative directory below the search directory, with the TNC's separators.
    const Result r = run_text_in(main_calling("HEIDENHAIN\\SUB1"), {std::string(TOOLCOMP_TEST_DATA)});
    CHECK(r.path.size() == 1);
    // '..' would leave the search directories: refused.
    const Caught c = caught([&] { run_text_in(main_calling("..\\heidenhain\\sub1"), {kTables}); });
    CHECK(c.code == "call_pgm_bad_name");
    CHECK(c.line == 6);
}

TEST_CASE("heidenhain CALL PGM cancels radius compensation", "[heidenhain][call_pgm]") {
    // RL with r = 2 along +X to (20,0); the call cancels compensation: the last compensated
    // move ends perpendicular at (20,2), the called program's move is uncompensated.
    TempDir d;
    d.write("S.h", "0 BEGIN PGM S MM\n1 L X+20 Y+20\n2 END PGM S MM\n");
    const Result r = run_text_in(kMainHead + "4 L X+0 Y+0 RL\n5 L X+20 Y+0\n6 CALL PGM S\n7 END PGM M MM\n", {d.str()});
    const Path& p = r.path;
    REQUIRE(p.size() >= 2);
    const std::size_t last = p.size() - 1;
    CHECK(p.line[last] == 2);
    CHECK(p.side[last] == 0);
    CHECK(col(p.starts(), last) == Vec3(20, 2, 0));
    CHECK(col(p.end, last) == Vec3(20, 20, 0));
    CHECK(p.line[last - 1] == 6);
    CHECK(p.side[last - 1] == 1);
    CHECK(col(p.end, last - 1) == Vec3(20, 2, 0));
}

TEST_CASE("heidenhain CALL PGM: recursion depth, block limit, errors in the called file", "[heidenhain][call_pgm]") {
    TempDir d;
    SECTION("a program calling itself stops at the nesting limit") {
        d.write("REC.h", "0 BEGIN PGM REC MM\n1 CALL PGM REC\n2 END PGM REC MM\n");
        const Caught c = caught([&] { run_text_in(kMainHead + "4 CALL PGM REC\n5 END PGM M MM\n", {d.str()}); });
        CHECK(c.code == "call_pgm_depth");
        CHECK(c.line == 2);  // the CALL block of REC.h
        CHECK_THAT(c.message, Catch::Contains("100"));
    }
    SECTION("the block limit counts the called program's blocks") {
        // call_main.h: blocks 1..6 up to the CALL, then sub1.h: BEGIN (7), L (8), FN (9).
        ControlProfile prof = profile_for(Dialect::heidenhain);
        prof.block_limit = 8;
        const Caught c = caught([&] { run_file(kData + "/call_main.h", {kData}, prof); });
        CHECK(c.code == "block_limit");
        CHECK(c.line == 3);
    }
    SECTION("a syntax error in the called program, at its line") {
        d.write("BAD.h", "0 BEGIN PGM BAD MM\n1 L X+1 Y+1\n2 L X+2 Y&\n3 END PGM BAD MM\n");
        const Caught c = caught([&] { run_text_in(kMainHead + "4 CALL PGM BAD\n5 END PGM M MM\n", {d.str()}); });
        CHECK(c.kind == ErrorKind::parse);
        CHECK(c.line == 3);
        CHECK_THAT(c.message, Catch::Contains("called program") && Catch::Contains("BAD.h"));
    }
    SECTION("other units are refused") {
        d.write("IN.h", "0 BEGIN PGM IN INCH\n1 L X+1\n2 END PGM IN INCH\n");
        const Caught c = caught([&] { run_text_in(kMainHead + "4 CALL PGM IN\n5 END PGM M MM\n", {d.str()}); });
        CHECK(c.code == "call_pgm_units");
        CHECK(c.line == 5);
    }
    SECTION("M30 in the called program ends the run, with a warning") {
        d.write("END.h", "0 BEGIN PGM END MM\n1 L X+5 Y-10\n2 M30\n3 END PGM END MM\n");
        const Result r = run_text_in(kMainHead + "4 CALL PGM END\n5 L X+50 Y+50\n6 END PGM M MM\n", {d.str()});
        REQUIRE(r.path.size() == 2);
        CHECK(col(r.path.end, 1) == Vec3(5, -10, 0));
        REQUIRE(r.diagnostics.size() == 1);
        CHECK(r.diagnostics[0].code == "call_pgm_end");
        CHECK(r.diagnostics[0].severity == Severity::warning);
    }
}
