#pragma once
// Where a run looks for the programs it calls by name (LinuxCNC o<name> call, Fanuc M98 /
// G65, Heidenhain CALL PGM, Sinumerik subprograms), and how it reads them: only in the
// search directories, only regular files, within the limits the caller set for the run.
//
// A called file is found by a name inside one of the directories. Its real path (symbolic
// links resolved) must lie inside that directory too, unless `follow_links` is set: a link
// in a search directory that leads to another place is refused ("outside_search_path"), so
// that a directory of programs cannot hand the run a file from anywhere else on the machine.
// Shops that keep their subprograms behind links set follow_links. An entry of the name that
// is not a regular file (a FIFO, a device, a directory) is refused ("not_a_regular_file"),
// never taken for "not found"; a link to nothing is no entry (the search goes on).
#include <filesystem>
#include <string>
#include <vector>

#include "toolcomp/program/input_limits.hpp"

namespace toolcomp {

struct SearchPath {
    std::vector<std::string> dirs;  // in order; none empty (check_search_path)
    bool follow_links = false;      // a link may lead out of its search directory
    ReadLimits limits;              // size of a called file, length of its lines
};

// Throws Error("search_path_empty") for an empty directory name (it would mean the working
// directory, which a run never searches).
void check_search_path(const std::vector<std::string>& dirs);

// What an entry of a search directory is, as a called program.
struct CalledEntry {
    enum Kind { absent, file, refused } kind = absent;
    std::filesystem::path path;  // file: the path to read (as named in the search directory)
    std::string code, message;   // refused: why ("not_a_regular_file", "outside_search_path")
};

// `candidate`: a path inside search directory `dir` (dir / name). absent when nothing has
// that name; file when it is a regular file whose real path lies inside `dir` (or
// follow_links); refused otherwise.
CalledEntry look_in(const SearchPath& search, const std::filesystem::path& dir, const std::filesystem::path& candidate);

// A called file's text, read within `search.limits` (its lines checked, a lone CR ending a
// line where `cr_ends_line`), or why it cannot be read (code: "file_not_found",
// "file_read_error", "not_a_regular_file", "input_too_large", "line_too_long").
struct CalledText {
    std::string text;
    std::string code, message;  // empty code: read
    bool ok() const { return code.empty(); }
};
CalledText read_called(const SearchPath& search, const std::filesystem::path& path, bool cr_ends_line);

}  // namespace toolcomp
