// Finding and reading the programs a run calls by name (see search_path.hpp).
#include "toolcomp/program/search_path.hpp"
#include "toolcomp/program/codes.hpp"

#include "toolcomp/program/diagnostic.hpp"

namespace toolcomp {

void check_search_path(const std::vector<std::string>& dirs) {
    for (const std::string& d : dirs)
        if (d.empty())
            throw Error(ErrorKind::generic, code::search_path_empty,
                        "An empty directory name in the search path (it would mean the working directory, which a "
                        "run never searches: name the directory, e.g. '.')");
}

namespace {
// Whether `inner` is `dir` itself or lies below it (both real paths: canonical, so without
// a trailing separator, "." or "..").
bool inside(const std::filesystem::path& inner, const std::filesystem::path& dir) {
    auto i = inner.begin();
    for (auto d = dir.begin(); d != dir.end(); ++d, ++i)
        if (i == inner.end() || *i != *d) return false;
    return true;
}
}  // namespace

CalledEntry look_in(const SearchPath& search, const std::filesystem::path& dir, const std::filesystem::path& candidate) {
    namespace fs = std::filesystem;
    CalledEntry e;
    std::error_code ec;
    // Nothing of that name, or a link to nothing (a dangling link, a loop): the search goes
    // on in the next directory, as it would for a missing file.
    if (!fs::exists(candidate, ec)) return e;
    e.path = candidate;
    if (!search.follow_links) {
        const fs::path real = fs::canonical(candidate, ec);
        const fs::path real_dir = ec ? fs::path() : fs::canonical(dir, ec);
        if (ec) {  // gone between the two looks
            e.kind = CalledEntry::refused;
            e.code = code::file_not_found;
            e.message = "Cannot read " + candidate.string() + ": " + ec.message();
            return e;
        }
        if (!inside(real, real_dir)) {
            e.kind = CalledEntry::refused;
            e.code = code::outside_search_path;
            e.message = candidate.string() + " is a link to " + real.string() +
                        ", outside its search directory (follow_links=True allows it)";
            return e;
        }
    }
    if (const char* kind = file_kind_text(candidate.string())) {
        e.kind = CalledEntry::refused;
        e.code = code::not_a_regular_file;
        e.message = "Cannot read " + candidate.string() + ": it is " + kind + ", not a regular file";
        return e;
    }
    e.kind = CalledEntry::file;
    return e;
}

CalledText read_called(const SearchPath& search, const std::filesystem::path& path, bool cr_ends_line) {
    CalledText r;
    FileText f = read_file_limited(path.string(), search.limits.max_bytes);
    if (f.status != FileText::ok) {
        r.code = read_error_code(f);
        r.message = "Cannot read " + path.string() + ": " + read_error_text(f, search.limits.max_bytes);
        return r;
    }
    try {
        check_line_lengths(f.text, search.limits.max_line_length, cr_ends_line);
    } catch (const Error& e) {
        r.code = e.code();
        r.message = path.string() + ": " + e.what();
        return r;
    }
    r.text = std::move(f.text);
    return r;
}

}  // namespace toolcomp
