// Tool model and the LinuxCNC / CSV / JSON tool-table formats: lossless round trips,
// unit conversion, partial rewrites, errors with their position, format conversion.
#include <catch2/catch.hpp>

#include "toolcomp/program/diagnostic.hpp"
#include "toolcomp/tools/tool_table.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#ifndef TOOLCOMP_TEST_DATA
#define TOOLCOMP_TEST_DATA "tests/programs"
#endif

using namespace toolcomp;
using Catch::Matchers::Contains;

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

std::vector<std::string> lines_of(const std::string& s) {
    std::vector<std::string> out;
    std::stringstream ss(s);
    std::string l;
    while (std::getline(ss, l)) out.push_back(l);
    return out;
}

// The error a parse raises: code, line, column.
struct Raised {
    std::string code;
    int line = -1, column = -1;
    std::string message;
};

Raised error_of(const std::string& text, TableFormat f, LengthUnit u = LengthUnit::mm) {
    try {
        read_tool_table(text, f, u);
    } catch (const ToolTableError& e) {
        return {e.code(), e.line(), e.column(), e.what()};
    }
    FAIL("no error raised for: " << text);
    return {};
}

}  // namespace

// ---- the model ------------------------------------------------------------------------------

TEST_CASE("cutting edge effective values add the wear", "[tools]") {
    CuttingEdge e;
    e.length = {1, 2, 30};
    e.length_wear = {0, 0, -0.05};
    e.radius = 5;
    e.radius_wear = -0.02;
    CHECK(e.effective_length().z() == Approx(29.95));
    CHECK(e.effective_length().x() == 1);
    CHECK(e.effective_radius() == Approx(4.98));
}

TEST_CASE("tool edges are found by D number", "[tools]") {
    Tool t;
    t.number = 7;
    CHECK(t.edges.size() == 1);
    CuttingEdge d2;
    d2.number = 2;
    d2.radius = 3;
    t.set_edge(d2);
    CHECK(t.edge(2).radius == 3);
    CHECK(t.edge().number == 1);
    d2.radius = 4;
    t.set_edge(d2);
    CHECK(t.edges.size() == 2);
    CHECK(t.edge(2).radius == 4);
    try {
        (void)t.edge(3);
        FAIL("expected an error");
    } catch (const ToolTableError& e) {
        CHECK(e.code() == "tool_no_such_edge");
    }
}

TEST_CASE("table set/find/remove", "[tools]") {
    ToolTable table;
    Tool t;
    t.number = 3;
    t.pocket = 4;
    table.set(t);
    t.number = 1;
    table.set(t);
    REQUIRE(table.size() == 2);
    CHECK(table.find(3)->pocket == 4);
    t.number = 3;
    t.pocket = 9;
    table.set(t);  // replaces in place
    CHECK(table.size() == 2);
    CHECK(table.tools().front().pocket == 9);
    CHECK(table.remove(3));
    CHECK_FALSE(table.remove(3));
    CHECK(table.find(3) == nullptr);
    CHECK_THROWS_AS(table.at(3), ToolTableError);

    Tool bad;
    bad.number = 5;
    bad.edges.front().orientation = 10;
    CHECK_THROWS_AS(table.set(bad), ToolTableError);
    bad.edges.clear();
    CHECK_THROWS_AS(table.set(bad), ToolTableError);
}

// ---- LinuxCNC .tbl --------------------------------------------------------------------------

TEST_CASE("stock LinuxCNC lathe table: values in inch, round trip byte-identical", "[tools][tbl]") {
    const std::string text = fixture("lathe.tbl");
    const ToolTable table = read_tool_table(text, TableFormat::linuxcnc, LengthUnit::inch);
    REQUIRE(table.size() == 10);
    CHECK(table.units() == LengthUnit::inch);

    const Tool& t1 = table.at(1);
    CHECK(t1.pocket == 1);
    CHECK(t1.edge().radius == Approx(1.27));  // D0.1 inch -> radius 1.27 mm
    CHECK(t1.edge().length.z() == Approx(2.54));
    CHECK(t1.edge().front_angle == 95);
    CHECK(t1.edge().back_angle == 155);
    CHECK(t1.edge().orientation == 1);
    CHECK(t1.comment.empty());

    const Tool& t6 = table.at(6);
    CHECK(t6.edge().length.x() == Approx(12.7));
    CHECK(t6.edge().length.z() == Approx(12.7));
    CHECK(t6.edge().orientation == 6);
    CHECK(table.at(7).edge().front_angle == -30);
    CHECK(table.at(9).edge().orientation == 9);
    CHECK(table.at(10).edge().radius == 0);
    CHECK(table.at(10).comment == "demo zero diameter");

    CHECK(write_tool_table(table, TableFormat::linuxcnc) == text);
    // Read as millimetres, the same text also comes back unchanged.
    CHECK(write_tool_table(read_tool_table(text, TableFormat::linuxcnc), TableFormat::linuxcnc) == text);
}

