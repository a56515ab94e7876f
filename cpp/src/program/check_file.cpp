// A program file read through as a syntax check, without keeping it: the command line's
// `check` of programs whose blocks (and Paths) would not fit in memory.
#include <unistd.h>

#include "../dialects/table.hpp"
#include "file_pieces.hpp"
#include "toolcomp/program/input_limits.hpp"
#include "toolcomp/run.hpp"

namespace toolcomp {

std::size_t check_program_file(const std::string& path, std::optional<Dialect> dialect, const ReadLimits& limits) {
    const Dialect d = dialect_of_file(path, dialect);
    const DialectRow& row = dialect_row(d);
    if (!row.read_in_pieces()) return read_program(path, d, /*strict=*/true, limits).size();  // read whole by a run too
    ::close(open_program_file(path));  // a missing file, a FIFO or a directory: as read_program says
    FilePieces pieces(path, kPieceBytes, limits.max_line_length, cr_ends_line(d));
    const std::unique_ptr<PieceReader> parser = row.pieces(d, path, /*strict=*/true, kPieceBytes);
    std::size_t blocks = 0;
    Program piece;  // each piece parsed over the one before (its memory written already)
    for (std::string_view t = pieces.next(); !t.empty() && !parser->done(); t = pieces.next()) {
        piece = parser->parse(t, std::move(piece));
        blocks += piece.size();
    }
    if (!parser->done())
        if (std::optional<Program> last = parser->end(std::move(piece))) blocks += last->size();
    return blocks;
}

}  // namespace toolcomp
