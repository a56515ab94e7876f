#pragma once
// The files a run executes blocks of: the main program first, then every called program or
// subprogram file in the order the run first enters it. Motion::file and Path::file index it
// (Path::files), so a segment leads back to its block in its own file.
#include <string>
#include <vector>

namespace toolcomp {

// Runs `interp` and hands what `report` takes from it to `*out` (when given) whether the run
// ends or throws: the files of a run that stopped at an error still name its moves.
template <class Interp, class Out, class Report>
void run_reporting(Interp& interp, Out* out, Report report) {
    try {
        interp.run();
    } catch (...) {
        if (out) *out = report(interp);
        throw;
    }
    if (out) *out = report(interp);
}

class SourceFiles {
public:
    int index(const std::string& name) {
        for (std::size_t i = 0; i < names_.size(); ++i)
            if (names_[i] == name) return static_cast<int>(i);
        names_.push_back(name);
        return static_cast<int>(names_.size() - 1);
    }
    const std::vector<std::string>& names() const { return names_; }

private:
    std::vector<std::string> names_;
};

}  // namespace toolcomp
