#pragma once
// The standard geometry nodes of a scene (Box, Sphere, Cone, Cylinder,
// IndexedFaceSet, IndexedTriangleSet, TriangleSet, PointSet) read from their
// fields into meshes (standard_geometry.h). Other geometry is named in a note.
#include "mesh.h"
#include "scene/scene.h"

#include <string>
#include <vector>

namespace fl::mesh {

struct StandardGeometryResult {
    Mesh mesh;
    bool solid = true;                 // the node's `solid`: only front faces are drawn
    std::vector<std::string> warnings; // bad indices ...
    std::string unsupported;           // set (a note) when the node type is not drawn yet
};

// `segments`: around the axis of spheres, cones and cylinders.
StandardGeometryResult standardGeometryMesh(const scene::Node& geometry, int segments = 48);

} // namespace fl::mesh
