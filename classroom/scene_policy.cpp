#include "scene_policy.h"

#include "scene/scene_reader.h"
#include "scene/source_map.h"

namespace fl::classroom {

namespace {

void refuse(SceneCheck& check, scene::FilePos where, std::string message,
            std::string suggestion = {}) {
    check.diagnostics.push_back(
        {scene::Severity::Error, kSceneFileName, where, std::move(message), std::move(suggestion)});
}

bool hasUrl(const scene::Node& node) {
    const scene::Field* url = node.field("url");
    return url && !url->value.strings.empty();
}

} // namespace

SceneCheck checkClassroomScene(const std::string& text, const ClassroomLimits& limits) {
    SceneCheck check;
    if (text.size() > limits.maxSceneBytes) {
        refuse(check, {},
               "the scene has " + std::to_string(text.size()) +
                   " bytes; a class scene may have at most " +
                   std::to_string(limits.maxSceneBytes));
        return check;
    }
    scene::ReadOptions options;
    options.followReferences = false;
    options.limits.maxFileBytes = limits.maxSceneBytes;
    options.limits.maxDecodedBytes = limits.maxSceneBytes;
    options.limits.maxNodes = limits.maxNodes;
    options.limits.maxExpandedNodes = limits.maxNodes;
    options.limits.maxInlineFiles = 0;
    options.limits.maxDiagnostics = 50;
    scene::ReadResult read = scene::readSceneBytes(text, kSceneFileName, options);
    check.diagnostics = std::move(read.diagnostics);
    if (!read.ok()) return check;
    const scene::Scene& s = *read.scene;
    check.nodes = s.nodeCount();
    if (check.nodes > limits.maxNodes)
        refuse(check, {},
               "the scene has " + std::to_string(check.nodes) +
                   " nodes; a class scene may have at most " + std::to_string(limits.maxNodes));
    // A reference to a file the reader did not follow is a warning for a
    // file on disk; in a class it is a refusal (the scene must stand alone).
    std::erase_if(check.diagnostics, [](const scene::SceneDiagnostic& d) {
        return d.severity != scene::Severity::Error &&
               d.message.find("cannot be followed") != std::string::npos;
    });
    for (const scene::ProtoDeclaration* proto : s.protos)
        if (proto->external)
            refuse(check, proto->where,
                   "EXTERNPROTO " + proto->name + ": a class scene may not refer to other files",
                   "declare it with PROTO in the scene itself");
    s.forEachNode([&](const scene::Node& node) {
        if (node.type == "Inline" || node.type == "Script" || hasUrl(node))
            refuse(check, node.where,
                   node.type + ": a class scene may not hold urls or scripts (" +
                       (node.type == "Script" ? "a Script's code" : "a url") +
                       " is never fetched or run here)",
                   "put the shape itself in the scene, written with function nodes");
        for (const scene::Field& field : node.fields) {
            if (field.value.strings.empty() || field.name != "definition") continue;
            const std::string formula = scene::formulaText(field);
            if (formula.size() > limits.maxFormulaBytes)
                refuse(check, field.where,
                       node.type + ".definition has " + std::to_string(formula.size()) +
                           " bytes; a class formula may have at most " +
                           std::to_string(limits.maxFormulaBytes));
        }
    });
    check.ok = !scene::hasErrors(check.diagnostics);
    return check;
}

} // namespace fl::classroom
