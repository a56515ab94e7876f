// Heidenhain TOOL.T (TNC 426 layout): reading through the common tool model, lossless
// round trips, rewriting only a changed row, units, conversion, errors with their position.
#include <catch2/catch.hpp>

#include "toolcomp/program/diagnostic.hpp"
#include "toolcomp/tools/format_heidenhain.hpp"
#include "toolcomp/tools/tool_table.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#ifndef TOOLCOMP_TEST_DATA
#define TOOLCOMP_TEST_DATA "tests/programs"
#endif

using namespace toolcomp;
using Catch::Matchers::Contains;
using Catch::Matchers::EndsWith;

namespace {

std::string fixture(const std::string& name) {
    std::ifstream in(std::string(TOOLCOMP_TEST_DATA) + "/tables/" + name, std::ios::binary);
    REQUIRE(in.good());
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

std::string to_crlf(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '\n') out += '\r';
        out += c;
    }
    return out;
}

// Lines without their endings (a '\r' before '\n' is dropped too).
std::vector<std::string> lines_of(const std::string& s) {
    std::vector<std::string> out;
    std::stringstream ss(s);
    std::string l;
    while (std::getline(ss, l)) {
        if (!l.empty() && l.back() == '\r') l.pop_back();
        out.push_back(l);
    }
    return out;
}

struct Raised {
    std::string code;
    int line = -1, column = -1;
    std::string message;
};

Raised read_error(const std::string& text) {
    try {
        read_tool_table(text, TableFormat::heidenhain);
    } catch (const ToolTableError& e) {
        return {e.code(), e.line(), e.column(), e.what()};
    }
    FAIL("no error raised for:\n" << text);
    return {};
}

Raised write_error(const ToolTable& table) {
    try {
        write_tool_table(table, TableFormat::heidenhain);
    } catch (const ToolTableError& e) {
        return {e.code(), e.line(), e.column(), e.what()};
    }
    FAIL("no error raised on write");
    return {};
}

const ToolTable heidenhain(const std::string& text, LengthUnit u = LengthUnit::mm) {
    return read_tool_table(text, TableFormat::heidenhain, u);
}

std::string write_t(const ToolTable& t) { return write_tool_table(t, TableFormat::heidenhain); }

// A small table with one right-aligned value column.
const std::string kSmall =
    "BEGIN TOOL .T MM\n"
    "T    NAME        L         R       DOC\n"
    "1    MILL_A          +50.5 +4      first\n"
    "2    MILL_B            +61 +2.5    second\n"
    "[END]\n";

}  // namespace

