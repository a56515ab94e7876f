// libFuzzer target: the Sinumerik front end (see fuzz_targets.hpp).
#include "fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    (void)toolcomp::fuzz::sinumerik_parse(data, size);
    return 0;
}
