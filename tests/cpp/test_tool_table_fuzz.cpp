// Randomised checks of the tool-table formats: random tables survive every format, and
// mangled files either fail with a ToolTableError or read, change and write back cleanly.
#include <catch2/catch.hpp>

#include "toolcomp/program/diagnostic.hpp"
#include "toolcomp/tools/tool_table.hpp"

#include <fstream>
#include <random>
#include <sstream>

#ifndef TOOLCOMP_TEST_DATA
#define TOOLCOMP_TEST_DATA "tests/programs"
#endif

using namespace toolcomp;

namespace {

std::string fixture(const std::string& name) {
    std::ifstream in(std::string(TOOLCOMP_TEST_DATA) + "/tables/" + name, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// Comments in .tbl are trimmed on read, so random comments are generated trimmed.
std::string trimmed(const std::string& s) {
    const auto b = s.find_first_not_of(' ');
    if (b == std::string::npos) return "";
    return s.substr(b, s.find_last_not_of(' ') - b + 1);
}

double random_value(std::mt19937& rng) {
    std::uniform_int_distribution<int> kind(0, 4);
    switch (kind(rng)) {
        case 0: return 0;
        case 1: return std::uniform_int_distribution<int>(-500, 500)(rng) / 10.0;
        case 2: return std::uniform_real_distribution<double>(-1000, 1000)(rng);
        case 3: return std::uniform_int_distribution<int>(1, 99999)(rng) * 1e-7;
        default: return std::uniform_int_distribution<int>(-30, 30)(rng) * 0.125;
    }
}

Tool random_tool(std::mt19937& rng, int number, bool single_edge_only) {
    Tool t;
    t.number = number;
    t.pocket = std::uniform_int_distribution<int>(0, 200)(rng);
    static const char* comments[] = {"", "end mill", "a, b; \"c\"", "  spaced  ", "semi;colon", "\xC3\xA9t\xC3\xA9"};
    t.comment = trimmed(comments[std::uniform_int_distribution<int>(0, 5)(rng)]);
    CuttingEdge& e = t.edges.front();
    e.length = {random_value(rng), random_value(rng), random_value(rng)};
    e.rotary = {random_value(rng), random_value(rng), random_value(rng)};
    e.uvw = {random_value(rng), random_value(rng), random_value(rng)};
    e.radius = std::abs(random_value(rng));
    e.front_angle = random_value(rng);
    e.back_angle = random_value(rng);
    e.orientation = std::uniform_int_distribution<int>(0, 9)(rng);
    if (!single_edge_only) {
        t.name = std::uniform_int_distribution<int>(0, 1)(rng) ? "T" + std::to_string(number) : "";
        e.corner_radius = std::abs(random_value(rng));
        e.length_wear.z() = random_value(rng) / 100;
        e.radius_wear = random_value(rng) / 100;
        const int more = std::uniform_int_distribution<int>(0, 2)(rng);
        const CuttingEdge first = e;  // `e` dangles once edges grows
        for (int d = 2; d < 2 + more; ++d) {
            CuttingEdge x = first;
            x.number = d;
            x.radius = std::abs(random_value(rng));
            t.edges.push_back(x);
        }
    }
    return t;
}

}  // namespace

TEST_CASE("random tables survive every format exactly (mm)", "[tools][fuzz]") {
    std::mt19937 rng(12345);
    for (int round = 0; round < 40; ++round) {
        const bool tbl_ok = round % 2 == 0;
        ToolTable table;
        const int n = std::uniform_int_distribution<int>(0, 12)(rng);
        for (int i = 0; i < n; ++i) table.set(random_tool(rng, std::uniform_int_distribution<int>(0, 300)(rng), tbl_ok));
        std::vector<TableFormat> formats{TableFormat::csv, TableFormat::json};
        if (tbl_ok) formats.push_back(TableFormat::linuxcnc);
        for (TableFormat f : formats) {
            INFO("round " << round << " format " << to_string(f));
            const std::string text = write_tool_table(table, f);
            const ToolTable back = read_tool_table(text, f);
            REQUIRE(back.size() == table.size());
            for (std::size_t i = 0; i < table.size(); ++i) CHECK(back.tools()[i] == table.tools()[i]);
            CHECK(write_tool_table(back, f) == text);
        }
    }
}

TEST_CASE("random tables survive every format in inch within rounding", "[tools][fuzz]") {
    std::mt19937 rng(777);
    for (int round = 0; round < 20; ++round) {
        ToolTable table(LengthUnit::inch);
        for (int i = 0; i < 6; ++i) table.set(random_tool(rng, i + 1, true));
        for (TableFormat f : {TableFormat::linuxcnc, TableFormat::csv, TableFormat::json}) {
            const ToolTable back = read_tool_table(write_tool_table(table, f), f, LengthUnit::inch);
            REQUIRE(back.size() == table.size());
            for (std::size_t i = 0; i < table.size(); ++i) {
                const CuttingEdge& a = table.tools()[i].edge();
                const CuttingEdge& b = back.tools()[i].edge();
                CHECK(b.length.x() == Approx(a.length.x()).margin(1e-12));
                CHECK(b.length.z() == Approx(a.length.z()).margin(1e-12));
                CHECK(b.uvw[1] == Approx(a.uvw[1]).margin(1e-12));
                CHECK(b.radius == Approx(a.radius).margin(1e-12));
                CHECK(b.front_angle == a.front_angle);
                CHECK(b.orientation == a.orientation);
            }
        }
    }
}

TEST_CASE("mangled files fail cleanly or read, change and write back", "[tools][fuzz]") {
    const std::pair<const char*, TableFormat> inputs[] = {
        {"lathe.tbl", TableFormat::linuxcnc}, {"mill.tbl", TableFormat::linuxcnc},
        {"tools.csv", TableFormat::csv},      {"tools_edges.csv", TableFormat::csv},
        {"tools.json", TableFormat::json}};
    const std::string alphabet = "TPDXQ;,\"{}[]:0123456789.-+e \n\r\tabz#\\";
    std::mt19937 rng(4242);
    int parsed = 0;
    for (const auto& [name, format] : inputs) {
        const std::string original = fixture(name);
        REQUIRE(!original.empty());
        for (int round = 0; round < 300; ++round) {
            std::string text = original;
            const int edits = std::uniform_int_distribution<int>(1, 4)(rng);
            for (int k = 0; k < edits && !text.empty(); ++k) {
                const std::size_t at = std::uniform_int_distribution<std::size_t>(0, text.size() - 1)(rng);
                const char c = alphabet[std::uniform_int_distribution<std::size_t>(0, alphabet.size() - 1)(rng)];
                switch (std::uniform_int_distribution<int>(0, 2)(rng)) {
                    case 0: text[at] = c; break;
                    case 1: text.insert(text.begin() + static_cast<std::ptrdiff_t>(at), c); break;
                    default: text.erase(at, 1); break;
                }
            }
            INFO(name << " round " << round << "\n" << text);
            ToolTable table;
            try {
                table = read_tool_table(text, format);
            } catch (const ToolTableError& e) {
                CHECK(e.line() >= 1);
                CHECK(!e.code().empty());
                continue;
            }
            ++parsed;
            CHECK(write_tool_table(table, format) == text);
            // Change every tool and drop the first; the result must read back as the model.
            std::vector<Tool> changed;
            for (Tool t : table.tools()) {
                t.pocket += 1;
                t.edges.front().front_angle += 1;
                changed.push_back(t);
            }
            for (const Tool& t : changed) table.set(t);
            if (!changed.empty()) {
                table.remove(changed.front().number);
                changed.erase(changed.begin());
            }
            const std::string out = write_tool_table(table, format);
            const ToolTable back = read_tool_table(out, format);
            REQUIRE(back.size() == changed.size());
            for (std::size_t i = 0; i < changed.size(); ++i) CHECK(back.tools()[i] == changed[i]);
        }
    }
    CHECK(parsed > 100);
}
