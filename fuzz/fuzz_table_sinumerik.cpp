// libFuzzer target: the Sinumerik tool data file (.ini) as a tool table, and the writers (see
// fuzz_targets.hpp).
#include "fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    (void)toolcomp::fuzz::table(toolcomp::TableFormat::sinumerik, data, size);
    return 0;
}
