#include "mesh_geometry.h"

#include <Qt3DCore/QAttribute>
#include <Qt3DCore/QBuffer>
#include <Qt3DCore/QGeometry>

#include <algorithm>
#include <cstring>
#include <vector>

namespace fl::viewer {
namespace {

constexpr int kFloatsPerVertex = 12; // position 3, normal 3, colour 4, texture coordinate 2

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
    const bool textured = mesh.texCoords.size() == mesh.positions.size();
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
        if (textured)
            std::memcpy(v + 10, mesh.texCoords[i].data(), 2 * sizeof(float));
        else
            v[10] = v[11] = 0;
        v += kFloatsPerVertex;
    }
    auto* vertexBuffer = new Qt3DCore::QBuffer(geometry);
    vertexBuffer->setData(vertices);
    auto* position = attribute(geometry, vertexBuffer,
                               Qt3DCore::QAttribute::defaultPositionAttributeName(), 3, 0, n);
    attribute(geometry, vertexBuffer, Qt3DCore::QAttribute::defaultNormalAttributeName(), 3, 3, n);
    attribute(geometry, vertexBuffer, Qt3DCore::QAttribute::defaultColorAttributeName(), 4, 6, n);
    attribute(geometry, vertexBuffer, Qt3DCore::QAttribute::defaultTextureCoordinateAttributeName(),
              2, 10, n);
    geometry->setBoundingVolumePositionAttribute(position);
    // 32-bit indices of `count` vertices drawn as `type`.
    auto indexed = [&](const void* data, std::size_t count,
                       Qt3DRender::QGeometryRenderer::PrimitiveType type) {
        auto* indexBuffer = new Qt3DCore::QBuffer(geometry);
        indexBuffer->setData(
            QByteArray(static_cast<const char*>(data), qsizetype(count * sizeof(quint32))));
        auto* index = new Qt3DCore::QAttribute(geometry);
        index->setAttributeType(Qt3DCore::QAttribute::IndexAttribute);
        index->setVertexBaseType(Qt3DCore::QAttribute::UnsignedInt);
        index->setBuffer(indexBuffer);
        index->setCount(uint(count));
        geometry->addAttribute(index);
        renderer->setPrimitiveType(type);
        renderer->setVertexCount(int(count));
    };
    if (mesh.isLines() && as != DrawAs::Vertices) {
        indexed(mesh.segments.data(), mesh.segments.size() * 2,
                Qt3DRender::QGeometryRenderer::Lines);
    } else if (mesh.isPointCloud() || as == DrawAs::Vertices) {
        renderer->setPrimitiveType(Qt3DRender::QGeometryRenderer::Points);
        renderer->setVertexCount(int(n));
    } else if (as == DrawAs::Edges) {
        // Each edge once, though two triangles share it.
        std::vector<mesh::Segment> edges;
        edges.reserve(mesh.triangles.size() * 3);
        for (const mesh::Triangle& t : mesh.triangles)
            for (std::size_t k = 0; k < 3; ++k)
                if (t[k] != t[(k + 1) % 3])
                    edges.push_back(
                        {std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])});
        std::sort(edges.begin(), edges.end());
        edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
        indexed(edges.data(), edges.size() * 2, Qt3DRender::QGeometryRenderer::Lines);
    } else {
        indexed(mesh.triangles.data(), mesh.triangles.size() * 3,
                Qt3DRender::QGeometryRenderer::Triangles);
    }
    renderer->setGeometry(geometry);
    return renderer;
}

Qt3DRender::QGeometryRenderer* makeBoxOutline(const std::array<double, 3>& lo,
                                              const std::array<double, 3>& hi,
                                              std::array<float, 4> colour,
                                              Qt3DCore::QNode* parent) {
    // Corner c has x from bit 0, y from bit 1, z from bit 2; an edge joins
    // corners that differ in one bit.
    mesh::Mesh box;
    box.primitive = mesh::Primitive::Lines;
    for (int c = 0; c < 8; ++c) {
        box.positions.push_back({float(c & 1 ? hi[0] : lo[0]), float(c & 2 ? hi[1] : lo[1]),
                                 float(c & 4 ? hi[2] : lo[2])});
        box.normals.push_back({0, 0, 0}); // unlit
    }
    for (std::uint32_t a = 0; a < 8; ++a)
        for (std::uint32_t bit : {1u, 2u, 4u})
            if (!(a & bit)) box.segments.push_back({a, a | bit});
    return makeGeometryRenderer(box, colour, parent);
}

} // namespace fl::viewer
