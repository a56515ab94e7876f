// A program file read piece by piece (program/file_pieces.hpp): whole lines, the first
// pieces small and growing to the piece size (each up to the last line end within its size), the file's text unchanged.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "program/file_pieces.hpp"
#include "toolcomp/program/text.hpp"

using namespace toolcomp;
namespace fs = std::filesystem;

namespace {
std::vector<std::string> pieces_of(FilePieces& f) {
    std::vector<std::string> out;
    for (std::string_view t = f.next(); !t.empty(); t = f.next()) out.emplace_back(t);
    return out;
}
}  // namespace

TEST_CASE("FilePieces: 64 kB first, then twice the one before up to the piece size, whole lines") {
    const fs::path path = fs::temp_directory_path() / "toolcomp_test_file_pieces.ngc";
    std::string text;
    for (int i = 0; text.size() < 1'500'000; ++i) text += "G1 X" + std::to_string(i % 977) + " Y" + std::to_string(i) + "\n";
    text += "M2";  // no newline at the end
    std::ofstream(path, std::ios::binary) << text;
    FilePieces f(path.string(), 256 * 1024, 1 << 20, false);
    for (int pass = 0; pass < 2; ++pass) {  // the second after rewind()
        const std::vector<std::string> p = pieces_of(f);
        REQUIRE(p.size() >= 6);
        const std::size_t wants[] = {64 * 1024, 128 * 1024, 256 * 1024, 256 * 1024};
        for (std::size_t k = 0; k < 4; ++k) {
            CHECK(p[k].size() <= wants[k]);
            CHECK(p[k].size() > wants[k] - 64);  // to the end of the last line within the size
            CHECK(p[k].back() == '\n');
        }
        std::string joined;
        for (const auto& s : p) joined += s;
        CHECK(joined == text);
        f.rewind();
    }
    fs::remove(path);
}

TEST_CASE("line_ends counts what std::count counts, across its 4 kB runs") {
    std::string text;
    for (std::size_t n : {0u, 1u, 4095u, 4096u, 4097u, 20000u}) {
        text.assign(n, 'x');
        for (std::size_t i = 0; i < n; i += 1 + i % 97) text[i] = '\n';
        CHECK(line_ends(text) == static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')));
    }
    CHECK(line_ends("G1\nG2\n\nM2") == 3);
}
