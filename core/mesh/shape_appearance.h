#pragma once
// What a shape's appearance does to its mesh: the constant light terms of
// its Material or FMaterial (SurfaceLook) and the vertex colours of its
// colour functions, evaluated in the geometry's own coordinates.
#include "scene_walk.h"

namespace fl::mesh {

// The light terms; without a material a function shape is lit and a
// standard one is not (X3D: unlit white).
SurfaceLook lookOf(const SceneWalkContext& context, const scene::Node* appearance,
                   bool functionShape);

// Vertex colours from the appearance's material over `geometryBox` (the
// geometry's coordinates, before the transforms above it move the mesh);
// keeps the colour field on the shape for picking and grading.
void colour(const SceneWalkContext& context, const scene::Node* appearance, const Box3& geometryBox,
            ShapeMesh& sm);

// A mesh's bounds as a box to colour over: a flat shape still gets depth.
Box3 colourBoxOf(const Mesh& m);

} // namespace fl::mesh