TEST_CASE("tbl: comments, blank lines, case, spacing, signs survive a round trip", "[tools][tbl]") {
    const std::string text = fixture("mill.tbl");
    const ToolTable table = read_tool_table(text, TableFormat::linuxcnc);
    REQUIRE(table.size() == 8);
    CHECK(write_tool_table(table, TableFormat::linuxcnc) == text);

    CHECK(table.at(1).edge().radius == 5);
    CHECK(table.at(1).edge().length.z() == 25);
    CHECK(table.at(1).comment == "10 mm end mill");
    CHECK(table.at(2).pocket == 2);
    CHECK(table.at(2).edge().length.z() == 30.5);
    CHECK(table.at(2).edge().radius == 3);
    CHECK(table.at(3).edge().length.y() == -0.25);
    CHECK(table.at(3).comment == "spaced  comment");
    const CuttingEdge& e4 = table.at(4).edge();
    CHECK(e4.rotary == std::array<double, 3>{1.5, -2, 3});
    CHECK(e4.uvw == std::array<double, 3>{0.1, -0.2, 0.3});
    CHECK(e4.orientation == 2);
    CHECK(table.at(5).edge().radius == 0.25);
    CHECK(table.at(6).comment == "no offsets");
    CHECK(table.at(7).edge().length.z() == 100);
    CHECK(table.at(7).comment == "exponent;and a second semicolon");
    CHECK(table.at(8).pocket == 0);
}

TEST_CASE("tbl: CRLF and a missing final newline are kept", "[tools][tbl]") {
    const std::string crlf = to_crlf(fixture("mill.tbl"));
    ToolTable table = read_tool_table(crlf, TableFormat::linuxcnc);
    CHECK(write_tool_table(table, TableFormat::linuxcnc) == crlf);

    // A changed tool keeps the CRLF of its line; a new tool gets the file's line ending.
    table.find(2)->edge().radius = 4;
    Tool t;
    t.number = 20;
    t.pocket = 20;
    table.set(t);
    const std::string out = write_tool_table(table, TableFormat::linuxcnc);
    CHECK_THAT(out, Contains("T2 P2 Z+30.500000 D+8.000000 ;lower-case words\r\n"));
    CHECK(out.size() >= 13);
    CHECK(out.substr(out.size() - 9) == "T20 P20\r\n");

    const std::string no_nl = "T1 P1 D6\nT2 P2 D8";
    ToolTable t2 = read_tool_table(no_nl, TableFormat::linuxcnc);
    CHECK(write_tool_table(t2, TableFormat::linuxcnc) == no_nl);
    t2.set(t);
    CHECK(write_tool_table(t2, TableFormat::linuxcnc) == "T1 P1 D6\nT2 P2 D8\nT20 P20\n");
}

