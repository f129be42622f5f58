#pragma once
// Facts about a mesh's connectivity that tests (and `functionlab mesh`)
// check: is it closed, is every edge shared by exactly two triangles, are
// neighbouring triangles oriented alike, which way does it enclose volume.
#include "mesh.h"

#include <cstddef>

namespace fl::mesh {

struct Topology {
    std::size_t edges = 0;
    std::size_t boundaryEdges = 0;       // used by one triangle: holes, open borders
    std::size_t nonManifoldEdges = 0;    // used by three or more
    std::size_t misorientedEdges = 0;    // two triangles walk it the same way
    std::size_t degenerateTriangles = 0; // a repeated index
    long eulerCharacteristic = 0;        // V - E + F over the vertices triangles use
    double signedVolume = 0;             // > 0 when the triangles face outward

    bool closed() const { return boundaryEdges == 0; }
    bool manifold() const { return nonManifoldEdges == 0; }
    bool consistentlyOriented() const { return misorientedEdges == 0; }
};

Topology analyseTopology(const Mesh& mesh);

// The mesh with triangles re-pointed at the first vertex of each exact
// position: where sharp edges duplicate vertices (a Box's 24 corners), the
// topology of the surface itself (closed once welded).
Mesh weldedByPosition(const Mesh& mesh);

// An implicit surface f = 0 has no preferred side, so its triangles face
// whichever way the sign of f says. When the surface closes on itself (a
// sphere written x^2+y^2+z^2-r^2), turns them and the normals to face out of
// the volume it encloses and returns true; leaves an open surface as it is
// and returns false.
bool orientClosedSurfaceOutward(Mesh& mesh);

// One unit normal per position: the area-weighted mean of the normals of
// the triangles round it (for a mesh read without normals, an OBJ); zero for
// a position no triangle with area uses.
std::vector<Vec3f> vertexNormals(const Mesh& mesh);

} // namespace fl::mesh
