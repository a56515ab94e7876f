#include "program_source.hpp"
#include "toolcomp/program/codes.hpp"

#include <unistd.h>

#include <utility>

#include "toolcomp/program/input_limits.hpp"

namespace toolcomp {

ProgramSource::ProgramSource(const std::string& path, Dialect dialect, const ReadLimits& limits,
                             std::size_t piece_bytes, bool limit_pieces, std::function<void()> check, bool threads)
    : check_(std::move(check)), threads_(threads) {
    std::uint64_t size = 0;
    ::close(open_program_file(path, "program file", &size));
    if (limit_pieces && size > limits.max_bytes)
        throw ParseError(code::input_too_large, "Cannot read program file '" + path + "': it is " + byte_count_text(size) +
                                                ", more than the limit of " + byte_count_text(limits.max_bytes) +
                                                " (max_bytes)");
    const DialectRow& row = dialect_row(dialect);
    bool whole = !row.read_in_pieces();
    if (!whole) {
        pieces_.emplace(path, piece_bytes, limits.max_line_length, cr_ends_line(dialect));
        bool start = true;
        for (std::string_view t = pieces_->next(); !t.empty() && !whole; t = pieces_->next(), start = false) {
            whole = row.has_control_flow(t, start);
            if (check_) check_();
        }
    }
    if (whole) {
        // Read leniently, as run() reads a file: a syntax error is raised when the run
        // reaches its line, and never after M2/M30.
        pieces_.reset();
        current_ = read_program(path, dialect, /*strict=*/false, limits);
        blocks_ = estimate_ = current_.size();
        return;
    }
    pieces_->rewind();
    parser_ = row.pieces(dialect, path, /*strict=*/false, piece_bytes);
    const std::string_view t = pieces_->next();
    current_ = parser_->parse(t, Program());
    if (t.empty() && !parser_->done())  // an empty file
        if (std::optional<Program> last = parser_->end(Program())) current_ = std::move(*last);
    blocks_ = current_.size();
    estimate_ = t.empty() ? 0 : static_cast<std::size_t>(static_cast<double>(blocks_) * static_cast<double>(size) /
                                                         static_cast<double>(t.size()));
    read_ahead();
}

ProgramSource::~ProgramSource() {
    // A piece being read on the other thread is waited for; a deferred one is never read.
    if (threads_ && ahead_.valid()) ahead_.wait();
}

// The next piece is read and parsed on the other core while the run works through this one
// (without threads: when the run asks for it).
void ProgramSource::read_ahead() {
    // The piece before last is parsed over: its pages are written already.
    ahead_ = std::async(threads_ ? std::launch::async : std::launch::deferred,
                        [this, into = std::move(spare_)]() mutable -> std::optional<Program> {
                            if (parser_->done()) return std::nullopt;
                            const std::string_view t = pieces_->next();
                            if (t.empty()) return parser_->end(std::move(into));
                            return parser_->parse(t, std::move(into));
                        });
}

std::function<const Program*()> ProgramSource::next_piece() {
    if (!parser_) return {};
    return [this]() -> const Program* {
        if (check_) check_();
        std::optional<Program> next;
        try {
            next = ahead_.get();  // a read error of the piece comes out here
        } catch (const Error&) {
            throw InputError{std::current_exception()};
        }
        if (!next) return nullptr;
        spare_ = std::exchange(current_, std::move(*next));
        blocks_ += current_.size();
        read_ahead();
        return &current_;
    };
}

}  // namespace toolcomp