TEST_CASE("tbl: a changed tool rewrites only its own line, in its word order", "[tools][tbl]") {
    const std::string text = fixture("lathe.tbl");
    ToolTable table = read_tool_table(text, TableFormat::linuxcnc, LengthUnit::inch);

    Tool t6 = table.at(6);
    t6.edge().length.z() = 0.6 * 25.4;
    table.set(t6);
    const auto before = lines_of(text);
    auto after = lines_of(write_tool_table(table, TableFormat::linuxcnc));
    REQUIRE(after.size() == before.size());
    for (std::size_t i = 0; i < before.size(); ++i)
        if (i != 5) CHECK(after[i] == before[i]);
    CHECK(after[5] == "T6 P6 D+0.100000 X+0.500000 Z+0.600000 I+120.000000 J+60.000000 Q6 ;");

    // A value that becomes non-zero is added after the line's own words; comments edited.
    table.find(9)->edge().length.y() = -0.25 * 25.4;
    table.find(9)->comment = "center";
    after = lines_of(write_tool_table(table, TableFormat::linuxcnc));
    CHECK(after[8] == "T9 P9 D+0.100000 Q9 Y-0.250000 ;center");

    // Removing drops the line, adding appends the canonical line.
    table.remove(3);
    Tool t;
    t.number = 12;
    t.pocket = 12;
    t.edge().radius = 0.4 * 25.4 / 2;
    t.edge().front_angle = 93;
    t.edge().orientation = 2;
    t.comment = "new insert";
    table.set(t);
    after = lines_of(write_tool_table(table, TableFormat::linuxcnc));
    REQUIRE(after.size() == before.size());
    CHECK(after[1] == before[1]);
    CHECK(after[2] == before[3]);
    CHECK(after.back() == "T12 P12 D+0.400000 I+93.000000 Q2 ;new insert");
}

TEST_CASE("tbl: numbers are written so they read back exactly", "[tools][tbl]") {
    ToolTable table(LengthUnit::mm);
    Tool t;
    t.number = 1;
    t.pocket = 1;
    t.edge().radius = 1.0 / 3.0;
    t.edge().length.z() = 123.456;
    table.set(t);
    const std::string out = write_tool_table(table, TableFormat::linuxcnc);
    CHECK_THAT(out, Contains("Z+123.456000"));
    const ToolTable back = read_tool_table(out, TableFormat::linuxcnc);
    CHECK(back.at(1).edge().radius == t.edge().radius);
    CHECK(back.at(1).edge().length.z() == 123.456);
}

TEST_CASE("tbl: inch tables convert X Y Z U V W D, not angles", "[tools][tbl]") {
    const ToolTable table =
        read_tool_table("T1 P1 D0.1 X1 Y-2 Z+3 U0.5 V1 W2 A10 B20 C30 I45 J60\n", TableFormat::linuxcnc, LengthUnit::inch);
    const CuttingEdge& e = table.at(1).edge();
    CHECK(e.radius == Approx(1.27));
    CHECK(e.length.x() == Approx(25.4));
    CHECK(e.length.y() == Approx(-50.8));
    CHECK(e.length.z() == Approx(76.2));
    CHECK(e.uvw[0] == Approx(12.7));
    CHECK(e.uvw[2] == Approx(50.8));
    CHECK(e.rotary == std::array<double, 3>{10, 20, 30});
    CHECK(e.front_angle == 45);
    CHECK(e.back_angle == 60);
}

TEST_CASE("tbl: errors carry code, line and column", "[tools][tbl]") {
    auto r = error_of("T1 P1 D6\nT2 P2 K5 ;x\n", TableFormat::linuxcnc);
    CHECK(r.code == "tbl_bad_word");
    CHECK(r.line == 2);
    CHECK(r.column == 7);

    r = error_of("; header\nT1 P1 Xabc\n", TableFormat::linuxcnc);
    CHECK(r.code == "tbl_bad_number");
    CHECK(r.line == 2);
    CHECK(r.column == 7);

    r = error_of("T1 P1\n\nT3 P3\n  T1 P9 ;again\n", TableFormat::linuxcnc);
    CHECK(r.code == "tbl_duplicate_tool");
    CHECK(r.line == 4);
    CHECK(r.column == 3);
    CHECK_THAT(r.message, Contains("line 1"));

    r = error_of("T1 P1 Q10\n", TableFormat::linuxcnc);
    CHECK(r.code == "tbl_bad_orientation");
    CHECK(r.line == 1);
    CHECK(r.column == 7);

    r = error_of("T1 P1 Q-1\n", TableFormat::linuxcnc);
    CHECK(r.code == "tbl_bad_orientation");

    r = error_of("T1\nP2 D4\n", TableFormat::linuxcnc);
    CHECK(r.code == "tbl_missing_tool");
    CHECK(r.line == 2);
    CHECK(r.column == 1);

    r = error_of("T1 P1 D4 d5\n", TableFormat::linuxcnc);
    CHECK(r.code == "tbl_duplicate_word");
    CHECK(r.column == 10);

    r = error_of("T1.5 P1\n", TableFormat::linuxcnc);
    CHECK(r.code == "tbl_bad_number");
    CHECK(r.column == 1);

    r = error_of("T1 P\n", TableFormat::linuxcnc);
    CHECK(r.code == "tbl_bad_number");
    CHECK(r.column == 4);

    r = error_of("T1 P1 Dnan\n", TableFormat::linuxcnc);
    CHECK(r.code == "tbl_bad_number");

    r = error_of("T-1 P1\n", TableFormat::linuxcnc);
    CHECK(r.code == "tbl_bad_number");
}

