// Reading a file whole within a size limit, and the limit on the length of one line.
#include "toolcomp/program/input_limits.hpp"
#include "toolcomp/program/codes.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "toolcomp/program/diagnostic.hpp"

namespace toolcomp {

namespace {

const char* file_kind(mode_t m) {
    if (S_ISDIR(m)) return "a directory";
    if (S_ISFIFO(m)) return "a FIFO (named pipe)";
    if (S_ISCHR(m)) return "a character device";
    if (S_ISBLK(m)) return "a block device";
    if (S_ISSOCK(m)) return "a socket";
    return "not a regular file";
}

}  // namespace

const char* file_kind_text(const std::string& path) {
    struct stat st;
    if (::stat(path.c_str(), &st) != 0 || S_ISREG(st.st_mode)) return nullptr;
    return file_kind(st.st_mode);
}

namespace {

FileText failed(FileText::Status s, std::string detail, std::uint64_t size = 0) {
    FileText r;
    r.status = s;
    r.detail = std::move(detail);
    r.size = size;
    return r;
}

// Lines ended in text[0, pos), pos just after a "\n" (or 0), by the rules of check_line_lengths.
std::size_t line_ends_before(std::string_view text, std::size_t pos, bool cr_ends_line) {
    std::size_t count = 0;
    for (std::size_t i = 0; i < pos; ++i) {
        if (text[i] == '\n') {
            ++count;
        } else if (cr_ends_line && text[i] == '\r') {
            std::size_t j = i;
            while (j < pos && text[j] == '\r') ++j;
            if (j < pos && text[j] == '\n') {
                ++count;  // "\r\n", "\r\r\n": one line end
                i = j;
            } else {
                count += j - i;  // each lone CR ends a line
                i = j - 1;
            }
        }
    }
    return count;
}

[[noreturn]] void too_long(std::size_t line, std::size_t length, std::size_t max) {
    const int l = line > static_cast<std::size_t>(INT32_MAX) ? INT32_MAX : static_cast<int>(line);
    throw ParseError(code::line_too_long,
                     "Line " + std::to_string(line) + " is " + std::to_string(length) +
                         " bytes long, more than the limit of " + std::to_string(max) + " bytes (max_line_length)",
                     {l, 0});
}

}  // namespace

namespace {
// Opens a regular file for reading: its descriptor, or -1 with `r` saying why. stat() first:
// opening a FIFO for reading would block until a writer comes.
int open_regular(const std::string& path, FileText& r, std::uint64_t& size) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) return r = failed(FileText::cannot_open, std::strerror(errno)), -1;
    if (!S_ISREG(st.st_mode)) return r = failed(FileText::not_regular, file_kind(st.st_mode)), -1;
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) return r = failed(FileText::cannot_open, std::strerror(errno)), -1;
    // The file opened may not be the one stat() saw (replaced in between): check it again.
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        ::close(fd);
        return r = failed(FileText::not_regular, file_kind(st.st_mode)), -1;
    }
    size = static_cast<std::uint64_t>(st.st_size);
    return fd;
}

[[noreturn]] void throw_read_error(const FileText& f, const std::string& path, std::uint64_t max_bytes,
                                   const std::string& what) {
    const std::string where = what + " '" + path + "'";
    if (f.status == FileText::cannot_open) throw ParseError(code::file_not_found, "Cannot open " + where);
    throw ParseError(read_error_code(f), "Cannot read " + where + ": " + read_error_text(f, max_bytes));
}
}  // namespace

FileText read_file_limited(const std::string& path, std::uint64_t max_bytes) {
    FileText status;
    std::uint64_t size = 0;
    const int fd = open_regular(path, status, size);
    if (fd < 0) return status;
    if (size > max_bytes) {
        ::close(fd);
        return failed(FileText::too_large, "", size);
    }
    FileText r;
    r.text.reserve(static_cast<std::size_t>(size));
    char buf[1 << 16];
    for (;;) {
        const ssize_t n = ::read(fd, buf, sizeof buf);
        if (n < 0) {
            if (errno == EINTR) continue;
            const int err = errno;
            ::close(fd);
            return failed(FileText::cannot_read, std::strerror(err));
        }
        if (n == 0) break;
        if (r.text.size() + static_cast<std::uint64_t>(n) > max_bytes) {  // grew while being read
            const std::uint64_t seen = r.text.size() + static_cast<std::uint64_t>(n);
            ::close(fd);
            return failed(FileText::too_large, "", seen);
        }
        r.text.append(buf, static_cast<std::size_t>(n));
    }
    ::close(fd);
    r.size = r.text.size();
    return r;
}

