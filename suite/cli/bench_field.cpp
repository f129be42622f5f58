#include "cli/bench_field.h"

#include "mesh/scene_meshing.h"
#include "scene/field_access.h"
#include "scene/scene_reader.h"

#include <iostream>

namespace fl::cli {

bool benchFieldFromScene(const std::string& command, const std::string& file,
                         field::ImplicitField& field, std::string& name) {
    scene::ReadResult r = scene::readSceneFile(file);
    for (const auto& d : r.diagnostics)
        std::cerr << scene::formatSceneDiagnostic(d) << "\n";
    if (!r.ok()) return false;
    bool found = false;
    r.scene->forEachNode([&](const scene::Node& n) {
        if (found || n.inProtoBody || n.kind() != scene::NodeKind::FGeometry ||
            scene::stringField(n, "type") == "parametric")
            return;
        const formula::Tape* tape = r.scene->definition(n, "definition");
        if (!tape) return;
        field.tape = *tape;
        field.box = mesh::domainOf(n);
        name = file + ":" + std::to_string(n.where.line);
        found = true;
    });
    if (!found)
        std::cerr << "functionlab " << command << ": " << file
                  << " has no implicit or explicit FGeometry\n";
    return found;
}

} // namespace fl::cli
