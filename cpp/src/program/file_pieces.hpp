#pragma once
// A program file read a piece at a time: whole lines, about `piece_bytes` each, so a file of
// any size is read in bounded memory. The first pieces are smaller (64 kB, then twice the one
// before): the run starts on the first while the next, parsed in another thread, is still
// short enough to be ready when the run needs it. Lines longer than `max_line_length` are refused with
// their line number (ParseError "line_too_long"), as when a file is read whole.
#include <cstddef>
#include <string>
#include <string_view>

namespace toolcomp {

class FilePieces {
public:
    // `cr_ends_line`: lone CRs end lines (program/dialect.hpp); they are handed out as LF.
    FilePieces(const std::string& path, std::size_t piece_bytes, std::size_t max_line_length, bool cr_ends_line);
    ~FilePieces();
    FilePieces(const FilePieces&) = delete;
    FilePieces& operator=(const FilePieces&) = delete;

    // The next piece (whole lines; the file's last line may lack its newline), empty at the
    // end of the file. Valid until the next call.
    std::string_view next();
    // Back to the start of the file.
    void rewind();

private:
    std::size_t first_piece_bytes() const;

    std::string path_;
    int fd_ = -1;
    std::size_t piece_bytes_, max_line_length_;
    std::size_t want_ = 0;  // the size of the next piece (growing to piece_bytes_)
    std::string buf_;       // the piece handed out, then the start of the next one
    std::size_t carry_ = 0; // bytes after the piece handed out (a line not yet complete)
    std::size_t lines_ = 0; // line ends before the piece handed out
    bool eof_ = false;
    bool cr_ends_line_;
    std::size_t decided_ = 0;  // CR line ends before it in buf_ are LF already
};

}  // namespace toolcomp
