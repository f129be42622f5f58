#pragma once
// The standard X3D geometry nodes as meshes, from plain parameters (the scene
// adapter in scene_standard_geometry.h reads them from nodes): so the viewer,
// the exports and the haptics' polygonal mode treat a Box like any function
// shape. Sizes and orientation follow X3D 19775-1 (13 Geometry3D, 11
// Rendering): centred on the origin, axes along y, counter-clockwise faces.
#include "field_names.h"
#include "mesh.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace fl::mesh {

Mesh boxMesh(std::array<double, 3> size);
// `segments` around the axis (at least 3); a sphere uses half as many rings.
Mesh sphereMesh(double radius, int segments = 48);
Mesh coneMesh(double bottomRadius, double height, bool side, bool bottom, int segments = 48);
Mesh cylinderMesh(double radius, double height, bool side, bool top, bool bottom,
                  int segments = 48);

// IndexedFaceSet, IndexedTriangleSet and friends, reduced to their common
// form: polygons as index lists (-1 ends one), optional colours and normals
// per vertex or per face.
struct FaceSet {
    std::vector<std::array<double, 3>> points;
    std::vector<std::int64_t> coordIndex;      // polygons, each ended by -1 (or the list's end)
    std::vector<std::array<float, 4>> colours; // Color (alpha 1) or ColorRGBA
    std::vector<std::int64_t> colourIndex; // empty: coordIndex (per vertex) or 0, 1, ... (per face)
    bool colourPerVertex = true;
    std::vector<std::array<double, 3>> normals;
    std::vector<std::int64_t> normalIndex;
    bool normalPerVertex = true;
    bool ccw = true;
    double creaseAngle = 0; // radians: neighbouring faces closer than this share a smooth normal
    // TextureCoordinate points, per vertex through texCoordIndex (or else
    // coordIndex); none: X3D's default, the bounding box's longest side
    // along s and the next along t, at the same scale.
    std::vector<std::array<double, 2>> texCoords;
    std::vector<std::int64_t> texCoordIndex;
};

struct FaceSetResult {
    Mesh mesh;
    std::vector<std::string> warnings; // bad indices, degenerate polygons (said once each)
};

// Polygons are fanned into triangles (X3D's `convex` is assumed); vertices are
// not shared between faces, so creases and per-face colours stay sharp.
FaceSetResult faceSetMesh(const FaceSet& faces);

// ElevationGrid: heights over an x-z grid, faces up (+y) with ccw TRUE.
struct ElevationGrid {
    int xDimension = 0, zDimension = 0;
    double xSpacing = 1, zSpacing = 1;
    std::vector<double> height; // xDimension * zDimension, x fastest
    std::vector<std::array<float, 4>> colours;
    bool colourPerVertex = true;
    bool ccw = true;
    double creaseAngle = 0;
    std::vector<std::array<double, 2>> texCoords; // one per height; none: s along x, t along z
};
FaceSetResult elevationGridMesh(const ElevationGrid& grid);

// Extrusion: a 2D cross-section swept along a spine, scaled and turned at
// each spine point (X3D 13.3.5: the spine-aligned cross-section planes).
struct Extrusion {
    std::vector<std::array<double, 2>> crossSection{{1, 1}, {1, -1}, {-1, -1}, {-1, 1}, {1, 1}};
    std::vector<std::array<double, 3>> spine{{0, 0, 0}, {0, 1, 0}};
    std::vector<std::array<double, 2>> scale{{1, 1}};             // one, or one per spine point
    std::vector<std::array<double, 4>> orientation{{0, 0, 1, 0}}; // axis-angle, likewise
    bool beginCap = true, endCap = true;
    double creaseAngle = 0;
};
// Faces outward: closed extrusions by their volume, open ones away from the spine.
FaceSetResult extrusionMesh(const Extrusion& extrusion);

// IndexedLineSet (polylines in `coordIndex`, -1 between) and LineSet (given
// as a coordIndex by the adapter): segments, colours per vertex or per
// polyline; normals zero (lines are unlit).
FaceSetResult lineSetMesh(const FaceSet& lines);

// PointSet: its points with their colours; normals zero (unlit).
Mesh pointSetMesh(const std::vector<std::array<double, 3>>& points,
                  const std::vector<std::array<float, 4>>& colours);

} // namespace fl::mesh
