#include "mesh_geometry.h"

#include <Qt3DCore/QAttribute>
#include <Qt3DCore/QBuffer>
#include <Qt3DCore/QGeometry>

#include <algorithm>
#include <cstring>
#include <vector>

namespace fl::viewer {
namespace {

constexpr int kFloatsPerVertex = 10; // position 3, normal 3, colour 4

Qt3DCore::QAttribute* attribute(Qt3DCore::QGeometry* g, Qt3DCore::QBuffer* buffer,
                                const QString& name, uint size, uint offset, uint count) {
    auto* a = new Qt3DCore::QAttribute(g);
    a->setName(name);
    a->setAttributeType(Qt3DCore::QAttribute::VertexAttribute);
    a->setVertexBaseType(Qt3DCore::QAttribute::Float);
    a->setVertexSize(size);
    a->setBuffer(buffer);
    a->setByteStride(kFloatsPerVertex * sizeof(float));
    a->setByteOffset(offset * sizeof(float));
    a->setCount(count);
    g->addAttribute(a);
    return a;
}

} // namespace

bool hasTransparency(const mesh::Mesh& mesh, std::array<float, 4> colour) {
    if (mesh.colours.size() != mesh.positions.size()) return colour[3] < 1;
    for (const auto& c : mesh.colours)
        if (c[3] < 1) return true;
    return false;
}

Qt3DRender::QGeometryRenderer* makeGeometryRenderer(const mesh::Mesh& mesh,
                                                    std::array<float, 4> colour,
                                                    Qt3DCore::QNode* parent, DrawAs as) {
    auto* renderer = new Qt3DRender::QGeometryRenderer(parent);
    auto* geometry = new Qt3DCore::QGeometry(renderer);
    const bool colours = mesh.colours.size() == mesh.positions.size();
    const uint n = uint(mesh.positions.size());
    QByteArray vertices(qsizetype(n) * kFloatsPerVertex * qsizetype(sizeof(float)),
                        Qt::Uninitialized);
    float* v = reinterpret_cast<float*>(vertices.data());
    for (uint i = 0; i < n; ++i) {
        std::memcpy(v, mesh.positions[i].data(), 3 * sizeof(float));
        if (i < mesh.normals.size())
            std::memcpy(v + 3, mesh.normals[i].data(), 3 * sizeof(float));
        else
            v[3] = v[4] = v[5] = 0;
        std::memcpy(v + 6, colours ? mesh.colours[i].data() : colour.data(), 4 * sizeof(float));
        v += kFloatsPerVertex;
    }
    auto* vertexBuffer = new Qt3DCore::QBuffer(geometry);
    vertexBuffer->setData(vertices);
    auto* position = attribute(geometry, vertexBuffer,
                               Qt3DCore::QAttribute::defaultPositionAttributeName(), 3, 0, n);
    attribute(geometry, vertexBuffer, Qt3DCore::QAttribute::defaultNormalAttributeName(), 3, 3, n);
    attribute(geometry, vertexBuffer, Qt3DCore::QAttribute::defaultColorAttributeName(), 4, 6, n);
    geometry->setBoundingVolumePositionAttribute(position);
    if (mesh.isLines() && as != DrawAs::Vertices) {
        QByteArray indices(reinterpret_cast<const char*>(mesh.segments.data()),
                           qsizetype(mesh.segments.size() * sizeof(mesh::Segment)));
        auto* indexBuffer = new Qt3DCore::QBuffer(geometry);
        indexBuffer->setData(indices);
        auto* index = new Qt3DCore::QAttribute(geometry);
        index->setAttributeType(Qt3DCore::QAttribute::IndexAttribute);
        index->setVertexBaseType(Qt3DCore::QAttribute::UnsignedInt);
        index->setBuffer(indexBuffer);
        index->setCount(uint(mesh.segments.size() * 2));
        geometry->addAttribute(index);
        renderer->setPrimitiveType(Qt3DRender::QGeometryRenderer::Lines);
        renderer->setVertexCount(int(mesh.segments.size() * 2));
    } else if (mesh.isPointCloud() || as == DrawAs::Vertices) {
        renderer->setPrimitiveType(Qt3DRender::QGeometryRenderer::Points);
        renderer->setVertexCount(int(n));
    } else if (as == DrawAs::Edges) {
        // Each edge once, though two triangles share it.
        std::vector<std::pair<quint32, quint32>> edges;
        edges.reserve(mesh.triangles.size() * 3);
        for (const mesh::Triangle& t : mesh.triangles)
            for (std::size_t k = 0; k < 3; ++k)
                if (t[k] != t[(k + 1) % 3])
                    edges.emplace_back(std::min(t[k], t[(k + 1) % 3]),
                                       std::max(t[k], t[(k + 1) % 3]));
        std::sort(edges.begin(), edges.end());
        edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
        std::vector<quint32> flat;
        flat.reserve(edges.size() * 2);
        for (const auto& [a, b] : edges)
            flat.insert(flat.end(), {a, b});
        QByteArray indices(reinterpret_cast<const char*>(flat.data()),
                           qsizetype(flat.size() * sizeof(quint32)));
        auto* indexBuffer = new Qt3DCore::QBuffer(geometry);
        indexBuffer->setData(indices);
        auto* index = new Qt3DCore::QAttribute(geometry);
        index->setAttributeType(Qt3DCore::QAttribute::IndexAttribute);
        index->setVertexBaseType(Qt3DCore::QAttribute::UnsignedInt);
        index->setBuffer(indexBuffer);
        index->setCount(uint(flat.size()));
        geometry->addAttribute(index);
        renderer->setPrimitiveType(Qt3DRender::QGeometryRenderer::Lines);
        renderer->setVertexCount(int(flat.size()));
    } else {
        QByteArray indices(qsizetype(mesh.triangles.size()) * 3 * qsizetype(sizeof(quint32)),
                           Qt::Uninitialized);
        std::memcpy(indices.data(), mesh.triangles.data(), std::size_t(indices.size()));
        auto* indexBuffer = new Qt3DCore::QBuffer(geometry);
        indexBuffer->setData(indices);
        auto* index = new Qt3DCore::QAttribute(geometry);
        index->setAttributeType(Qt3DCore::QAttribute::IndexAttribute);
        index->setVertexBaseType(Qt3DCore::QAttribute::UnsignedInt);
        index->setBuffer(indexBuffer);
        index->setCount(uint(mesh.triangles.size() * 3));
        geometry->addAttribute(index);
        renderer->setPrimitiveType(Qt3DRender::QGeometryRenderer::Triangles);
        renderer->setVertexCount(int(mesh.triangles.size() * 3));
    }
    renderer->setGeometry(geometry);
    return renderer;
}

Qt3DRender::QGeometryRenderer* makeBoxOutline(const std::array<double, 3>& lo,
                                              const std::array<double, 3>& hi,
                                              std::array<float, 4> colour,
                                              Qt3DCore::QNode* parent) {
    // Corner c has x from bit 0, y from bit 1, z from bit 2; as degenerate
    // triangles (a, b, b) each gives its edge a-b, and only the box's twelve
    // edges are listed.
    mesh::Mesh box;
    for (int c = 0; c < 8; ++c) {
        box.positions.push_back({float(c & 1 ? hi[0] : lo[0]), float(c & 2 ? hi[1] : lo[1]),
                                 float(c & 4 ? hi[2] : lo[2])});
        box.normals.push_back({0, 0, 0}); // unlit
    }
    for (std::uint32_t a = 0; a < 8; ++a)
        for (std::uint32_t bit : {1u, 2u, 4u})
            if (!(a & bit)) box.triangles.push_back({a, a | bit, a | bit});
    return makeGeometryRenderer(box, colour, parent, DrawAs::Edges);
}

} // namespace fl::viewer
