#pragma once
// An FPdeSurface's model: its url read like an Inline's — only a file
// inside the top scene's folder, the first url entry that reads — and kept
// while the file is unchanged (a viewer meshes the shape again and again).
#include "pde/pde_model.h"
#include "scene/scene.h"

#include <memory>
#include <string>
#include <vector>

namespace fl::mesh {

struct PdeSurfaceModel {
    std::shared_ptr<const pde::Model> model; // null: `error` says why
    std::string file;                        // the file read (its key in caches)
    std::string error;
};

PdeSurfaceModel pdeSurfaceModel(const scene::Scene& scene, const scene::Node& surface,
                                const std::vector<std::string>& urls);

} // namespace fl::mesh