TEST_CASE("tbl: data it cannot hold is refused, never dropped", "[tools][tbl]") {
    ToolTable table;
    Tool t;
    t.number = 1;
    t.edge().corner_radius = 0.5;
    table.set(t);
    try {
        write_tool_table(table, TableFormat::linuxcnc);
        FAIL("expected an error");
    } catch (const ToolTableError& e) {
        CHECK(e.code() == "tbl_unrepresentable");
    }
    t.edge().corner_radius = 0;
    CuttingEdge d2;
    d2.number = 2;
    t.set_edge(d2);
    table.set(t);
    CHECK_THROWS_AS(write_tool_table(table, TableFormat::linuxcnc), ToolTableError);
}

// ---- CSV ----------------------------------------------------------------------------------

TEST_CASE("csv: round trip byte-identical, values, unknown columns", "[tools][csv]") {
    const std::string text = fixture("tools.csv");
    ToolTable table = read_tool_table(text, TableFormat::csv);
    REQUIRE(table.size() == 4);
    CHECK(write_tool_table(table, TableFormat::csv) == text);
    CHECK(write_tool_table(read_tool_table(to_crlf(text), TableFormat::csv), TableFormat::csv) == to_crlf(text));

    CHECK(table.at(1).name == "EM10");
    CHECK(table.at(1).comment == "10 mm end mill, 3 flutes");
    CHECK(table.at(1).edge().radius == 5);
    CHECK(table.at(2).edge().length.z() == 30.5);
    CHECK(table.at(2).comment.empty());
    CHECK(table.at(3).name == "Ball \"R6\"");
    CHECK(table.at(3).edge().length.y() == -0.25);
    CHECK(table.at(4).edge().radius == 0.4);
    CHECK(table.at(4).edge().orientation == 3);
    CHECK(table.at(4).edge().front_angle == 95);

    // Changing tool 3 rewrites its row only; the vendor cell stays, quoting is redone.
    table.find(3)->edge().length.z() = 41;
    const auto before = lines_of(text);
    auto after = lines_of(write_tool_table(table, TableFormat::csv));
    REQUIRE(after.size() == before.size());
    for (std::size_t i = 0; i < before.size(); ++i)
        if (i != 4) CHECK(after[i] == before[i]);
    CHECK(after[4] == "3,3,\"Ball \"\"R6\"\"\",0.5,-0.25,41,,,,,,,12,,,,ball nose,Hoffmann");

    table.remove(2);
    Tool t;
    t.number = 9;
    t.pocket = 9;
    t.name = "drill, 5";
    t.edge().radius = 2.5;
    table.set(t);
    after = lines_of(write_tool_table(table, TableFormat::csv));
    CHECK(after.size() == before.size());
    CHECK(after.back() == "9,9,\"drill, 5\",,,,,,,,,,5,,,,,");
}

TEST_CASE("csv: several edges per tool, aliases, case-insensitive header", "[tools][csv]") {
    const std::string text = fixture("tools_edges.csv");
    ToolTable table = read_tool_table(text, TableFormat::csv);
    REQUIRE(table.size() == 2);
    CHECK(write_tool_table(table, TableFormat::csv) == text);
    const Tool& t10 = table.at(10);
    REQUIRE(t10.edges.size() == 2);
    CHECK(t10.edge(1).radius == 2);
    CHECK(t10.edge(1).corner_radius == 0.5);
    CHECK(t10.edge(2).length.z() == 95.5);
    CHECK(t10.edge(2).length_wear.z() == -0.02);
    CHECK(t10.edge(2).radius_wear == 0.01);
    CHECK(t10.edge(2).effective_radius() == Approx(2.51));
    CHECK(t10.comment == "step drill");

    // A new edge goes after the tool's last row.
    Tool t = t10;
    CuttingEdge d3;
    d3.number = 3;
    d3.radius = 3;
    t.set_edge(d3);
    table.set(t);
    const auto after = lines_of(write_tool_table(table, TableFormat::csv));
    REQUIRE(after.size() == 5);
    CHECK(after[3] == "10,3,10,,3,,,,step drill");
    CHECK(after[4] == lines_of(text)[3]);
}