TEST_CASE("heidenhain: TNC 426 TOOL.T values through the tool model", "[heidenhain]") {
    const ToolTable table = heidenhain(fixture("tnc426.t"));
    CHECK(table.units() == LengthUnit::mm);
    REQUIRE(table.source_format() == TableFormat::heidenhain);
    std::vector<int> numbers;
    for (const Tool& t : table.tools()) numbers.push_back(t.number);
    CHECK(numbers == std::vector<int>{0, 1, 2, 3, 5, 7, 12});

    const Tool& t0 = table.at(0);
    CHECK(t0.name == "NULLWERKZEUG");
    CHECK(t0.edge() == CuttingEdge{});

    const Tool& t1 = table.at(1);  // end mill with a radius undersize
    CHECK(t1.name == "SCHAFTFRAESER_10");
    CHECK(t1.comment == "SCHRUPPEN Z4");
    CHECK(t1.edge().length.z() == 95.25);
    CHECK(t1.edge().radius == 5);
    CHECK(t1.edge().corner_radius == 0);
    CHECK(t1.edge().radius_wear == -0.02);
    CHECK(t1.edge().effective_radius() == Approx(4.98));
    CHECK(t1.pocket == 0);

    const CuttingEdge& ball = table.at(2).edge();  // R2 = R
    CHECK(ball.radius == 3);
    CHECK(ball.corner_radius == 3);
    CHECK(ball.corner_radius_wear == 0.01);
    CHECK(ball.length.z() == 80.5);

    const CuttingEdge& torus = table.at(3).edge();  // 0 < R2 < R
    CHECK(torus.radius == 8);
    CHECK(torus.corner_radius == 1.5);
    CHECK(torus.length_wear.z() == 0.05);
    CHECK(torus.radius_wear == -0.015);
    CHECK(torus.length.x() == 0);
    CHECK(torus.length_wear.x() == 0);

    const Tool& drill = table.at(5);  // a name with a blank and a comma, empty DOC
    CHECK(drill.name == "BOHRER D8,5");
    CHECK(drill.comment.empty());
    CHECK(drill.edge().length.z() == 120.125);
    CHECK(drill.edge().radius == 4.25);

    const Tool& locked = table.at(7);  // empty numeric fields are 0
    CHECK(locked.name == "FASE_90");
    CHECK(locked.comment == "GESPERRT");
    CHECK(locked.edge() == CuttingEdge{});

    const Tool& utf8 = table.at(12);  // columns count characters, not bytes
    CHECK(utf8.name == "FR\xC3\x84SER_D20");
    CHECK(utf8.comment == "\xC3\x98"
                          "20 HM");
    CHECK(utf8.edge().length.z() == 150);
    CHECK(utf8.edge().radius == 10);
    CHECK(utf8.edge().length_wear.z() == -0.1);
}

TEST_CASE("heidenhain: read and write back unchanged is byte-identical", "[heidenhain]") {
    for (const char* name : {"tnc426.t", "tnc426_inch.t"}) {
        INFO(name);
        const std::string text = fixture(name);
        CHECK(write_t(heidenhain(text)) == text);
        if (text.find("\r\n") == std::string::npos) {
            const std::string crlf = to_crlf(text);
            CHECK(write_t(heidenhain(crlf)) == crlf);
        }
        // No final line ending.
        const std::string bare = text.substr(0, text.find_last_not_of("\r\n") + 1);
        CHECK(write_t(heidenhain(bare)) == bare);
    }
    // A byte order mark, blank lines, blank lines after [END], short rows, tabs in a value.
    const std::string odd =
        "\xEF\xBB\xBF"
        "begin tool .t mm\r\n"
        "T    NAME        L         R       DOC\r\n"
        "\r\n"
        "1    A\r\n"
        "   \r\n"
        "2                +5\t       +1\r\n"
        "[end]\r\n"
        "\r\n";
    const ToolTable t = heidenhain(odd);
    CHECK(t.at(1).name == "A");
    CHECK(t.at(1).edge().length.z() == 0);
    CHECK(t.at(2).edge().length.z() == 5);
    CHECK(t.at(2).edge().radius == 1);
    CHECK(write_t(t) == odd);
}

