// Parse and run one program file through the C++ pipeline and print the time of each,
// for profiling without Python (valgrind --tool=callgrind, perf record):
//   bench_pipeline PROGRAM [TOOL_TABLE.tbl]         read whole, then run
//   bench_pipeline --file PROGRAM [TOOL_TABLE.tbl]  run_file: read piece by piece as it runs
// Prints figures, asserts nothing.
#include <chrono>
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

#include "toolcomp/program/dialect.hpp"
#include "toolcomp/run.hpp"
#include "toolcomp/tools/tool_table.hpp"

int main(int argc, char** argv) {
    const bool file = argc > 1 && std::string(argv[1]) == "--file";
    if (file) --argc, ++argv;
    if (argc < 2) {
        std::fprintf(stderr, "usage: bench_pipeline [--file] PROGRAM [TOOL_TABLE.tbl]\n");
        return 2;
    }
    using clock = std::chrono::steady_clock;
    std::optional<toolcomp::ToolTable> tools;
    if (argc > 2) tools = toolcomp::read_tool_table_file(argv[2]);
    toolcomp::RunOptions options;
    options.share_unchanged_path = true;  // as the Python module runs
    if (file) {
        const auto t0 = clock::now();
        const toolcomp::Result result = toolcomp::run_file(argv[1], std::nullopt, tools ? &*tools : nullptr, options);
        const double s = std::chrono::duration<double>(clock::now() - t0).count();
        std::printf("blocks %zu  segments %zu/%zu  diagnostics %zu\n", result.blocks, result.nominal.size(),
                    result.compensated().size(), result.diagnostics.size());
        std::printf("run_file %.3f s (%.0f ns/block)\n", s, s / static_cast<double>(result.blocks) * 1e9);
        return result.ok() ? 0 : 1;
    }
    const auto t0 = clock::now();
    const toolcomp::Program program = toolcomp::read_program(argv[1]);
    const auto t1 = clock::now();
    const toolcomp::Result result = toolcomp::run(program, tools ? &*tools : nullptr, options);
    const auto t2 = clock::now();
    const double parse = std::chrono::duration<double>(t1 - t0).count();
    const double run = std::chrono::duration<double>(t2 - t1).count();
    const double blocks = static_cast<double>(result.blocks);
    std::printf("blocks %zu  segments %zu/%zu  diagnostics %zu\n", result.blocks, result.nominal.size(),
                result.compensated().size(), result.diagnostics.size());
    std::printf("parse %.3f s (%.0f ns/block)  run %.3f s (%.0f ns/block)\n", parse, parse / blocks * 1e9, run,
                run / blocks * 1e9);
    return result.ok() ? 0 : 1;
}
