#pragma once
// What a dialect's interpreter leaves besides its moves, also when it stops at an error.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "toolcomp/tools/tool_table.hpp"

namespace toolcomp {

// Numbered parameter values (#n -> value): what a run starts from (a LinuxCNC .var file,
// Fanuc common variables) and what it ends with.
using ParameterValues = std::map<int, double>;

struct InterpretOutput {
    std::vector<std::string> files;  // the files moves came from, main program first (Motion::file)
    ParameterValues parameters;      // numbered parameters at the end (set ones only; ISO dialects)
    std::optional<ToolTable> tools;  // the tool table as the program left it, when it edited it (G10 L1)
    double dwell_seconds = 0;        // the dwells the run made (G4, the cycles' dwells), seconds
};

}  // namespace toolcomp
