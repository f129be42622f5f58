// libFuzzer target for the ClassicVRML / VRML97 reader (and the writers).
#include "scene_fuzz_common.h"

#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > 256 * 1024) return 0;
    std::string text(reinterpret_cast<const char*>(data), size);
    if (!text.starts_with("#")) text = "#X3D V3.3 utf8\nPROFILE Full\n" + text;
    fuzzSceneText(std::move(text));
    return 0;
}
