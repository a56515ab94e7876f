// The Motion stream carries what the compensation stages need: tool, length offset vector
// and the cutter radius compensation request (side, radius from the tool table's D / 2 or
// from G41.1's D, the lathe orientation).
#include <catch2/catch.hpp>
#include <vector>

#include "toolcomp/control/profile.hpp"
#include "toolcomp/dialects/iso/interpreter.hpp"
#include "toolcomp/dialects/iso/lexer.hpp"
#include "toolcomp/tools/tool_table.hpp"

using namespace toolcomp;

namespace {
struct Collect : MotionSink {
    std::vector<Motion> moves;
    void push(const Motion& m) override { moves.push_back(m); }
};

std::vector<Motion> stream(const std::string& text, const ToolTable* tools) {
    Program p = iso::parse(text, Dialect::linuxcnc);
    Collect c;
    std::vector<Diagnostic> diags;
    iso::interpret(p, tools, profile_for(Dialect::linuxcnc), {}, c, diags);
    return c.moves;
}
}  // namespace

TEST_CASE("radius compensation requests ride on the moves") {
    ToolTable tools = read_tool_table("T1 P1 Z25 D10\nT2 P2 D-6\nT3 P3 D0.8 Q3\n", TableFormat::linuxcnc);
    auto m = stream(
        "G21 G17 T1 M6 G43\nG0 X0 Y0\nG41 G1 X10 F100\nG40 G1 X20\nG42 D2 G1 X30\nG40 G0 X0\n"
        "G18 G41.1 D2 L6 G1 X1\nG40 G0 X0\nG42 D3 G1 X5\nM2\n",
        &tools);
    REQUIRE(m.size() == 8);
    CHECK(m[0].radius.side == 0);
    CHECK(m[1].radius.side == 1);
    CHECK(m[1].radius.radius == 5.0);  // D10 is a diameter
    CHECK(m[1].tool == 1);
    CHECK(m[1].tool_offset.z() == 25.0);
    CHECK(m[2].radius.side == 0);
    CHECK(m[3].radius.side == 1);  // G42 with a negative diameter cuts on the left
    CHECK(m[3].radius.radius == 3.0);
    CHECK(m[5].radius.side == 1);
    CHECK(m[5].radius.radius == 1.0);
    CHECK(m[5].radius.orientation == 6);
    CHECK(m[7].radius.side == -1);
    CHECK(m[7].radius.radius == Approx(0.4));
    CHECK(m[7].radius.orientation == 3);
}

TEST_CASE("LinuxCNC's refusals around radius compensation") {
    ToolTable tools = read_tool_table("T1 P1 D10\nT3 P3 D0.8 Q3\n", TableFormat::linuxcnc);
    CHECK_THROWS_WITH(stream("G21 G41 D1\nG41 D1\nM2\n", &tools), "Cannot turn cutter radius comp on when on");
    CHECK_THROWS_WITH(stream("G21 G41.1\nM2\n", &tools), "G41.1 with no D word");
    CHECK_THROWS_WITH(stream("G21 G17 G41.1 D1 L3\nM2\n", &tools), "G41.1 with L word, but plane is not G18");
    CHECK_THROWS_WITH(stream("G21 G17 G42 D3\nM2\n", &tools), "G42 with lathe tool, but plane is not G18");
    CHECK_THROWS_WITH(stream("G21 G41 D1.5\nM2\n", &tools), "G41 requires D word to be a whole number");
    CHECK_THROWS_WITH(stream("G21 G41 D1\nG18\nM2\n", &tools), "Cannot change planes with cutter radius compensation on");
    CHECK_THROWS_WITH(stream("G21 G41 D1\nG43 H1\nM2\n", &tools),
                      "Cannot change tool offset with cutter radius compensation on");
    CHECK_THROWS_WITH(stream("G21 G41 D1\nG81 X1 R1 Z0 F10\nM2\n", &tools),
                      "Cannot use canned cycles with cutter compensation on");
    CHECK_THROWS_WITH(stream("G21 G41 D1\nG55\nM2\n", &tools),
                      "Cannot change coordinate systems with cutter radius compensation on");
}