TEST_CASE("csv: errors carry code, line and column", "[tools][csv]") {
    auto r = error_of("tool,z,diameter\n1,25,10\n2,abc,6\n", TableFormat::csv);
    CHECK(r.code == "csv_bad_number");
    CHECK(r.line == 3);
    CHECK(r.column == 3);

    r = error_of("pocket,z\n1,2\n", TableFormat::csv);
    CHECK(r.code == "csv_missing_tool_column");
    CHECK(r.line == 1);

    r = error_of("# c\ntool,z\n1,2\n1,3\n", TableFormat::csv);
    CHECK(r.code == "csv_duplicate_tool");
    CHECK(r.line == 4);
    CHECK(r.column == 1);

    r = error_of("tool,comment\n1,\"open\n", TableFormat::csv);
    CHECK(r.code == "csv_bad_quote");
    CHECK(r.line == 2);
    CHECK(r.column == 3);

    r = error_of("tool,z\n1,2,3\n", TableFormat::csv);
    CHECK(r.code == "csv_extra_field");
    CHECK(r.column == 5);

    r = error_of("tool,orientation\n1,12\n", TableFormat::csv);
    CHECK(r.code == "csv_bad_orientation");
    CHECK(r.column == 3);

    r = error_of("tool,diameter,radius\n", TableFormat::csv);
    CHECK(r.code == "csv_duplicate_column");
    CHECK(r.column == 15);

    r = error_of("tool,edge,pocket\n1,1,1\n1,2,5\n", TableFormat::csv);
    CHECK(r.code == "csv_inconsistent_tool");
    CHECK(r.line == 3);
    CHECK(r.column == 5);

    r = error_of("tool,z\n,2\n", TableFormat::csv);
    CHECK(r.code == "csv_missing_tool");
}

TEST_CASE("csv: a quoted field may hold commas, quotes and line breaks", "[tools][csv]") {
    const std::string text = "tool,comment\r\n1,\"two\r\nlines, \"\"quoted\"\"\"\r\n2,plain\r\n";
    ToolTable table = read_tool_table(text, TableFormat::csv);
    CHECK(table.at(1).comment == "two\r\nlines, \"quoted\"");
    CHECK(write_tool_table(table, TableFormat::csv) == text);
    table.find(2)->comment = "changed";
    CHECK(write_tool_table(table, TableFormat::csv) ==
          "tool,comment\r\n1,\"two\r\nlines, \"\"quoted\"\"\"\r\n2,changed\r\n");
}

// ---- JSON ---------------------------------------------------------------------------------

TEST_CASE("json: round trip byte-identical and values", "[tools][json]") {
    const std::string text = fixture("tools.json");
    const ToolTable table = read_tool_table(text, TableFormat::json);
    REQUIRE(table.size() == 4);
    CHECK(write_tool_table(table, TableFormat::json) == text);
    CHECK(write_tool_table(read_tool_table(to_crlf(text), TableFormat::json), TableFormat::json) == to_crlf(text));

    CHECK(table.at(1).name == "EM10");
    CHECK(table.at(1).edge().radius == 5);
    CHECK(table.at(2).edge().radius == 3);
    CHECK(table.at(2).edge().length.z() == 30.5);
    const Tool& t3 = table.at(3);
    REQUIRE(t3.edges.size() == 2);
    CHECK(t3.edge(1).corner_radius == 0.5);
    CHECK(t3.edge(2).length_wear.z() == -0.02);
    CHECK(t3.comment == "step drill \xC3\xA9");
    CHECK(table.at(4).edge().orientation == 3);
}

