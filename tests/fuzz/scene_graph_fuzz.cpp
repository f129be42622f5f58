// libFuzzer target for loops made with DEF and USE (issue 26 §1): the bytes
// choose a graph of grouping nodes (Group, Transform, Switch, LOD,
// FTransform, a PROTO instance) and how it is written, in X3D XML or
// ClassicVRML. The law: the reader refuses the scene, with a located error
// that says so, exactly when the graph has a loop; a scene without one loads
// and goes through the writers and back like any other.
#include "../common/node_graph_text.h"
#include "scene_fuzz_common.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const fl::test::NodeGraphText graph = fl::test::NodeGraphText::fromBytes(data, size);
    const std::string text = graph.text();
    const fl::scene::ReadResult r = fl::scene::readSceneBytes(text, "graph");
    const fl::scene::SceneDiagnostic* error = nullptr;
    for (const auto& d : r.diagnostics)
        if (d.severity == fl::scene::Severity::Error && !error) error = &d;
    const bool loop = graph.hasLoop();
    const bool saysLoop = error && error->pos.line > 0 &&
                          (error->message.find("makes a loop") != std::string::npos ||
                           error->message.find("inside the node it names") != std::string::npos);
    if (loop != !r.ok() || (loop && !saysLoop)) {
        std::fprintf(stderr, "graph %s a loop, but the scene %s:\n%s\n%s\n",
                     loop ? "has" : "has no", r.ok() ? "loads" : "is refused", text.c_str(),
                     error ? fl::scene::formatSceneDiagnostic(*error).c_str() : "");
        std::abort();
    }
    if (!loop) fuzzSceneText(text);
    return 0;
}
