// libFuzzer target: the linuxcnc tool-table reader and the writers (see fuzz_targets.hpp).
#include "fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    (void)toolcomp::fuzz::table(toolcomp::TableFormat::linuxcnc, data, size);
    return 0;
}