TEST_CASE("json: a changed tool keeps its keys, layout and unknown keys", "[tools][json]") {
    const std::string text = fixture("tools.json");
    ToolTable table = read_tool_table(text, TableFormat::json);
    table.find(2)->edge().radius = 3.5;
    table.find(2)->comment = "changed";
    table.find(1)->edge().length.z() = 26;
    const std::string out = write_tool_table(table, TableFormat::json);
    CHECK_THAT(out, Contains(
        "    {\n"
        "      \"tool\": 2,\n"
        "      \"pocket\": 2,\n"
        "      \"z\": 30.5,\n"
        "      \"radius\": 3.5,\n"
        "      \"vendor\": {\"name\": \"Garant\", \"order\": 12345},\n"
        "      \"comment\": \"changed\"\n"
        "    },\n"));
    CHECK_THAT(out, Contains(
        "{\"tool\": 1, \"pocket\": 1, \"name\": \"EM10\", \"z\": 26, \"diameter\": 10, \"comment\": \"10 mm end mill\"},"));
    CHECK_THAT(out, Contains("\"source\": \"crib export 2024-05\""));
    // Unchanged tools keep their text, \u escape included.
    CHECK_THAT(out, Contains("\"comment\": \"step drill \\u00e9\"}"));
    const ToolTable back = read_tool_table(out, TableFormat::json);
    CHECK(back.at(2).edge().radius == 3.5);
    CHECK(back.at(1).edge().length.z() == 26);
}

TEST_CASE("json: removing and adding tools", "[tools][json]") {
    ToolTable table = read_tool_table(fixture("tools.json"), TableFormat::json);
    table.remove(2);
    table.remove(4);
    Tool t;
    t.number = 8;
    t.pocket = 8;
    t.edge().radius = 1;
    table.set(t);
    const std::string out = write_tool_table(table, TableFormat::json);
    const ToolTable back = read_tool_table(out, TableFormat::json);
    REQUIRE(back.size() == 3);
    CHECK(back.tools()[0].number == 1);
    CHECK(back.tools()[1].number == 3);
    CHECK(back.tools()[2].number == 8);
    CHECK_THAT(out, Contains("\n    {\"tool\": 8, \"pocket\": 8, \"diameter\": 2}\n  ]\n}\n"));

    ToolTable empty = read_tool_table("{\"tools\": []}", TableFormat::json);
    CHECK(write_tool_table(empty, TableFormat::json) == "{\"tools\": []}");
    empty.set(t);
    CHECK(read_tool_table(write_tool_table(empty, TableFormat::json), TableFormat::json).at(8) == t);
}

TEST_CASE("json: units key, inch values", "[tools][json]") {
    const std::string text = R"({"units": "inch", "tools": [{"tool": 1, "diameter": 0.1, "z": 2, "a": 45}]})";
    ToolTable table = read_tool_table(text, TableFormat::json);  // the file's unit wins
    CHECK(table.units() == LengthUnit::inch);
    CHECK(table.at(1).edge().radius == Approx(1.27));
    CHECK(table.at(1).edge().length.z() == Approx(50.8));
    CHECK(table.at(1).edge().rotary[0] == 45);
    CHECK(write_tool_table(table, TableFormat::json) == text);
    table.find(1)->edge().radius = 2.54;
    CHECK_THAT(write_tool_table(table, TableFormat::json), Contains("\"diameter\": 0.2,"));
    // Changing the unit writes the canonical document in the new unit.
    table.set_units(LengthUnit::mm);
    CHECK_THAT(write_tool_table(table, TableFormat::json), Contains("\"units\": \"mm\""));
    CHECK_THAT(write_tool_table(table, TableFormat::json), Contains("\"diameter\": 5.08"));
}

TEST_CASE("json: errors carry code, line and column", "[tools][json]") {
    auto r = error_of("{\n  \"tools\": [\n    {\"tool\": 1,}\n  ]\n}\n", TableFormat::json);
    CHECK(r.code == "json_syntax");
    CHECK(r.line == 3);
    CHECK(r.column == 16);

    r = error_of("{\"tools\": [{\"tool\": 1},\n {\"tool\": 1}]}", TableFormat::json);
    CHECK(r.code == "json_duplicate_tool");
    CHECK(r.line == 2);
    CHECK(r.column == 11);

    r = error_of("{\"units\": \"cm\", \"tools\": []}", TableFormat::json);
    CHECK(r.code == "json_bad_units");
    CHECK(r.column == 11);

    r = error_of("{\"tools\": [{\"tool\": 1, \"orientation\": 10}]}", TableFormat::json);
    CHECK(r.code == "json_bad_orientation");

    r = error_of("{\"tools\": [{\"tool\": 1.5}]}", TableFormat::json);
    CHECK(r.code == "json_bad_number");
    CHECK(r.column == 21);

    r = error_of("{\"tools\": [{\"tool\": 1, \"z\": \"5\"}]}", TableFormat::json);
    CHECK(r.code == "json_bad_value");

    r = error_of("{\"tools\": [{\"pocket\": 1}]}", TableFormat::json);
    CHECK(r.code == "json_missing_tool");

    r = error_of("{\"tools\": [{\"tool\": 1, \"z\": 1, \"edges\": [{}]}]}", TableFormat::json);
    CHECK(r.code == "json_mixed_edges");

    r = error_of("{\"tools\": [{\"tool\": 1, \"radius\": 1, \"diameter\": 2}]}", TableFormat::json);
    CHECK(r.code == "json_duplicate_key");

    r = error_of("[]", TableFormat::json);
    CHECK(r.code == "json_bad_schema");

    r = error_of("{\"tools\": [], \"tools\": []}", TableFormat::json);
    CHECK(r.code == "json_duplicate_key");
}

