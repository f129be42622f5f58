#pragma once
// Bounds that keep a hostile or mistaken formula from exhausting the machine.
// Each one, when exceeded, produces a located error naming the limit.
#include <cstddef>

namespace fl::formula {

struct Limits {
    std::size_t maxSourceBytes = 256 * 1024;
    int maxNestingDepth = 200;         // parentheses, calls, blocks and operators combined
    long maxUnrolledIterations = 4096; // total loop iterations unrolled in one compilation
    std::size_t maxTapeSize = 200000;  // instructions after folding and sharing
    int maxCallDepth = 64;             // user-function inlining depth (recursion is refused)
    long maxExpansionSteps =
        1000000;        // statements and expressions visited while inlining and unrolling
    int maxErrors = 50; // stop reporting (and working) after this many errors
};

} // namespace fl::formula