TEST_CASE("heidenhain: a changed tool rewrites only its own row, in the same layout", "[heidenhain]") {
    const std::string text = fixture("tnc426.t");
    ToolTable table = heidenhain(text);
    const auto before = lines_of(text);

    Tool t3 = table.at(3);
    t3.edge().radius = 7.5;
    t3.edge().radius_wear = 0;
    t3.edge().length_wear.z() = -0.02;
    t3.comment = "NACHGESCHLIFFEN";
    table.set(t3);
    std::string out = write_t(table);
    auto after = lines_of(out);
    REQUIRE(after.size() == before.size());
    for (std::size_t i = 0; i < before.size(); ++i)
        if (i != 5) CHECK(after[i] == before[i]);
    std::string expect = before[5];
    expect.replace(34, 4, "+7.5");
    expect.replace(58, 16, "-0.02   +0      ");
    expect.replace(126, 15, "NACHGESCHLIFFEN");
    CHECK(after[5] == expect);
    CHECK(after[5].size() == before[5].size());
    const ToolTable back = heidenhain(out);
    CHECK(back.at(3) == t3);

    // The UTF-8 row: fields placed by characters.
    Tool t12 = table.at(12);
    t12.edge().radius = 9.995;
    table.set(t12);
    after = lines_of(write_t(table));
    CHECK(after[8].substr(0, 50) == "12   FR\xC3\x84SER_D20       +150        +9.995      +0 ");
    CHECK(heidenhain(write_t(table)).at(12) == t12);

    // An empty field that gets a value is filled from its start; others stay empty.
    Tool t7 = table.at(7);
    t7.edge().radius = 2;
    table.set(t7);
    after = lines_of(write_t(table));
    CHECK(after[7].substr(0, 50) == "7    FASE_90" + std::string(22, ' ') + "+2" + std::string(14, ' '));
    CHECK(after[7].size() == before[7].size());
    CHECK(heidenhain(write_t(table)).at(7) == t7);

    // A pocket number is not a TOOL.T column: the row stays as it was.
    ToolTable again = heidenhain(text);
    again.find(1)->pocket = 4;
    CHECK(write_t(again) == text);
}

TEST_CASE("heidenhain: right-aligned values stay right-aligned, numbers in TNC spelling", "[heidenhain]") {
    ToolTable table = heidenhain(kSmall);
    CHECK(write_t(table) == kSmall);
    Tool t = table.at(1);
    t.edge().length.z() = 100.25;  // L was right-aligned: keeps its end
    t.edge().radius = 0.05;        // R was left-aligned: keeps its start
    table.set(t);
    auto lines = lines_of(write_t(table));
    CHECK(lines[2] == "1    MILL_A        +100.25 +0.05   first");
    t.edge().length.z() = 0;
    t.edge().radius = -0.02;
    table.set(t);
    lines = lines_of(write_t(table));
    CHECK(lines[2] == "1    MILL_A             +0 -0.02   first");
    t.edge().length.z() = 5;
    t.edge().radius = 1.0 / 3.0;  // exact spelling does not fit R's 7 characters
    table.set(t);
    const Raised r = write_error(table);
    CHECK(r.code == "heidenhain_value_too_wide");
    CHECK_THAT(r.message, Contains("T1") && Contains("R"));

    // The last column has no limit.
    t.edge().radius = 4;
    t.comment = "a much longer comment than before";
    table.set(t);
    lines = lines_of(write_t(table));
    CHECK(lines[2] == "1    MILL_A             +5 +4      a much longer comment than before");
    CHECK(heidenhain(write_t(table)).at(1) == t);

    // A name that does not fit NAME's field.
    t.name = "NAME_OF_THIRTEEN";
    table.set(t);
    CHECK(write_error(table).code == "heidenhain_value_too_wide");
}

TEST_CASE("heidenhain: removing deletes the row, a new tool goes before [END]", "[heidenhain]") {
    const std::string text = fixture("tnc426.t");
    ToolTable table = heidenhain(text);
    const auto before = lines_of(text);
    CHECK(table.remove(5));
    Tool t;
    t.number = 20;
    t.pocket = 20;  // dropped: TOOL.T has no pocket
    t.name = "GEWINDEFRAESER";
    t.comment = "M8";
    t.edge().length.z() = 64.2;
    t.edge().radius = 2.95;
    t.edge().radius_wear = -0.01;
    table.set(t);
    const std::string out = write_t(table);
    const auto after = lines_of(out);
    REQUIRE(after.size() == before.size());
    for (std::size_t i = 0; i < 6; ++i) CHECK(after[i] == before[i]);
    CHECK(after[6] == before[7]);
    CHECK(after[7] == before[8]);
    std::string row = "20   GEWINDEFRAESER   +64.2       +2.95       +0          +0      -0.01   +0";
    row += std::string(126 - row.size(), ' ') + "M8";  // DOC starts at column 127
    REQUIRE(after[8].size() >= row.size());
    CHECK(after[8].substr(0, row.size()) == row);
    CHECK(after[8].find_first_not_of(' ', row.size()) == std::string::npos);
    CHECK(after[8].size() == before[1].size());  // padded like the header line
    CHECK(after[9] == "[END]");
    const ToolTable back = heidenhain(out);
    Tool expect = t;
    expect.pocket = 0;
    CHECK(back.at(20) == expect);
    CHECK_FALSE(back.contains(5));

    // CRLF files give new rows CRLF.
    ToolTable crlf = heidenhain(to_crlf(kSmall));
    Tool small;
    small.number = 9;
    small.name = "NEU";
    small.comment = "x";
    small.edge().length.z() = 1;
    small.edge().radius = 2;
    crlf.set(small);
    CHECK_THAT(write_t(crlf), EndsWith("second\r\n9    NEU         +1        +2      x\r\n[END]\r\n"));
}

