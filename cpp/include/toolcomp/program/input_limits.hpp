#pragma once
// Limits on the input a run accepts: the size of a file read whole (program, called
// program, tool table) and the length of one program line. A file is checked before a
// byte of it is read: only regular files are read (a FIFO, a device such as /dev/zero or a
// directory would block or never end), and one larger than the limit is refused at once.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace toolcomp {

inline constexpr std::uint64_t kDefaultMaxProgramBytes = std::uint64_t{2} << 30;  // 2 GiB
inline constexpr std::uint64_t kDefaultMaxTableBytes = std::uint64_t{256} << 20;  // 256 MiB
inline constexpr std::size_t kDefaultMaxLineLength = std::size_t{1} << 20;        // 1 MiB

// Limits on reading a program file: a run's main program and every file it calls.
struct ReadLimits {
    std::uint64_t max_bytes = kDefaultMaxProgramBytes;  // larger files: ParseError("input_too_large")
    std::size_t max_line_length = kDefaultMaxLineLength;
};

// What reading a file whole found. On anything but `ok`, `text` is empty and `detail` says
// why: strerror() for cannot_open / cannot_read, the kind of file ("a FIFO", "a directory",
// ...) for not_regular, nothing for too_large (`size` holds the size found).
struct FileText {
    enum Status { ok, cannot_open, cannot_read, not_regular, too_large } status = ok;
    std::string text;
    std::string detail;
    std::uint64_t size = 0;
};

// Reads `path` whole if it is a regular file of at most `max_bytes` bytes. Never blocks on a
// FIFO and never reads more than max_bytes + 1 bytes (a file that grows while it is read is
// too large as well).
FileText read_file_limited(const std::string& path, std::uint64_t max_bytes);

// The error code of a failed read ("file_not_found", "file_read_error",
// "not_a_regular_file", "input_too_large") and what went wrong, to follow "Cannot read
// <file>: " ("it is a FIFO (named pipe), not a regular file", "it is 10737418240 bytes
// (10.0 GiB), more than the limit of ... (max_bytes)").
const char* read_error_code(const FileText& f);
std::string read_error_text(const FileText& f, std::uint64_t max_bytes);

// What `path` names (links followed) when it is there and not a regular file: "a directory",
// "a FIFO (named pipe)", "a character device", ...; nullptr for a regular file or nothing.
const char* file_kind_text(const std::string& path);

// "2147483648 bytes (2.0 GiB)": a byte count for messages.
std::string byte_count_text(std::uint64_t n);

// A program file read whole, or ParseError: "file_not_found" (cannot be opened),
// "file_read_error", "not_a_regular_file", "input_too_large" (message names the size and
// the limit). `what` names the file in the message ("program file").
std::string read_program_text(const std::string& path, std::uint64_t max_bytes, const std::string& what = "program file");

// Opens a program file to be read bit by bit (no size limit): its file descriptor, or the
// ParseError of read_program_text ("file_not_found", "not_a_regular_file").
// `size` (when given) receives the file's size.
int open_program_file(const std::string& path, const std::string& what = "program file", std::uint64_t* size = nullptr);

// Throws ParseError("line_too_long") with the 1-based line number of the first line longer
// than `max_line_length` bytes (line end not counted). Lines end with "\n"; with
// `cr_ends_line` also with a lone "\r" ("\r\n" and "\r\r\n" are one line end), as the
// Sinumerik and Heidenhain front ends read them. `first_line`: the number of text's first
// line (a piece of a longer text).
void check_line_lengths(std::string_view text, std::size_t max_line_length, bool cr_ends_line, std::size_t first_line = 1);

}  // namespace toolcomp
