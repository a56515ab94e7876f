// libFuzzer target: the Sinumerik tool data reader and writer (see fuzz_targets.hpp).
#include "fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    (void)toolcomp::fuzz::tc_dp(data, size);
    return 0;
}