TEST_CASE("heidenhain: INCH tables convert lengths, the BEGIN line gives the unit", "[heidenhain]") {
    const std::string text = fixture("tnc426_inch.t");
    // The caller's unit is overridden by the file's own.
    ToolTable table = heidenhain(text, LengthUnit::mm);
    CHECK(table.units() == LengthUnit::inch);
    CHECK(table.at(1).name == "ENDMILL_1/2");
    CHECK(table.at(1).edge().length.z() == Approx(95.25));
    CHECK(table.at(1).edge().radius == Approx(6.35));
    CHECK(table.at(1).edge().radius_wear == Approx(-0.0127));
    CHECK(table.at(2).edge().corner_radius == table.at(2).edge().radius);
    CHECK(table.at(3).edge().corner_radius == Approx(1.5875));
    CHECK(table.at(3).edge().length_wear.z() == Approx(0.0508));
    CHECK(table.at(3).edge().corner_radius_wear == Approx(-0.0254));
    CHECK(write_t(table) == text);

    // A changed value is written in inch.
    table.find(2)->edge().radius_wear = -0.001 * 25.4;
    const auto after = lines_of(write_t(table));
    CHECK(after[3] == "2    BALL_1/4         +2.5        +0.125      +0.125      +0       -0.001   +0                               %00000000");

    // Changing the unit writes the canonical layout in the new unit.
    table.set_units(LengthUnit::mm);
    const std::string mm = write_t(table);
    CHECK(lines_of(mm)[0] == "BEGIN TOOL .T MM");
    const ToolTable back = heidenhain(mm);
    CHECK(back.units() == LengthUnit::mm);
    for (const Tool& t : table.tools()) CHECK(back.at(t.number) == t);

    // A BEGIN line without a unit takes the caller's.
    const ToolTable no_unit = heidenhain("BEGIN TOOL.T\nT R\n1 +0.5\n[END]\n", LengthUnit::inch);
    CHECK(no_unit.units() == LengthUnit::inch);
    CHECK(no_unit.at(1).edge().radius == Approx(12.7));
}