// ---- conversion and files -------------------------------------------------------------------

TEST_CASE("conversion between formats keeps all data", "[tools][convert]") {
    const ToolTable lathe = read_tool_table(fixture("lathe.tbl"), TableFormat::linuxcnc, LengthUnit::inch);
    const std::string csv = write_tool_table(lathe, TableFormat::csv);
    CHECK(lines_of(csv).front() ==
          "tool,edge,pocket,name,x,y,z,a,b,c,u,v,w,diameter,corner_radius,x_wear,y_wear,z_wear,"
          "diameter_wear,corner_radius_wear,front_angle,back_angle,orientation,comment");
    const ToolTable from_csv = read_tool_table(csv, TableFormat::csv, LengthUnit::inch);
    const std::string json = write_tool_table(from_csv, TableFormat::json);
    const ToolTable from_json = read_tool_table(json, TableFormat::json);
    CHECK(from_json.units() == LengthUnit::inch);
    REQUIRE(from_json.size() == lathe.size());
    for (std::size_t i = 0; i < lathe.size(); ++i) {
        CHECK(from_csv.tools()[i] == lathe.tools()[i]);
        CHECK(from_json.tools()[i] == lathe.tools()[i]);
    }
    const std::string tbl = write_tool_table(from_json, TableFormat::linuxcnc);
    CHECK(lines_of(tbl)[0] == "T1 P1 D+0.100000 Z+0.100000 I+95.000000 J+155.000000 Q1");
    CHECK(lines_of(tbl)[9] == "T10 P10 ;demo zero diameter");
    const ToolTable back = read_tool_table(tbl, TableFormat::linuxcnc, LengthUnit::inch);
    for (std::size_t i = 0; i < lathe.size(); ++i) CHECK(back.tools()[i] == lathe.tools()[i]);

    // Multi-edge JSON tools survive CSV.
    const ToolTable multi = read_tool_table(fixture("tools.json"), TableFormat::json);
    const ToolTable via_csv = read_tool_table(write_tool_table(multi, TableFormat::csv), TableFormat::csv);
    for (std::size_t i = 0; i < multi.size(); ++i) CHECK(via_csv.tools()[i] == multi.tools()[i]);
    const ToolTable mill = read_tool_table(fixture("mill.tbl"), TableFormat::linuxcnc);
    const ToolTable mill_json = read_tool_table(write_tool_table(mill, TableFormat::json), TableFormat::json);
    for (std::size_t i = 0; i < mill.size(); ++i) CHECK(mill_json.tools()[i] == mill.tools()[i]);
}

TEST_CASE("formats and units by name and suffix", "[tools]") {
    CHECK(table_format_from_path("a/b/tool.TBL") == TableFormat::linuxcnc);
    CHECK(table_format_from_path("tools.csv") == TableFormat::csv);
    CHECK(table_format_from_path("x.y/tools.json") == TableFormat::json);
    CHECK_THROWS_AS(table_format_from_path("x.tbl/tools"), ToolTableError);
    CHECK_THROWS_AS(table_format_from_path("tools.txt"), ToolTableError);
    CHECK(table_format_from_string("tbl") == TableFormat::linuxcnc);
    CHECK(table_format_from_string("LinuxCNC") == TableFormat::linuxcnc);
    CHECK(length_unit_from_string("in") == LengthUnit::inch);
    CHECK_THROWS_AS(length_unit_from_string("cm"), ToolTableError);
}