std::string byte_count_text(std::uint64_t n) {
    const char* units[] = {"KiB", "MiB", "GiB", "TiB"};
    std::string out = std::to_string(n) + " bytes";
    if (n < 1024) return out;
    double v = static_cast<double>(n);
    int u = -1;
    while (v >= 1024 && u < 3) {
        v /= 1024;
        ++u;
    }
    char b[32];
    std::snprintf(b, sizeof b, " (%.1f %s)", v, units[u]);
    return out + b;
}

const char* read_error_code(const FileText& f) {
    switch (f.status) {
        case FileText::ok: return "";
        case FileText::cannot_open: return code::file_not_found;
        case FileText::not_regular: return code::not_a_regular_file;
        case FileText::too_large: return code::input_too_large;
        default: return code::file_read_error;
    }
}

std::string read_error_text(const FileText& f, std::uint64_t max_bytes) {
    switch (f.status) {
        case FileText::ok: return "";
        case FileText::not_regular: return "it is " + f.detail + ", not a regular file";
        case FileText::too_large:
            return "it is " + byte_count_text(f.size) + ", more than the limit of " + byte_count_text(max_bytes) +
                   " (max_bytes)";
        default: return f.detail;
    }
}

std::string read_program_text(const std::string& path, std::uint64_t max_bytes, const std::string& what) {
    FileText f = read_file_limited(path, max_bytes);
    if (f.status == FileText::ok) return std::move(f.text);
    throw_read_error(f, path, max_bytes, what);
}

int open_program_file(const std::string& path, const std::string& what, std::uint64_t* size) {
    FileText f;
    std::uint64_t bytes = 0;
    const int fd = open_regular(path, f, bytes);
    if (fd < 0) throw_read_error(f, path, 0, what);
    if (size) *size = bytes;
    return fd;
}

void check_line_lengths(std::string_view text, std::size_t max_line_length, bool cr_ends_line, std::size_t first_line) {
    if (text.size() <= max_line_length) return;
    const char* b = text.data();
    const std::size_t n = text.size();
    std::size_t pos = 0;
    for (;;) {
        // The lines that start within max_line_length + 1 bytes of pos and end there (at the
        // last line end in those bytes) are short enough: passed over in one look.
        if (n - pos <= max_line_length) return;
        if (const void* last = memrchr(b + pos, '\n', max_line_length + 1)) {
            pos = static_cast<std::size_t>(static_cast<const char*>(last) - b) + 1;
            continue;
        }
        // The line at pos has no end within them: its length without the CRs before its end.
        const void* hit = std::memchr(b + pos, '\n', n - pos);
        const std::size_t end = hit ? static_cast<std::size_t>(static_cast<const char*>(hit) - b) : n;
        std::size_t content_end = end;  // CRs right before the "\n" belong to the line end
        while (content_end > pos && b[content_end - 1] == '\r') --content_end;
        if (content_end - pos > max_line_length) {
            if (!cr_ends_line) too_long(line_ends_before(text, pos, false) + first_line, content_end - pos, max_line_length);
            std::size_t start = pos, sub = 0;
            for (std::size_t i = pos; i <= content_end; ++i) {
                if (i < content_end && b[i] != '\r') continue;
                if (i - start > max_line_length)
                    too_long(line_ends_before(text, pos, true) + first_line + sub, i - start, max_line_length);
                ++sub;
                start = i + 1;
            }
        }
        if (!hit) return;
        pos = end + 1;
    }
}

}  // namespace toolcomp
