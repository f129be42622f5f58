#pragma once
// The standard geometry nodes of a scene read from their fields into meshes
// (standard_geometry.h): Geometry3D (Box, Sphere, Cone, Cylinder,
// IndexedFaceSet, ElevationGrid, Extrusion), Rendering (triangle, fan, strip
// and quad sets, indexed or not, line and point sets), Geometry2D (in the
// z = 0 plane). Other geometry is named in a note.
#include "mesh.h"
#include "scene/field_source.h"
#include "scene/scene.h"
#include "text_layout.h"

#include <string>
#include <vector>

namespace fl::mesh {

struct StandardGeometryResult {
    Mesh mesh;
    bool solid = true;                 // the node's `solid`: only front faces are drawn
    std::vector<std::string> warnings; // bad indices ...
    std::string unsupported;           // set (a note) when the node type is not drawn yet
};

// `segments`: around the axis of spheres, cones and cylinders (and of
// Geometry2D circles). `text`: the font source for Text (none: a note).
// `fields`: where the node's values come from — the one clock at a moment
// (a CoordinateInterpolator moves the points), or the file.
StandardGeometryResult standardGeometryMesh(const scene::Node& geometry, int segments = 48,
                                            const TextOutliner& text = {},
                                            const scene::FieldSource& fields = scene::FileFields{});

// The node's `solid` (only front faces drawn); true for nodes without one.
bool standardGeometryIsSolid(const scene::Node& geometry, const scene::FieldSource& fields);

} // namespace fl::mesh
