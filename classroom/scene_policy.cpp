#include "scene_policy.h"

#include "pde/pde_data_url.h"
#include "pde/pde_mesh.h"
#include "scene/field_access.h"
#include "scene/scene_reader.h"
#include "scene/scene_work.h"
#include "scene/source_map.h"

#include <algorithm>
#include <cmath>

namespace fl::classroom {

namespace {

void refuse(SceneCheck& check, scene::FilePos where, std::string message,
            std::string suggestion = {}) {
    check.diagnostics.push_back(
        {scene::Severity::Error, kSceneFileName, where, std::move(message), std::move(suggestion)});
}

bool hasUrl(const scene::Node& node) {
    const scene::Field* url = node.field("url");
    if (!url || url->value.strings.empty()) return false;
    // A PDE model carried in the scene (data: urls only) names no file.
    if (node.kind() == scene::NodeKind::FPdeSurface)
        return !std::all_of(url->value.strings.begin(), url->value.strings.end(),
                            [](const std::string& u) { return pde::isDataUrl(u); });
    return true;
}

// The triangles an FPdeSurface's model would take at the finest resolution
// its level of detail may choose: two per grid cell of every patch. An
// unreadable model costs nothing here (the shape shows its error).
double pdeCells(const scene::Node& node) {
    const scene::Field* url = node.field("url");
    if (!url) return 0;
    double resolution = scene::numberField(node, "resolution", 0, 32);
    const auto range = scene::numbersField(node, "lodRange");
    if (scene::boolField(node, "lod") && range.size() == 2)
        resolution = std::max(resolution, range[1]);
    const pde::MeshOptions grid = pde::meshOptionsFor(resolution);
    for (const std::string& u : url->value.strings) {
        const pde::ReadResult r = pde::readDataUrl(u, "data url");
        if (r.ok()) return double(r.model->patches.size()) * grid.stepsU * grid.stepsV;
    }
    return 0;
}

} // namespace

scene::ReadOptions readOptionsFor(const ClassroomLimits& limits) {
    scene::ReadOptions options;
    options.followReferences = false;
    options.limits.maxFileBytes = limits.maxSceneBytes;
    options.limits.maxDecodedBytes = limits.maxSceneBytes;
    options.limits.maxNodes = limits.maxNodes;
    options.limits.maxExpandedNodes = limits.maxNodes;
    options.limits.maxInlineFiles = 0;
    options.limits.maxDiagnostics = 50;
    options.limits.maxUnfoldedNodes = limits.maxUnfoldedNodes;
    options.limits.maxTapeInstructions = limits.maxTapeInstructions;
    options.limits.maxCompileSteps = limits.maxCompileSteps;
    return options;
}

scene::WorkBudget workBudgetFor(const ClassroomLimits& limits) {
    return {limits.maxMeshCells, limits.maxMeshEvaluations};
}

SceneCheck checkClassroomScene(const std::string& text, const ClassroomLimits& limits) {
    SceneCheck check;
    if (text.size() > limits.maxSceneBytes) {
        refuse(check, {},
               "the scene has " + std::to_string(text.size()) +
                   " bytes; a class scene may have at most " +
                   std::to_string(limits.maxSceneBytes));
        check.tooLarge = true;
        return check;
    }
    const scene::ReadOptions options = readOptionsFor(limits);
    scene::ReadResult read = scene::readSceneBytes(text, kSceneFileName, options);
    check.diagnostics = std::move(read.diagnostics);
    check.tooCostly = std::any_of(check.diagnostics.begin(), check.diagnostics.end(),
                                  [](const scene::SceneDiagnostic& d) { return d.overBudget; });
    if (!read.ok()) return check;
    const scene::Scene& s = *read.scene;
    check.nodes = s.nodeCount();
    check.tooLarge = check.nodes > limits.maxNodes;
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
    double pdeWork = 0;
    s.forEachNode([&](const scene::Node& node) {
        if (node.kind() == scene::NodeKind::FPdeSurface && !hasUrl(node)) {
            const double cells = pdeCells(node);
            pdeWork += cells;
            if (pdeWork > limits.maxMeshCells) {
                refuse(check, node.where,
                       "FPdeSurface: its model would take " + std::to_string(std::llround(cells)) +
                           " grid cells at its finest resolution; a class scene may mesh at most " +
                           std::to_string(std::llround(limits.maxMeshCells)) + " in all",
                       "fit fewer patches, or lower resolution and lodRange");
                check.tooCostly = true;
            }
        }
        if (node.kind() == scene::NodeKind::Inline || node.kind() == scene::NodeKind::Script ||
            hasUrl(node))
            refuse(check, node.where,
                   node.type + ": a class scene may not hold urls or scripts (" +
                       (node.kind() == scene::NodeKind::Script ? "a Script's code" : "a url") +
                       " is never fetched or run here)",
                   "put the shape itself in the scene, written with function nodes");
        for (const scene::Field& field : node.fields) {
            if (field.value.strings.empty() || field.name != "definition") continue;
            const std::string formula = scene::formulaText(field);
            if (formula.size() > limits.maxFormulaBytes) {
                refuse(check, field.where,
                       node.type + ".definition has " + std::to_string(formula.size()) +
                           " bytes; a class formula may have at most " +
                           std::to_string(limits.maxFormulaBytes));
                check.tooLarge = true;
            }
        }
    });
    if (auto costly = scene::checkWorkBudget(s, workBudgetFor(limits))) {
        costly->file = kSceneFileName;
        check.diagnostics.push_back(std::move(*costly));
        check.tooCostly = true;
    }
    check.ok = !scene::hasErrors(check.diagnostics);
    return check;
}

} // namespace fl::classroom
