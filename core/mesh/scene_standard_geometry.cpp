#include "scene_standard_geometry.h"

#include "scene/field_access.h"
#include "standard_geometry.h"

#include <cstdint>

namespace fl::mesh {
namespace {

using scene::Node;

std::vector<std::array<double, 3>> triples(const std::vector<double>& v) {
    std::vector<std::array<double, 3>> out;
    for (std::size_t i = 0; i + 2 < v.size(); i += 3)
        out.push_back({v[i], v[i + 1], v[i + 2]});
    return out;
}

std::vector<std::int64_t> indices(const Node& n, const char* field) {
    std::vector<std::int64_t> out;
    for (double d : scene::numbersField(n, field))
        out.push_back(std::int64_t(d));
    return out;
}

std::vector<std::array<double, 3>> pointsOf(const Node& n, const char* field, const char* values) {
    const Node* holder = scene::effectiveNode(scene::nodeField(n, field));
    return holder ? triples(scene::numbersField(*holder, values))
                  : std::vector<std::array<double, 3>>{};
}

// Color (RGB) or ColorRGBA.
std::vector<std::array<float, 4>> coloursOf(const Node& n) {
    std::vector<std::array<float, 4>> out;
    const Node* c = scene::effectiveNode(scene::nodeField(n, "color"));
    if (!c) return out;
    const auto v = scene::numbersField(*c, "color");
    const std::size_t stride = c->type == "ColorRGBA" ? 4 : 3;
    for (std::size_t i = 0; i + stride - 1 < v.size(); i += stride)
        out.push_back(
            {float(v[i]), float(v[i + 1]), float(v[i + 2]), stride == 4 ? float(v[i + 3]) : 1.0f});
    return out;
}

FaceSet commonFaceSet(const Node& n) {
    FaceSet f;
    f.points = pointsOf(n, "coord", "point");
    f.colours = coloursOf(n);
    f.colourPerVertex = scene::boolField(n, "colorPerVertex");
    f.normals = pointsOf(n, "normal", "vector");
    f.normalPerVertex = scene::boolField(n, "normalPerVertex");
    f.ccw = scene::boolField(n, "ccw");
    return f;
}

// Triangles written as a flat list of corners: -1 after every third.
std::vector<std::int64_t> inThrees(const std::vector<std::int64_t>& corners) {
    std::vector<std::int64_t> out;
    for (std::size_t i = 0; i + 2 < corners.size(); i += 3)
        out.insert(out.end(), {corners[i], corners[i + 1], corners[i + 2], -1});
    return out;
}

} // namespace

StandardGeometryResult standardGeometryMesh(const Node& g, int segments) {
    StandardGeometryResult r;
    const std::string& type = g.type;
    r.solid = !g.spec || !scene::findFieldSpec(*g.spec, "solid") || scene::boolField(g, "solid");
    auto use = [&](FaceSetResult&& f) {
        r.mesh = std::move(f.mesh);
        r.warnings = std::move(f.warnings);
    };
    if (type == "Box") {
        const auto s = scene::numbersField(g, "size");
        if (s.size() == 3) r.mesh = boxMesh({s[0], s[1], s[2]});
    } else if (type == "Sphere") {
        r.mesh = sphereMesh(scene::numberField(g, "radius", 0, 1), segments);
    } else if (type == "Cone") {
        r.mesh = coneMesh(scene::numberField(g, "bottomRadius", 0, 1),
                          scene::numberField(g, "height", 0, 2), scene::boolField(g, "side"),
                          scene::boolField(g, "bottom"), segments);
    } else if (type == "Cylinder") {
        r.mesh = cylinderMesh(scene::numberField(g, "radius", 0, 1),
                              scene::numberField(g, "height", 0, 2), scene::boolField(g, "side"),
                              scene::boolField(g, "top"), scene::boolField(g, "bottom"), segments);
    } else if (type == "IndexedFaceSet") {
        FaceSet f = commonFaceSet(g);
        f.coordIndex = indices(g, "coordIndex");
        f.colourIndex = indices(g, "colorIndex");
        f.normalIndex = indices(g, "normalIndex");
        f.creaseAngle = scene::numberField(g, "creaseAngle");
        use(faceSetMesh(f));
    } else if (type == "IndexedTriangleSet") {
        FaceSet f = commonFaceSet(g);
        f.coordIndex = inThrees(indices(g, "index"));
        use(faceSetMesh(f));
    } else if (type == "TriangleSet") {
        FaceSet f = commonFaceSet(g);
        std::vector<std::int64_t> all(f.points.size());
        for (std::size_t i = 0; i < all.size(); ++i)
            all[i] = std::int64_t(i);
        f.coordIndex = inThrees(all);
        use(faceSetMesh(f));
    } else if (type == "ElevationGrid") {
        ElevationGrid eg;
        eg.xDimension = int(scene::numberField(g, "xDimension"));
        eg.zDimension = int(scene::numberField(g, "zDimension"));
        eg.xSpacing = scene::numberField(g, "xSpacing", 0, 1);
        eg.zSpacing = scene::numberField(g, "zSpacing", 0, 1);
        eg.height = scene::numbersField(g, "height");
        eg.colours = coloursOf(g);
        eg.colourPerVertex = scene::boolField(g, "colorPerVertex");
        eg.ccw = scene::boolField(g, "ccw");
        eg.creaseAngle = scene::numberField(g, "creaseAngle");
        use(elevationGridMesh(eg));
    } else if (type == "Extrusion") {
        Extrusion ex;
        auto pairs = [&](const char* field) {
            std::vector<std::array<double, 2>> out;
            const auto v = scene::numbersField(g, field);
            for (std::size_t i = 0; i + 1 < v.size(); i += 2)
                out.push_back({v[i], v[i + 1]});
            return out;
        };
        ex.crossSection = pairs("crossSection");
        ex.spine = triples(scene::numbersField(g, "spine"));
        ex.scale = pairs("scale");
        if (ex.scale.empty()) ex.scale = {{1, 1}};
        ex.orientation.clear();
        const auto o = scene::numbersField(g, "orientation");
        for (std::size_t i = 0; i + 3 < o.size(); i += 4)
            ex.orientation.push_back({o[i], o[i + 1], o[i + 2], o[i + 3]});
        if (ex.orientation.empty()) ex.orientation = {{0, 0, 1, 0}};
        ex.beginCap = scene::boolField(g, "beginCap");
        ex.endCap = scene::boolField(g, "endCap");
        ex.creaseAngle = scene::numberField(g, "creaseAngle");
        use(extrusionMesh(ex));
    } else if (type == "IndexedLineSet") {
        FaceSet f = commonFaceSet(g);
        f.coordIndex = indices(g, "coordIndex");
        f.colourIndex = indices(g, "colorIndex");
        use(lineSetMesh(f));
    } else if (type == "LineSet") {
        FaceSet f = commonFaceSet(g);
        f.colourPerVertex = true;
        std::int64_t next = 0;
        for (double count : scene::numbersField(g, "vertexCount")) {
            for (std::int64_t k = 0; k < std::int64_t(count); ++k)
                f.coordIndex.push_back(next++);
            f.coordIndex.push_back(-1);
        }
        use(lineSetMesh(f));
    } else if (type == "PointSet") {
        r.mesh = pointSetMesh(pointsOf(g, "coord", "point"), coloursOf(g));
    } else {
        r.unsupported = type + " is not drawn yet";
    }
    return r;
}

} // namespace fl::mesh
