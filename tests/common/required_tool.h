#pragma once
// A test that needs an outside tool (view3dscene, the glTF validator,
// assimp, chromium, bubblewrap) skips where the tool is missing — on a
// developer's machine — but fails where it must be there: CI sets
// FUNCTIONLAB_REQUIRE_TOOLS=1 (.ci/run), so a tool the set-up failed to
// install can never turn its tests into silent passes.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string_view>

namespace fl::test {

inline bool toolsRequired() {
    const char* v = std::getenv("FUNCTIONLAB_REQUIRE_TOOLS");
    return v && std::string_view(v) != "" && std::string_view(v) != "0";
}

} // namespace fl::test

// Skips (or, with FUNCTIONLAB_REQUIRE_TOOLS, fails) the current test.
#define FUNCTIONLAB_SKIP_WITHOUT_TOOL(message)                                                     \
    do {                                                                                           \
        if (::fl::test::toolsRequired())                                                           \
            GTEST_FAIL() << message                                                                \
                         << " (FUNCTIONLAB_REQUIRE_TOOLS is set: the tool must be "                \
                            "installed)";                                                          \
        else                                                                                       \
            GTEST_SKIP() << message;                                                               \
    } while (0)
