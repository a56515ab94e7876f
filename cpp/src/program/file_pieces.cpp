#include "file_pieces.hpp"
#include "toolcomp/program/codes.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <unistd.h>

#include "toolcomp/program/diagnostic.hpp"
#include "toolcomp/program/input_limits.hpp"
#include "toolcomp/program/text.hpp"

namespace toolcomp {

FilePieces::FilePieces(const std::string& path, std::size_t piece_bytes, std::size_t max_line_length,
                       bool cr_ends_line)
    : path_(path), fd_(open_program_file(path)), piece_bytes_(std::max<std::size_t>(piece_bytes, 1)),
      max_line_length_(max_line_length), want_(first_piece_bytes()), cr_ends_line_(cr_ends_line) {}

std::size_t FilePieces::first_piece_bytes() const { return std::min<std::size_t>(piece_bytes_, std::size_t{1} << 16); }

FilePieces::~FilePieces() {
    if (fd_ >= 0) ::close(fd_);
}

void FilePieces::rewind() {
    if (::lseek(fd_, 0, SEEK_SET) < 0)
        throw ParseError(code::file_read_error, "Cannot read program file '" + path_ + "': " + std::strerror(errno));
    buf_.clear();
    carry_ = lines_ = decided_ = 0;
    eof_ = false;
    want_ = first_piece_bytes();
}

std::string_view FilePieces::next() {
    if (cr_ends_line_) decided_ -= buf_.size() - carry_;
    buf_.erase(0, buf_.size() - carry_);  // the piece handed out last time
    // Read until a piece's worth ending with a newline is there, or the file ends.
    const std::size_t want = want_;
    want_ = std::min(2 * want_, piece_bytes_);
    while (!eof_ && !(buf_.size() >= want && buf_.rfind('\n') != std::string::npos)) {
        const std::size_t have = buf_.size();
        buf_.resize(have + std::max<std::size_t>(want > have ? want - have : 0, 1 << 16));
        const ssize_t n = ::read(fd_, buf_.data() + have, buf_.size() - have);
        buf_.resize(have + static_cast<std::size_t>(std::max<ssize_t>(n, 0)));
        if (n < 0) {
            if (errno == EINTR) continue;
            throw ParseError(code::file_read_error, "Cannot read program file '" + path_ + "': " + std::strerror(errno));
        }
        eof_ = n == 0;
        if (cr_ends_line_)
            decided_ += cr_line_ends_to_lf(buf_.data() + decided_, buf_.size() - decided_, eof_);
        // A line with no end within the limit is too long, whatever follows: stop reading it.
        const std::size_t last_nl = buf_.rfind('\n');
        const std::size_t from = last_nl == std::string::npos ? 0 : last_nl + 1;
        // CRs at the end not yet decided (line ends if no LF follows) are no line content.
        const std::size_t upto = cr_ends_line_ ? decided_ : buf_.size();
        if (upto > from && upto - from > max_line_length_ + 2) {
            const std::size_t line =
                lines_ + 1 + static_cast<std::size_t>(std::count(buf_.begin(), buf_.begin() + from, '\n'));
            throw ParseError(code::line_too_long,
                             "Line " + std::to_string(line) + " is longer than the limit of " +
                                 std::to_string(max_line_length_) + " bytes (max_line_length)",
                             {static_cast<int>(std::min<std::size_t>(line, INT32_MAX)), 0});
        }
    }
    const std::size_t end = eof_ ? buf_.size() : buf_.rfind('\n') + 1;
    carry_ = buf_.size() - end;
    const std::string_view piece(buf_.data(), end);
    check_line_lengths(piece, max_line_length_, false, lines_ + 1);
    lines_ += line_ends(piece);
    return piece;
}

}  // namespace toolcomp
