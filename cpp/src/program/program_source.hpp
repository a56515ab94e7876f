#pragma once
// The main program of a run from a file: read and parsed whole, or, for a file in which
// nothing steers across blocks (its dialect's has_control_flow: dialects/table.hpp), piece
// by piece: then memory
// for the program stays that of two pieces (about `piece_bytes` of text each: the next one is
// read and parsed in another thread while the run works through the current one) whatever
// its length.
#include <cstdint>
#include <exception>
#include <functional>
#include <future>
#include <optional>
#include <string>

#include "../dialects/table.hpp"
#include "file_pieces.hpp"
#include "toolcomp/run.hpp"

namespace toolcomp {

class ProgramSource {
public:
    // A piece that cannot be read (a line too long, a read error) stops the run whatever
    // RunOptions::strict says, as it does when the file is read whole before the run: it is
    // thrown past the pipeline's lenient handling as this, and `error` is rethrown above it.
    struct InputError {
        std::exception_ptr error;
    };

    // A file larger than `limits.max_bytes` is refused before it is read (ParseError
    // "input_too_large") when it would be read whole, and with `limit_pieces` also when it is
    // read piece by piece. `check` is called before each piece (it may throw to stop).
    // `threads`: the next piece is read and parsed on a thread of its own while the run works
    // (else when the run asks for it, on the run's thread).
    ProgramSource(const std::string& path, Dialect dialect, const ReadLimits& limits, std::size_t piece_bytes,
                  bool limit_pieces, std::function<void()> check = {}, bool threads = true);
    ~ProgramSource();
    ProgramSource(const ProgramSource&) = delete;
    ProgramSource& operator=(const ProgramSource&) = delete;
    // The whole program, or its first piece.
    const Program& first() const { return current_; }
    // For the interpreter (iso::InterpretOptions::next_piece); empty when read whole.
    std::function<const Program*()> next_piece();
    bool in_pieces() const { return parser_ != nullptr; }
    std::size_t blocks() const { return blocks_; }  // blocks read so far
    // Blocks the whole file may hold, from the size of the file and the first piece.
    std::size_t estimated_blocks() const { return estimate_; }

private:
    void read_ahead();

    std::optional<FilePieces> pieces_;
    std::unique_ptr<PieceReader> parser_;
    Program current_;
    Program spare_;  // the piece before current_, to be parsed over by the next read-ahead
    std::size_t blocks_ = 0, estimate_ = 0;
    std::function<void()> check_;
    bool threads_ = true;
    std::future<std::optional<Program>> ahead_;  // the next piece, read and parsed meanwhile
};

}  // namespace toolcomp