TEST_CASE("heidenhain: conversion to CSV and back keeps the mapped data", "[heidenhain]") {
    const ToolTable table = heidenhain(fixture("tnc426.t"));
    const std::string csv = write_tool_table(table, TableFormat::csv);
    const ToolTable from_csv = read_tool_table(csv, TableFormat::csv);
    REQUIRE(from_csv.size() == table.size());
    for (std::size_t i = 0; i < table.size(); ++i) CHECK(from_csv.tools()[i] == table.tools()[i]);

    // Back to TOOL.T: the canonical layout (the unmapped columns are lost).
    const std::string t = write_t(from_csv);
    const auto lines = lines_of(t);
    CHECK(lines[0] == "BEGIN TOOL .T MM");
    CHECK(lines[1].rfind("T    NAME             L           R           R2          DL      DR      DR2     LCUTS   "
                         "ANGLE   TL RT  TIME1 TIME2 CUR.TIME DOC              PLC",
                         0) == 0);
    CHECK(lines[3].rfind("1    SCHAFTFRAESER_10 +95.25      +5          +0          +0      -0.02   +0      ", 0) == 0);
    CHECK(lines.back() == "[END]");
    CHECK_THAT(t, Contains("\r\n"));
    const ToolTable back = heidenhain(t);
    REQUIRE(back.size() == table.size());
    for (std::size_t i = 0; i < table.size(); ++i) CHECK(back.tools()[i] == table.tools()[i]);
    CHECK(write_t(back) == t);  // the canonical file is itself lossless
    CHECK_THAT(t, !Contains("COOLANT") && !Contains("%00000001"));

    // JSON too.
    const ToolTable from_json = read_tool_table(write_tool_table(table, TableFormat::json), TableFormat::json);
    for (std::size_t i = 0; i < table.size(); ++i) CHECK(from_json.tools()[i] == table.tools()[i]);
}

TEST_CASE("heidenhain: a table from .tbl or code; what TOOL.T cannot hold is refused", "[heidenhain]") {
    ToolTable tbl = read_tool_table("T1 P3 Z+50.5 D+10 ;end mill\nT2 P4 Z40 D6.35\n", TableFormat::linuxcnc);
    const std::string t = write_t(tbl);
    const ToolTable back = heidenhain(t);
    CHECK(back.at(1).edge().length.z() == 50.5);
    CHECK(back.at(1).edge().radius == 5);
    CHECK(back.at(1).comment == "end mill");
    CHECK(back.at(1).pocket == 0);  // dropped
    CHECK(back.at(2).edge().radius == 3.175);
    CHECK_THAT(t, Contains("+3.175"));

    // Wide values widen the canonical columns.
    ToolTable code;
    Tool w;
    w.number = 123456;
    w.name = "A_VERY_LONG_TOOL_NAME_FOR_A_TNC";
    w.edge().radius = 1.0 / 3.0;
    code.set(w);
    const ToolTable wb = heidenhain(write_t(code));
    CHECK(wb.at(123456) == w);

    // mill.tbl tool 4 has X, A B C, U V W, angles and an orientation.
    const ToolTable mill = read_tool_table(fixture("mill.tbl"), TableFormat::linuxcnc);
    Raised r = write_error(mill);
    CHECK(r.code == "heidenhain_unrepresentable");
    CHECK_THAT(r.message, Contains("T3"));  // T3 has X0.5 Y-0.25

    auto refused = [](const Tool& tool) {
        ToolTable tt;
        tt.set(tool);
        return write_error(tt).code;
    };
    Tool base;
    base.number = 1;
    Tool x = base;
    x.edge().length_wear.x() = 0.1;
    CHECK(refused(x) == "heidenhain_unrepresentable");
    Tool two = base;
    CuttingEdge d2;
    d2.number = 2;
    two.set_edge(d2);
    CHECK(refused(two) == "heidenhain_unrepresentable");
    Tool q = base;
    q.edge().orientation = 3;
    CHECK(refused(q) == "heidenhain_unrepresentable");
    Tool nl = base;
    nl.comment = "two\nlines";
    CHECK(refused(nl) == "heidenhain_unrepresentable");

    // A mapped column the file does not have.
    ToolTable no_r2 = heidenhain(kSmall);
    Tool ball = no_r2.at(2);
    ball.edge().corner_radius = 2.5;
    no_r2.set(ball);
    r = write_error(no_r2);
    CHECK(r.code == "heidenhain_unrepresentable");
    CHECK_THAT(r.message, Contains("R2"));
    ball.edge().corner_radius = 0;
    ball.edge().radius_wear = 0.01;  // DR missing too
    no_r2.set(ball);
    CHECK(write_error(no_r2).code == "heidenhain_unrepresentable");
}

