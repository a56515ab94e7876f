// libFuzzer target: the ISO front end (linuxcnc, fanuc, rockwell) (see fuzz_targets.hpp).
#include "fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    (void)toolcomp::fuzz::iso_parse(data, size);
    return 0;
}
