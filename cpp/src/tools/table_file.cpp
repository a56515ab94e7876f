// Reading and safely replacing tool-table files.
#include "toolcomp/program/diagnostic.hpp"
#include "toolcomp/tools/tool_table.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

namespace toolcomp {

namespace {

[[noreturn]] void fail(const std::string& what, const std::string& path, int err) {
    throw ToolTableError("table_file_error", what + " '" + path + "': " + std::strerror(err));
}

std::string read_all(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) fail("cannot open tool table", path, errno);
    std::string out;
    char buf[1 << 16];
    for (;;) {
        const ssize_t n = ::read(fd, buf, sizeof buf);
        if (n < 0) {
            if (errno == EINTR) continue;
            const int err = errno;
            ::close(fd);
            fail("cannot read tool table", path, err);
        }
        if (n == 0) break;
        out.append(buf, static_cast<std::size_t>(n));
    }
    ::close(fd);
    return out;
}

void write_all(int fd, const std::string& data, const std::string& path) {
    std::size_t done = 0;
    while (done < data.size()) {
        const ssize_t n = ::write(fd, data.data() + done, data.size() - done);
        if (n < 0) {
            if (errno == EINTR) continue;
            fail("cannot write tool table", path, errno);
        }
        done += static_cast<std::size_t>(n);
    }
}

}  // namespace

ToolTable read_tool_table_file(const std::string& path, std::optional<TableFormat> format, LengthUnit units) {
    const TableFormat f = format ? *format : table_format_from_path(path);
    const std::string text = read_all(path);
    return read_tool_table(text, f, units);
}

void write_tool_table_file(const ToolTable& table, const std::string& path, std::optional<TableFormat> format) {
    const TableFormat f = format ? *format : table_format_from_path(path);
    // Format first: an unrepresentable table must not touch the file system at all.
    const std::string data = write_tool_table(table, f);

    const auto slash = path.find_last_of('/');
    const std::string dir = slash == std::string::npos ? "." : (slash == 0 ? "/" : path.substr(0, slash));
    const std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
    std::string tmp = dir + "/." + base + ".tmpXXXXXX";
    const int fd = ::mkstemp(tmp.data());
    if (fd < 0) fail("cannot create a temporary file for", path, errno);
    bool fd_open = true;
    try {
        // Keep the permissions of the file being replaced (mkstemp creates 0600).
        struct stat st {};
        if (::stat(path.c_str(), &st) == 0) {
            ::fchmod(fd, st.st_mode & 07777);
        } else {
            const mode_t mask = ::umask(0);
            ::umask(mask);
            ::fchmod(fd, 0666 & ~mask);
        }
        write_all(fd, data, path);
        if (::fsync(fd) != 0) fail("cannot flush tool table", path, errno);
        fd_open = false;
        if (::close(fd) != 0) fail("cannot close tool table", path, errno);
    } catch (...) {
        if (fd_open) ::close(fd);
        ::unlink(tmp.c_str());
        throw;
    }
    if (::rename(tmp.c_str(), path.c_str()) != 0) {
        const int err = errno;
        ::unlink(tmp.c_str());
        fail("cannot replace tool table", path, err);
    }
    // Make the rename itself durable.
    const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dfd >= 0) {
        ::fsync(dfd);
        ::close(dfd);
    }
}

}  // namespace toolcomp