TEST_CASE("heidenhain: errors carry code, line and column", "[heidenhain]") {
    const std::string head = "BEGIN TOOL .T MM\nT    NAME        L         R       DOC\n";
    struct Case {
        std::string text, code;
        int line, column;
    };
    const std::vector<Case> cases = {
        {"", "heidenhain_missing_begin", 1, 1},
        {"T NAME\n[END]\n", "heidenhain_missing_begin", 1, 1},
        {"  BEGIN PGM 1 MM\n", "heidenhain_not_tool_table", 1, 9},
        {"BEGIN TOOL_P .TCH MM\nP T\n[END]\n", "heidenhain_not_tool_table", 1, 7},
        {"BEGIN TOOL .T MM\n", "heidenhain_missing_header", 2, 1},
        {"BEGIN TOOL .T MM\n1    MILL  +5\n[END]\n", "heidenhain_missing_header", 2, 1},
        {"BEGIN TOOL .T MM\n[END]\n", "heidenhain_missing_header", 2, 1},
        {"BEGIN TOOL .T MM\nT    NAME  L   R  l\n[END]\n", "heidenhain_duplicate_column", 2, 19},
        {head + "1    A           +5x\n[END]\n", "heidenhain_bad_number", 3, 18},
        {head + "1    A           +5        1,5\n[END]\n", "heidenhain_bad_number", 3, 28},
        {head + "1    A\n2    B                     +-1\n[END]\n", "heidenhain_bad_number", 4, 28},
        {head + "x1   A\n[END]\n", "heidenhain_bad_number", 3, 1},
        {head + "  -1 A\n[END]\n", "heidenhain_bad_number", 3, 3},
        {head + "5.2  A         +5\n[END]\n", "heidenhain_tool_index_unsupported", 3, 1},
        {head + "     A         +5\n[END]\n", "heidenhain_missing_tool", 3, 6},
        {head + "1    A\n2    B\n 1   C\n[END]\n", "heidenhain_duplicate_tool", 5, 2},
        {head + "1    A\n2    B\n", "heidenhain_missing_end", 5, 1},
        {head + "1    A\n2    B", "heidenhain_missing_end", 5, 1},
        {head + "1    A\n[END]\n\n  3  C\n", "heidenhain_text_after_end", 6, 3},
    };
    for (const Case& c : cases) {
        INFO(c.text);
        const Raised r = read_error(c.text);
        CHECK(r.code == c.code);
        CHECK(r.line == c.line);
        CHECK(r.column == c.column);
        CHECK_FALSE(r.message.empty());
    }
    // Columns are characters: a two-byte name still points at the right column.
    const Raised u = read_error(head + "1    \xC3\x84X          +5x\n[END]\n");
    CHECK(u.code == "heidenhain_bad_number");
    CHECK(u.column == 18);
}

TEST_CASE("heidenhain: format names and suffixes", "[heidenhain]") {
    CHECK(table_format_from_string("heidenhain") == TableFormat::heidenhain);
    CHECK(table_format_from_string("T") == TableFormat::heidenhain);
    CHECK(table_format_from_path("TNC/TOOL.T") == TableFormat::heidenhain);
    CHECK(table_format_from_path("x.y/tool.t") == TableFormat::heidenhain);
    CHECK(to_string(TableFormat::heidenhain) == "heidenhain");
    CHECK_THROWS_AS(table_format_from_path("tool.tch"), ToolTableError);
}

TEST_CASE("heidenhain: files by suffix", "[heidenhain]") {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / ("toolcomp_heidenhain_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string path = (dir / "TOOL.T").string();
    std::ofstream(path, std::ios::binary) << fixture("tnc426.t");
    ToolTable table = read_tool_table_file(path);
    CHECK(table.size() == 7);
    table.find(2)->edge().corner_radius_wear = 0;
    write_tool_table_file(table, path);
    CHECK(read_tool_table_file(path).at(2).edge().corner_radius_wear == 0);
    fs::remove_all(dir);
}
