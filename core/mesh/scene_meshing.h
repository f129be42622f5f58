#pragma once
// Meshes the function shapes of a scene at one moment: every FShape whose
// FGeometry is implicit or explicit, in its domain box, at the geometry's own
// t for that moment, placed by the Transform and FTransform nodes above it.
#include "dual_contouring.h"
#include "mesh.h"
#include "scene/scene.h"

#include <string>
#include <vector>

namespace fl::mesh {

struct SceneMeshOptions {
    MeshOptions mesh;              // threads, budget, cancel ...
    bool useFileResolution = true; // each FGeometry's `resolution`; false: mesh.resolution
    double targetError = 0;        // > 0: mesh each shape to this error instead
    double sceneSeconds = 0; // the moment, in scene time (wall clocks: the scene started at 0 UTC)
    // > 0: every function shape as a cloud of about this many points (its
    // FGeometry's `points` field otherwise; 0 there: a mesh).
    std::size_t points = 0;
};

struct ShapeMesh {
    const scene::Node* shape = nullptr;
    std::string name; // "FShape WATERMELON (file:line:col)"
    Mesh mesh;        // in scene coordinates
    MeshStats stats;
    double measuredError = -1; // with a target error: what was reached
    std::vector<std::string> warnings;
    std::string error;
};

struct SceneMeshes {
    std::vector<ShapeMesh> shapes;
    std::vector<std::string> notes; // what was not meshed and why
};

SceneMeshes meshScene(const scene::Scene& scene, const SceneMeshOptions& options);

// A function node's domain box (domainMin .. domainMax).
Box3 domainOf(const scene::Node& node);

// All shapes' meshes of one kind (triangles, or point clouds) as one.
Mesh mergeMeshes(const std::vector<ShapeMesh>& shapes, Primitive primitive = Primitive::Triangles);

} // namespace fl::mesh
