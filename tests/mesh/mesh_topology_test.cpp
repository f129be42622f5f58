// analyseTopology on small meshes whose every count is known by hand:
// a closed tetrahedron, one face turned, a fin (three triangles on one
// edge), an open fan, and degenerate triangles.
#include "mesh/mesh_topology.h"

#include <gtest/gtest.h>

using namespace fl::mesh;

namespace {

Mesh tetrahedron() {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    // Outward, counter-clockwise seen from outside.
    m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return m;
}

} // namespace

TEST(MeshTopology, AClosedTetrahedronIsASphere) {
    const Topology t = analyseTopology(tetrahedron());
    EXPECT_EQ(t.edges, 6u);
    EXPECT_EQ(t.boundaryEdges, 0u);
    EXPECT_EQ(t.nonManifoldEdges, 0u);
    EXPECT_EQ(t.misorientedEdges, 0u);
    EXPECT_EQ(t.eulerCharacteristic, 2);
    EXPECT_NEAR(t.signedVolume, 1.0 / 6.0, 1e-12);
    EXPECT_TRUE(t.closed());
}

TEST(MeshTopology, OneTurnedFaceMisorientsItsThreeEdges) {
    Mesh m = tetrahedron();
    std::swap(m.triangles[3][1], m.triangles[3][2]);
    const Topology t = analyseTopology(m);
    EXPECT_EQ(t.misorientedEdges, 3u);
    EXPECT_EQ(t.boundaryEdges, 0u);
}

TEST(MeshTopology, AFinIsNonManifoldAndAFanIsOpen) {
    Mesh fin;
    fin.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
    fin.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
    const Topology f = analyseTopology(fin);
    EXPECT_EQ(f.nonManifoldEdges, 1u);
    EXPECT_EQ(f.boundaryEdges, 6u);
    EXPECT_EQ(f.edges, 7u);
    EXPECT_EQ(f.eulerCharacteristic, 5 - 7 + 3);

    Mesh fan;
    fan.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    fan.triangles = {{0, 1, 2}, {0, 2, 3}};
    const Topology o = analyseTopology(fan);
    EXPECT_EQ(o.edges, 5u);
    EXPECT_EQ(o.boundaryEdges, 4u);
    EXPECT_EQ(o.misorientedEdges, 0u);
    EXPECT_FALSE(o.closed());
}

TEST(MeshTopology, DegenerateTrianglesAreCountedAndLeftOut) {
    Mesh m = tetrahedron();
    m.triangles.push_back({1, 1, 2});
    m.triangles.push_back({3, 0, 3});
    const Topology t = analyseTopology(m);
    EXPECT_EQ(t.degenerateTriangles, 2u);
    EXPECT_EQ(t.edges, 6u);
    EXPECT_EQ(t.eulerCharacteristic, 2);
    EXPECT_EQ(analyseTopology(Mesh{}).edges, 0u);
}
