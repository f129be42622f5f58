// libFuzzer target for the X3D XML reader (and the writers).
#include "scene_fuzz_common.h"

#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > 256 * 1024) return 0;
    std::string text(reinterpret_cast<const char*>(data), size);
    if (!text.starts_with("<")) text = "<X3D profile='Full'><Scene>" + text + "</Scene></X3D>";
    fuzzSceneText(std::move(text));
    return 0;
}
