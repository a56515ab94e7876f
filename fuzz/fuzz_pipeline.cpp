// libFuzzer target: parse + run, every dialect (see fuzz_targets.hpp).
#include "fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    (void)toolcomp::fuzz::pipeline(data, size);
    return 0;
}