TEST_CASE("files: read, replace safely, keep the old file on errors", "[tools][file]") {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / ("toolcomp_tables_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string path = (dir / "lathe.tbl").string();
    {
        std::ofstream(path, std::ios::binary) << fixture("lathe.tbl");
    }
    fs::permissions(path, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);

    ToolTable table = read_tool_table_file(path, std::nullopt, LengthUnit::inch);
    CHECK(table.size() == 10);
    table.find(2)->edge().orientation = 3;
    write_tool_table_file(table, path, std::nullopt);
    CHECK(read_tool_table_file(path, std::nullopt, LengthUnit::inch).at(2).edge().orientation == 3);
    CHECK((fs::status(path).permissions() & fs::perms::all) ==
          (fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read));

    // A table the format cannot hold: error, old file untouched, no temporary left behind.
    const std::string before = [&] {
        std::ifstream in(path, std::ios::binary);
        std::stringstream ss;
        ss << in.rdbuf();
        return ss.str();
    }();
    table.find(2)->edge().corner_radius = 1;
    CHECK_THROWS_AS(write_tool_table_file(table, path, std::nullopt), ToolTableError);
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    CHECK(ss.str() == before);

    write_tool_table_file(table, (dir / "lathe.json").string(), std::nullopt);
    const ToolTable j = read_tool_table_file((dir / "lathe.json").string(), std::nullopt, LengthUnit::mm);
    CHECK(j.units() == LengthUnit::inch);
    CHECK(j.at(2).edge().corner_radius == 1);
    write_tool_table_file(j, (dir / "out.dat").string(), TableFormat::csv);
    CHECK(read_tool_table_file((dir / "out.dat").string(), TableFormat::csv, LengthUnit::inch).at(2) == j.at(2));

    std::size_t files = 0;
    for (const auto& e : fs::directory_iterator(dir)) {
        (void)e;
        ++files;
    }
    CHECK(files == 3);

    try {
        read_tool_table_file((dir / "missing.tbl").string());
        FAIL("expected an error");
    } catch (const ToolTableError& e) {
        CHECK(e.code() == "table_file_error");
    }
    fs::remove_all(dir);
}

TEST_CASE("csv: a value without a column adds the column at the end of the header", "[tools][csv]") {
    const std::string text = "tool,z,comment\n1,25,a\n2,30,b\n";
    ToolTable table = read_tool_table(text, TableFormat::csv);
    table.find(2)->edge().orientation = 3;
    CuttingEdge d2;
    d2.number = 2;
    d2.radius = 1;
    table.find(2)->set_edge(d2);
    CHECK(write_tool_table(table, TableFormat::csv) ==
          "tool,z,comment,edge,diameter,orientation\n1,25,a\n2,30,b,,,3\n2,,b,2,2,\n");
    const ToolTable back = read_tool_table(write_tool_table(table, TableFormat::csv), TableFormat::csv);
    CHECK(back.at(2) == table.at(2));
    CHECK(back.at(1) == table.at(1));
}

TEST_CASE("json: editing one edge keeps the other edges' text and unknown keys", "[tools][json]") {
    const std::string text =
        "{\"tools\": [\n"
        "  {\"tool\": 3, \"edges\": [\n"
        "    {\"edge\": 1, \"radius\": 2, \"insert\": \"CCMT\"},\n"
        "    {\"edge\": 2, \"radius\": 2.5, \"z\": 95.5}\n"
        "  ]}\n"
        "]}\n";
    ToolTable table = read_tool_table(text, TableFormat::json);
    table.find(3)->edge(2).length.z() = 96;
    CuttingEdge d4;
    d4.number = 4;
    d4.radius = 1;
    table.find(3)->set_edge(d4);
    CHECK(write_tool_table(table, TableFormat::json) ==
          "{\"tools\": [\n"
          "  {\"tool\": 3, \"edges\": [\n"
          "    {\"edge\": 1, \"radius\": 2, \"insert\": \"CCMT\"},\n"
          "    {\"edge\": 2, \"radius\": 2.5, \"z\": 96},\n"
          "    {\"edge\": 4, \"diameter\": 2}\n"
          "  ]}\n"
          "]}\n");
}
