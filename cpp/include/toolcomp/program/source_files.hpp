#pragma once
// The files a run executes blocks of: the main program first, then every called program or
// subprogram file in the order the run first enters it. Motion::file and Path::file index it
// (Path::files), so a segment leads back to its block in its own file.
#include <string>
#include <vector>

namespace toolcomp {

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
