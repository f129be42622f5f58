#pragma once
// A coarse picture of a scene's function shapes in plain X3D, for the X3D
// browsers that know nothing of FShape: `functionlab convert` adds it as one
// root Group (DEF scene::kPreviewDefName) of IndexedFaceSets with per-vertex
// colours and normals, at the scene's moment 0, in scene coordinates.
// FunctionLab's readers drop that Group again, so it never becomes part of
// the user's scene, and write-then-read stays the identity.
#include "scene/scene.h"
#include "scene_meshing.h"

#include <cstddef>
#include <string>
#include <vector>

namespace fl::mesh {

struct PreviewOptions {
    double resolution = 32; // cells along each domain box's longest side
    int threads = 0;        // 0: one per core
};

struct PreviewResult {
    std::size_t shapes = 0;    // function shapes drawn
    std::size_t triangles = 0; // in all
    std::vector<std::string> warnings;
};

// A standard Shape node, owned by `into`, that draws a mesh as X3D browsers
// can: an IndexedFaceSet (or IndexedLineSet, PointSet) with the mesh's
// per-vertex colours and normals and a Material with its look's constant
// terms (a see-through mesh's mean opacity as its transparency).
scene::Node* standardShapeNode(scene::Scene& into, const ShapeMesh& shape);

// Appends the preview to `scene.roots`; adds nothing when the scene has no
// function shape to draw.
PreviewResult addPreview(scene::Scene& scene, const PreviewOptions& options = {});

} // namespace fl::mesh
