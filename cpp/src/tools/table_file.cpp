// Reading and safely replacing tool-table files.
//
// A write never leaves a half-written table behind, even when the process is killed: the
// new text goes to a temporary file in the same directory, which is fsynced and renamed
// over the table (rename is atomic), and the directory is fsynced. Two writers of one table
// would otherwise race on that temporary file and on which rename wins, so a writer first
// takes an exclusive flock() on "<table>.lock" and a second writer fails at once with
// ToolTableError("table_locked"). flock() locks die with their process, so a writer killed
// mid-save leaves at most a stale lock file and a stale temporary file, both of which the
// next writer reuses. Reading opens the table read-only and takes no lock.
#include "toolcomp/program/diagnostic.hpp"
#include "toolcomp/program/codes.hpp"
#include "toolcomp/program/input_limits.hpp"
#include "toolcomp/tools/tool_table.hpp"

#include <cerrno>
#include <climits>
#include <cstdint>
#include <optional>
#include <cstdio>
#include <cstring>
#include <cstdlib>
#include <fcntl.h>
#include <string>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace toolcomp {

namespace {

[[noreturn]] void fail(const std::string& what, const std::string& path, int err) {
    throw ToolTableError(code::table_file_error, what + " '" + path + "': " + std::strerror(err));
}

// The file a path names, links resolved (the path itself when it does not exist yet).
std::string real_path(const std::string& path) {
    char buf[PATH_MAX];
    return ::realpath(path.c_str(), buf) ? std::string(buf) : path;
}

std::optional<ToolTable::FileStamp> stamp_of(const std::string& real) {
    struct stat st {};
    if (::stat(real.c_str(), &st) != 0) return std::nullopt;
    return ToolTable::FileStamp{real, static_cast<std::uint64_t>(st.st_dev), static_cast<std::uint64_t>(st.st_ino),
                                static_cast<std::uint64_t>(st.st_size),
                                static_cast<std::int64_t>(st.st_mtim.tv_sec) * 1'000'000'000 + st.st_mtim.tv_nsec};
}

std::string read_all(const std::string& path, std::uint64_t max_bytes) {
    FileText f = read_file_limited(path, max_bytes);
    if (f.status == FileText::ok) return std::move(f.text);
    const bool io = f.status == FileText::cannot_open || f.status == FileText::cannot_read;
    throw ToolTableError(io ? code::table_file_error : read_error_code(f),
                         std::string(f.status == FileText::cannot_open ? "cannot open" : "cannot read") +
                             " tool table '" + path + "': " + read_error_text(f, max_bytes));
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

// An exclusive lock on "<table>.lock" for the time of one write. The lock file is removed
// (while still locked) when the write is done. A writer that opened the file before its
// removal then holds a lock on an unlinked file: it must check that the file it locked is
// still the one at the lock path, and start again otherwise.
class WriterLock {
public:
    WriterLock(const std::string& table_path) : path_(table_path + ".lock") {
        for (int attempt = 0; attempt < 1000; ++attempt) {
            fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0666);
            if (fd_ < 0) fail("cannot create the lock file", path_, errno);
            if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
                const int err = errno;
                ::close(fd_);
                if (err == EWOULDBLOCK || err == EINTR)
                    throw ToolTableError(code::table_locked, "tool table '" + table_path +
                                                             "' is being written by another writer (lock file '" +
                                                             path_ + "'); try again when it has finished");
                fail("cannot lock", path_, err);
            }
            struct stat held {}, now {};
            if (::fstat(fd_, &held) == 0 && ::stat(path_.c_str(), &now) == 0 && held.st_dev == now.st_dev &&
                held.st_ino == now.st_ino)
                return;
            ::close(fd_);  // locked a lock file that its last holder had just removed
        }
        throw ToolTableError(code::table_locked, "cannot lock tool table '" + table_path + "' (lock file '" + path_ +
                                                 "' keeps being replaced)");
    }
    ~WriterLock() {
        ::unlink(path_.c_str());  // before closing: nobody else holds the lock yet
        ::close(fd_);
    }
    WriterLock(const WriterLock&) = delete;
    WriterLock& operator=(const WriterLock&) = delete;

private:
    std::string path_;
    int fd_ = -1;
};

}  // namespace

ToolTable read_tool_table_file(const std::string& path, std::optional<TableFormat> format, LengthUnit units,
                               std::uint64_t max_bytes) {
    const TableFormat f = format ? *format : table_format_from_path(path);
    const std::string real = real_path(path);
    const auto stamp = stamp_of(real);
    const std::string text = read_all(path, max_bytes);
    ToolTable table = read_tool_table(text, f, units);
    table.set_file_stamp(stamp);
    return table;
}

void write_tool_table_file(const ToolTable& table, const std::string& path, std::optional<TableFormat> format) {
    const TableFormat f = format ? *format : table_format_from_path(path);
    // Format first: an unrepresentable table must not touch the file system at all.
    const std::string data = write_tool_table(table, f);

    // A link stays a link: the file it names is replaced.
    const std::string target = real_path(path);
    const auto slash = target.find_last_of('/');
    const std::string dir = slash == std::string::npos ? "." : (slash == 0 ? "/" : target.substr(0, slash));
    const std::string base = slash == std::string::npos ? target : target.substr(slash + 1);
    const WriterLock lock(target);
    // The file this table was read from, changed since by someone else: writing would lose
    // their change.
    if (const auto& was = table.file_stamp(); was && was->path == target) {
        const auto now = stamp_of(target);
        if (now && !(*now == *was))
            throw ToolTableError(code::table_changed_on_disk,
                                 "'" + path + "' was changed since the table was read from it: read it again "
                                 "(or write to another file)");
    }
    // One temporary name per table: under the lock nobody else uses it, and a file left
    // there by a writer that was killed is simply replaced.
    const std::string tmp = dir + "/." + base + ".tmp";
    if (::unlink(tmp.c_str()) != 0 && errno != ENOENT) fail("cannot remove the old temporary file", tmp, errno);
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0600);
    if (fd < 0) fail("cannot create a temporary file for", path, errno);
    bool fd_open = true;
    try {
        // Keep the permissions of the file being replaced (the temporary file starts as 0600).
        struct stat st {};
        if (::stat(target.c_str(), &st) == 0) {
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
    if (::rename(tmp.c_str(), target.c_str()) != 0) {
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
    // A table read from this file now knows it as written (its next save is not a conflict);
    // a table built in memory, or read from another file, keeps what it had.
    if (const auto& was = table.file_stamp(); was && was->path == target) table.set_file_stamp(stamp_of(target));
}

}  // namespace toolcomp
