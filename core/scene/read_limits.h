#pragma once
// Bounds on what a scene file may ask of us; each exceeded bound is a located
// error, never a crash, a hang or unbounded memory (docs/nodes.md, "Limits").
#include <cstddef>
#include <string>

namespace fl::scene {

struct ReadLimits {
    std::size_t maxFileBytes = 64u << 20;     // a file as read from disk
    std::size_t maxDecodedBytes = 256u << 20; // after gunzip
    std::size_t maxNodes = 2'000'000;         // written in files, all Inlines together
    std::size_t maxNestingDepth = 256;        // nodes within nodes, as written
    // What the scene is once every USE, PROTO instance and Inline is unfolded:
    // the work a walk down the tree does (a DEF used twice at each of 30
    // levels is a small file of a billion nodes). The depth is the one every
    // recursive walker guards against (kMaxWalkDepth).
    std::size_t maxUnfoldedNodes = 4'000'000;
    std::size_t maxUnfoldedDepth = 512;
    std::size_t maxExpandedNodes = 2'000'000; // created by PROTO expansion
    std::size_t maxProtoDepth = 32;           // PROTO instances within PROTO bodies
    std::size_t maxInlineDepth = 8;           // Inline within Inline
    std::size_t maxInlineFiles = 256;         // files one scene may pull in
    // The work of a scene's formulas: steps to compile them (inlining,
    // unrolling; a text shared by many PROTO instances compiles once) and the
    // instructions of their tapes, each instance counted (each is evaluated).
    long maxCompileSteps = 50'000'000;
    std::size_t maxTapeInstructions = 20'000'000;
    std::size_t maxDiagnostics = 200; // then one "too many" note
};

// A size as a person reads it in a message: "64 MiB", "256 KiB", "900 bytes".
inline std::string byteSizeText(std::size_t bytes) {
    if (bytes >= (1u << 20) && bytes % (1u << 20) == 0) return std::to_string(bytes >> 20) + " MiB";
    if (bytes >= (1u << 10) && bytes % (1u << 10) == 0) return std::to_string(bytes >> 10) + " KiB";
    return std::to_string(bytes) + " bytes";
}

} // namespace fl::scene
