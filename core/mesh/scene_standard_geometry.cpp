#include "scene_standard_geometry.h"

#include "nurbs.h"
#include "scene/field_access.h"
#include "standard_geometry.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <string_view>
#include <utility>

namespace fl::mesh {
namespace {

using scene::FieldSource;
using scene::Node;

// The standard geometry node types drawn here, told apart by type: the
// catalogue's name is looked up once, at the edge, and every branch below
// switches on the kind (issue 14: a kind is a type, not a string).
enum class GeometryKind : std::uint8_t {
    Arc2D,
    ArcClose2D,
    Box,
    Circle2D,
    Cone,
    Cylinder,
    Disk2D,
    ElevationGrid,
    Extrusion,
    IndexedFaceSet,
    IndexedLineSet,
    IndexedQuadSet,
    IndexedTriangleFanSet,
    IndexedTriangleSet,
    IndexedTriangleStripSet,
    LineSet,
    NurbsCurve,
    NurbsPatchSurface,
    NurbsTrimmedSurface,
    PointSet,
    Polyline2D,
    Polypoint2D,
    QuadSet,
    Rectangle2D,
    Sphere,
    Text,
    TriangleFanSet,
    TriangleSet,
    TriangleSet2D,
    TriangleStripSet,
};

std::optional<GeometryKind> geometryKindOf(const Node& g) {
    static constexpr std::pair<std::string_view, GeometryKind> kKinds[] = {
        {"Arc2D", GeometryKind::Arc2D},
        {"ArcClose2D", GeometryKind::ArcClose2D},
        {"Box", GeometryKind::Box},
        {"Circle2D", GeometryKind::Circle2D},
        {"Cone", GeometryKind::Cone},
        {"Cylinder", GeometryKind::Cylinder},
        {"Disk2D", GeometryKind::Disk2D},
        {"ElevationGrid", GeometryKind::ElevationGrid},
        {"Extrusion", GeometryKind::Extrusion},
        {"IndexedFaceSet", GeometryKind::IndexedFaceSet},
        {"IndexedLineSet", GeometryKind::IndexedLineSet},
        {"IndexedQuadSet", GeometryKind::IndexedQuadSet},
        {"IndexedTriangleFanSet", GeometryKind::IndexedTriangleFanSet},
        {"IndexedTriangleSet", GeometryKind::IndexedTriangleSet},
        {"IndexedTriangleStripSet", GeometryKind::IndexedTriangleStripSet},
        {"LineSet", GeometryKind::LineSet},
        {"NurbsCurve", GeometryKind::NurbsCurve},
        {"NurbsPatchSurface", GeometryKind::NurbsPatchSurface},
        {"NurbsTrimmedSurface", GeometryKind::NurbsTrimmedSurface},
        {"PointSet", GeometryKind::PointSet},
        {"Polyline2D", GeometryKind::Polyline2D},
        {"Polypoint2D", GeometryKind::Polypoint2D},
        {"QuadSet", GeometryKind::QuadSet},
        {"Rectangle2D", GeometryKind::Rectangle2D},
        {"Sphere", GeometryKind::Sphere},
        {"Text", GeometryKind::Text},
        {"TriangleFanSet", GeometryKind::TriangleFanSet},
        {"TriangleSet", GeometryKind::TriangleSet},
        {"TriangleSet2D", GeometryKind::TriangleSet2D},
        {"TriangleStripSet", GeometryKind::TriangleStripSet},
    };
    if (!g.spec) return std::nullopt;
    for (const auto& [name, kind] : kKinds)
        if (name == g.spec->name) return kind;
    return std::nullopt;
}

std::vector<std::array<double, 3>> triples(const std::vector<double>& v) {
    std::vector<std::array<double, 3>> out;
    for (std::size_t i = 0; i + 2 < v.size(); i += 3)
        out.push_back({v[i], v[i + 1], v[i + 2]});
    return out;
}

std::vector<std::int64_t> indices(const FieldSource& fields, const Node& n, const char* field) {
    std::vector<std::int64_t> out;
    for (double d : fields.numbers(n, field))
        out.push_back(std::int64_t(d));
    return out;
}

std::vector<std::array<double, 3>> pointsOf(const FieldSource& fields, const Node& n,
                                            const char* field, const char* values) {
    const Node* holder = scene::effectiveNode(fields.node(n, field));
    return holder ? triples(fields.numbers(*holder, values)) : std::vector<std::array<double, 3>>{};
}

// Color (RGB) or ColorRGBA.
std::vector<std::array<float, 4>> coloursOf(const FieldSource& fields, const Node& n) {
    std::vector<std::array<float, 4>> out;
    const Node* c = scene::effectiveNode(fields.node(n, "color"));
    if (!c) return out;
    const auto v = fields.numbers(*c, "color");
    const std::size_t stride = c->kind() == scene::NodeKind::ColorRGBA ? 4 : 3;
    for (std::size_t i = 0; i + stride - 1 < v.size(); i += stride)
        out.push_back(
            {float(v[i]), float(v[i + 1]), float(v[i + 2]), stride == 4 ? float(v[i + 3]) : 1.0f});
    return out;
}

// An MFVec2f/MFVec2d as pairs.
std::vector<Point2> pairsOf(const std::vector<double>& v) {
    std::vector<Point2> out;
    for (std::size_t i = 0; i + 1 < v.size(); i += 2)
        out.push_back({v[i], v[i + 1]});
    return out;
}

// TextureCoordinate points; other texCoord nodes (generators, multi-texture)
// leave X3D's default mapping.
std::vector<Point2> texCoordsOf(const FieldSource& fields, const Node& n) {
    const Node* holder = scene::effectiveNode(fields.node(n, "texCoord"));
    if (!holder || holder->kind() != scene::NodeKind::TextureCoordinate) return {};
    return pairsOf(fields.numbers(*holder, "point"));
}

FaceSet commonFaceSet(const FieldSource& fields, const Node& n) {
    FaceSet f;
    f.texCoords = texCoordsOf(fields, n);
    f.points = pointsOf(fields, n, "coord", "point");
    f.colours = coloursOf(fields, n);
    f.colourPerVertex = fields.flag(n, "colorPerVertex");
    f.normals = pointsOf(fields, n, "normal", "vector");
    f.normalPerVertex = fields.flag(n, "normalPerVertex");
    f.ccw = fields.flag(n, "ccw");
    return f;
}

// Triangles written as a flat list of corners: -1 after every third.
// 0, 1, ..., n - 1: every point in order (the non-indexed sets).
std::vector<std::int64_t> sequence(std::size_t n) {
    std::vector<std::int64_t> out(n);
    for (std::size_t i = 0; i < n; ++i)
        out[i] = std::int64_t(i);
    return out;
}

std::vector<std::int64_t> inThrees(const std::vector<std::int64_t>& corners) {
    std::vector<std::int64_t> out;
    for (std::size_t i = 0; i + 2 < corners.size(); i += 3)
        out.insert(out.end(), {corners[i], corners[i + 1], corners[i + 2], -1});
    return out;
}

// Groups of consecutive vertices: `counts` for TriangleFanSet/StripSet, or
// an index list split at -1 for the indexed ones.
std::vector<std::vector<std::int64_t>> groupsByCount(const std::vector<double>& counts,
                                                     std::size_t vertices) {
    std::vector<std::vector<std::int64_t>> out;
    std::int64_t next = 0;
    for (double c : counts) {
        std::vector<std::int64_t> g;
        for (std::int64_t k = 0; k < std::int64_t(c) && std::size_t(next) < vertices; ++k)
            g.push_back(next++);
        out.push_back(std::move(g));
    }
    return out;
}

std::vector<std::vector<std::int64_t>> groupsByIndex(const std::vector<std::int64_t>& index) {
    std::vector<std::vector<std::int64_t>> out(1);
    for (std::int64_t i : index) {
        if (i < 0)
            out.emplace_back();
        else
            out.back().push_back(i);
    }
    return out;
}

// Fans (v0, vk, vk+1) and strips (every other triangle turned round so all
// keep the strip's winding) as triangles in coordIndex form.
std::vector<std::int64_t> fans(const std::vector<std::vector<std::int64_t>>& groups) {
    std::vector<std::int64_t> out;
    for (const auto& v : groups)
        for (std::size_t k = 1; k + 1 < v.size(); ++k)
            out.insert(out.end(), {v[0], v[k], v[k + 1], -1});
    return out;
}

std::vector<std::int64_t> strips(const std::vector<std::vector<std::int64_t>>& groups) {
    std::vector<std::int64_t> out;
    for (const auto& v : groups)
        for (std::size_t k = 0; k + 2 < v.size(); ++k) {
            if (k % 2 == 0)
                out.insert(out.end(), {v[k], v[k + 1], v[k + 2], -1});
            else
                out.insert(out.end(), {v[k + 1], v[k], v[k + 2], -1});
        }
    return out;
}

// X3D 11.4 (triangle, fan, strip and quad sets): without a Normal node and
// with normalPerVertex, a vertex's normal is the mean of the faces sharing
// it; else each face's own.
void smoothUnlessNormalsGiven(const FieldSource& fields, FaceSet& f, const Node& g) {
    if (f.normals.empty() && fields.flag(g, "normalPerVertex")) f.creaseAngle = std::numbers::pi;
}

// Fan and strip sets also ignore colorPerVertex: colours are per vertex.
FaceSetResult triangulatedMesh(const FieldSource& fields, FaceSet f,
                               std::vector<std::int64_t>&& coordIndex, const Node& g) {
    f.coordIndex = std::move(coordIndex);
    f.colourPerVertex = true;
    smoothUnlessNormalsGiven(fields, f, g);
    return faceSetMesh(f);
}

// Points of a 2D node (z = 0) and the circle helpers of Geometry2D.
std::vector<std::array<double, 3>> planePoints(const std::vector<double>& xy) {
    std::vector<std::array<double, 3>> out;
    for (std::size_t i = 0; i + 1 < xy.size(); i += 2)
        out.push_back({xy[i], xy[i + 1], 0});
    return out;
}

std::vector<std::array<double, 3>> arcPoints(double radius, double start, double end,
                                             int segments) {
    // X3D: an arc from startAngle counter-clockwise to endAngle; equal angles
    // make a full circle.
    // X3D keeps the angles within [-2 pi, 2 pi]; any others are reduced.
    const double turn = 2 * 3.14159265358979323846;
    std::vector<std::array<double, 3>> out;
    if (!std::isfinite(radius) || !std::isfinite(start) || !std::isfinite(end)) return out;
    double sweep = std::fmod(end - start, turn);
    if (sweep <= 0) sweep += turn;
    if (std::abs(end - start) < 1e-12) sweep = turn;
    start = std::fmod(start, turn);
    const int n = std::clamp(int(std::ceil(segments * sweep / turn)), 1, std::max(1, segments));
    for (int k = 0; k <= n; ++k) {
        const double a = start + sweep * k / n;
        out.push_back({radius * std::cos(a), radius * std::sin(a), 0});
    }
    return out;
}

FaceSet polyline(std::vector<std::array<double, 3>> points) {
    FaceSet f;
    f.points = std::move(points);
    f.coordIndex = sequence(f.points.size());
    return f;
}

FaceSetResult geometry2DMesh(const FieldSource& fields, const Node& g, GeometryKind kind,
                             int segments) {
    if (kind == GeometryKind::Rectangle2D) {
        const double w = fields.number(g, "size", 0, 2) / 2;
        const double h = fields.number(g, "size", 1, 2) / 2;
        FaceSet f;
        f.points = {{-w, -h, 0}, {w, -h, 0}, {w, h, 0}, {-w, h, 0}};
        f.coordIndex = {0, 1, 2, 3};
        return faceSetMesh(f);
    }
    if (kind == GeometryKind::TriangleSet2D) {
        FaceSet f;
        f.points = planePoints(fields.numbers(g, "vertices"));
        f.coordIndex = inThrees(sequence(f.points.size()));
        return faceSetMesh(f);
    }
    if (kind == GeometryKind::Disk2D) {
        const double inner = fields.number(g, "innerRadius", 0, 0);
        const double outer = fields.number(g, "outerRadius", 0, 1);
        const auto o = arcPoints(outer, 0, 0, segments);
        if (inner == outer) return lineSetMesh(polyline(o)); // X3D: a circle
        FaceSet f;
        f.points = o;
        const std::int64_t n = std::int64_t(o.size()) - 1; // last repeats the first
        if (inner <= 0) {
            f.coordIndex = sequence(std::size_t(n));
        } else {
            const auto in = arcPoints(inner, 0, 0, segments);
            f.points.insert(f.points.end(), in.begin(), in.end());
            const std::int64_t base = n + 1;
            for (std::int64_t k = 0; k < n; ++k)
                f.coordIndex.insert(f.coordIndex.end(), {k, k + 1, base + k + 1, base + k, -1});
        }
        return faceSetMesh(f);
    }
    if (kind == GeometryKind::ArcClose2D) {
        auto arc = arcPoints(fields.number(g, "radius", 0, 1), fields.number(g, "startAngle"),
                             fields.number(g, "endAngle", 0, 1.570796), segments);
        FaceSet f;
        const bool pie = fields.string(g, "closureType") != "CHORD";
        if (pie) f.points.push_back({0, 0, 0});
        f.points.insert(f.points.end(), arc.begin(), arc.end());
        f.coordIndex = sequence(f.points.size());
        return faceSetMesh(f);
    }
    if (kind == GeometryKind::Arc2D)
        return lineSetMesh(
            polyline(arcPoints(fields.number(g, "radius", 0, 1), fields.number(g, "startAngle"),
                               fields.number(g, "endAngle", 0, 1.570796), segments)));
    if (kind == GeometryKind::Circle2D)
        return lineSetMesh(polyline(arcPoints(fields.number(g, "radius", 0, 1), 0, 0, segments)));
    // Polyline2D
    return lineSetMesh(polyline(planePoints(fields.numbers(g, "lineSegments"))));
}

NurbsSurface nurbsSurfaceOf(const FieldSource& fields, const Node& g,
                            std::vector<std::string>& warnings) {
    NurbsSurface s;
    s.points = pointsOf(fields, g, "controlPoint", "point");
    const int uDim = int(fields.number(g, "uDimension"));
    const int vDim = int(fields.number(g, "vDimension"));
    if (uDim < 2 || vDim < 2 || std::size_t(uDim) * std::size_t(vDim) != s.points.size()) {
        warnings.push_back("uDimension " + std::to_string(uDim) + " x vDimension " +
                           std::to_string(vDim) + " does not match the " +
                           std::to_string(s.points.size()) +
                           " control points (each dimension needs at least 2); nothing drawn");
        return {};
    }
    s.u = makeNurbsBasis(int(fields.number(g, "uOrder", 0, 3)), uDim, fields.numbers(g, "uKnot"),
                         "u", warnings);
    s.v = makeNurbsBasis(int(fields.number(g, "vOrder", 0, 3)), vDim, fields.numbers(g, "vKnot"),
                         "v", warnings);
    s.weights = nurbsWeights(fields.numbers(g, "weight"), s.points.size(), warnings);
    return s;
}

// The trimming contours of a NurbsTrimmedSurface: each Contour2D's pieces
// (ContourPolyline2D, NurbsCurve2D) joined end to end into one closed loop.
std::vector<Contour2> trimmingContours(const FieldSource& fields, const Node& g,
                                       std::vector<std::string>& warnings) {
    std::vector<Contour2> out;
    for (const Node* raw : fields.nodes(g, "trimmingContour")) {
        const Node* contour = scene::effectiveNode(raw);
        if (!contour) continue;
        Contour2 loop;
        for (const Node* rawPiece : fields.nodes(*contour, "children")) {
            const Node* piece = scene::effectiveNode(rawPiece);
            if (!piece) continue;
            const auto points = pairsOf(fields.numbers(*piece, "controlPoint"));
            std::vector<Point2> along;
            if (piece->kind() == scene::NodeKind::NurbsCurve2D)
                along = nurbsCurve2DPoints(
                    int(fields.number(*piece, "order", 0, 3)), points,
                    fields.numbers(*piece, "weight"), fields.numbers(*piece, "knot"),
                    nurbsSegments(int(fields.number(*piece, "tessellation")), int(points.size())),
                    warnings);
            else
                along = points;
            for (const Point2& p : along)
                if (loop.empty() || loop.back() != p) loop.push_back(p);
        }
        if (loop.size() >= 3) out.push_back(std::move(loop));
    }
    return out;
}

FaceSetResult nurbsMesh(const FieldSource& fields, const Node& g) {
    FaceSetResult r;
    const std::optional<GeometryKind> kind = geometryKindOf(g);
    if (kind == GeometryKind::NurbsCurve) {
        NurbsCurve c;
        c.points = pointsOf(fields, g, "controlPoint", "point");
        c.basis = makeNurbsBasis(int(fields.number(g, "order", 0, 3)), int(c.points.size()),
                                 fields.numbers(g, "knot"), "", r.warnings);
        if (c.basis.count < 2) return r;
        c.weights = nurbsWeights(fields.numbers(g, "weight"), c.points.size(), r.warnings);
        r.mesh = nurbsCurveMesh(
            c, nurbsSegments(int(fields.number(g, "tessellation")), int(c.points.size())));
        return r;
    }
    const NurbsSurface s = nurbsSurfaceOf(fields, g, r.warnings);
    if (s.points.empty()) return r;
    const std::vector<Contour2> trim = kind == GeometryKind::NurbsTrimmedSurface
                                           ? trimmingContours(fields, g, r.warnings)
                                           : std::vector<Contour2>{};
    int uSegments = nurbsSegments(int(fields.number(g, "uTessellation")), s.u.count);
    int vSegments = nurbsSegments(int(fields.number(g, "vTessellation")), s.v.count);
    limitNurbsCells(uSegments, vSegments, r.warnings);
    r.mesh = nurbsSurfaceMesh(s, uSegments, vSegments, trim, &r.warnings);
    return r;
}

// Text and its FontStyle (defaults from the catalogue when there is none).
TextLayout textLayoutOf(const FieldSource& fields, const Node& g) {
    TextLayout t;
    t.lines = fields.strings(g, "string");
    t.length = fields.numbers(g, "length");
    t.maxExtent = fields.number(g, "maxExtent");
    const Node* style = scene::effectiveNode(fields.node(g, "fontStyle"));
    if (!style) return t;
    const auto family = fields.strings(*style, "family");
    if (!family.empty()) t.font.family = family;
    t.font.style = fields.string(*style, "style");
    t.font.size = fields.number(*style, "size", 0, 1);
    t.spacing = fields.number(*style, "spacing", 0, 1);
    const auto justify = fields.strings(*style, "justify");
    if (!justify.empty()) t.justifyMajor = justify[0];
    if (justify.size() > 1) t.justifyMinor = justify[1];
    t.horizontal = fields.flag(*style, "horizontal");
    t.leftToRight = fields.flag(*style, "leftToRight");
    t.topToBottom = fields.flag(*style, "topToBottom");
    return t;
}

bool isGeometry2D(std::optional<GeometryKind> kind) {
    return kind == GeometryKind::Rectangle2D || kind == GeometryKind::TriangleSet2D ||
           kind == GeometryKind::Disk2D || kind == GeometryKind::ArcClose2D ||
           kind == GeometryKind::Arc2D || kind == GeometryKind::Circle2D ||
           kind == GeometryKind::Polyline2D;
}

} // namespace

bool standardGeometryIsSolid(const Node& g, const FieldSource& fields) {
    return !g.spec || !scene::findFieldSpec(*g.spec, "solid") || fields.flag(g, "solid");
}

StandardGeometryResult standardGeometryMesh(const Node& g, int segments, const TextOutliner& text,
                                            const FieldSource& fields) {
    StandardGeometryResult r;
    const std::optional<GeometryKind> kind = geometryKindOf(g);
    r.solid = standardGeometryIsSolid(g, fields);
    auto use = [&](FaceSetResult&& f) {
        r.mesh = std::move(f.mesh);
        r.warnings = std::move(f.warnings);
    };
    if (kind == GeometryKind::Box) {
        const auto s = fields.numbers(g, "size");
        if (s.size() == 3) r.mesh = boxMesh({s[0], s[1], s[2]});
    } else if (kind == GeometryKind::Sphere) {
        r.mesh = sphereMesh(fields.number(g, "radius", 0, 1), segments);
    } else if (kind == GeometryKind::Cone) {
        r.mesh = coneMesh(fields.number(g, "bottomRadius", 0, 1), fields.number(g, "height", 0, 2),
                          fields.flag(g, "side"), fields.flag(g, "bottom"), segments);
    } else if (kind == GeometryKind::Cylinder) {
        r.mesh = cylinderMesh(fields.number(g, "radius", 0, 1), fields.number(g, "height", 0, 2),
                              fields.flag(g, "side"), fields.flag(g, "top"),
                              fields.flag(g, "bottom"), segments);
    } else if (kind == GeometryKind::IndexedFaceSet) {
        FaceSet f = commonFaceSet(fields, g);
        f.coordIndex = indices(fields, g, "coordIndex");
        f.colourIndex = indices(fields, g, "colorIndex");
        f.normalIndex = indices(fields, g, "normalIndex");
        f.texCoordIndex = indices(fields, g, "texCoordIndex");
        f.creaseAngle = fields.number(g, "creaseAngle");
        use(faceSetMesh(f));
    } else if (kind == GeometryKind::IndexedTriangleSet) {
        FaceSet f = commonFaceSet(fields, g);
        f.coordIndex = inThrees(indices(fields, g, "index"));
        smoothUnlessNormalsGiven(fields, f, g);
        use(faceSetMesh(f));
    } else if (kind == GeometryKind::TriangleSet) {
        FaceSet f = commonFaceSet(fields, g);
        f.coordIndex = inThrees(sequence(f.points.size()));
        use(faceSetMesh(f));
    } else if (kind == GeometryKind::ElevationGrid) {
        ElevationGrid eg;
        eg.xDimension = int(fields.number(g, "xDimension"));
        eg.zDimension = int(fields.number(g, "zDimension"));
        eg.xSpacing = fields.number(g, "xSpacing", 0, 1);
        eg.zSpacing = fields.number(g, "zSpacing", 0, 1);
        eg.height = fields.numbers(g, "height");
        eg.colours = coloursOf(fields, g);
        eg.colourPerVertex = fields.flag(g, "colorPerVertex");
        eg.ccw = fields.flag(g, "ccw");
        eg.creaseAngle = fields.number(g, "creaseAngle");
        eg.texCoords = texCoordsOf(fields, g);
        use(elevationGridMesh(eg));
    } else if (kind == GeometryKind::Extrusion) {
        Extrusion ex;
        ex.crossSection = pairsOf(fields.numbers(g, "crossSection"));
        ex.spine = triples(fields.numbers(g, "spine"));
        ex.scale = pairsOf(fields.numbers(g, "scale"));
        if (ex.scale.empty()) ex.scale = {{1, 1}};
        ex.orientation.clear();
        const auto o = fields.numbers(g, "orientation");
        for (std::size_t i = 0; i + 3 < o.size(); i += 4)
            ex.orientation.push_back({o[i], o[i + 1], o[i + 2], o[i + 3]});
        if (ex.orientation.empty()) ex.orientation = {{0, 0, 1, 0}};
        ex.beginCap = fields.flag(g, "beginCap");
        ex.endCap = fields.flag(g, "endCap");
        ex.creaseAngle = fields.number(g, "creaseAngle");
        use(extrusionMesh(ex));
    } else if (kind == GeometryKind::IndexedLineSet) {
        FaceSet f = commonFaceSet(fields, g);
        f.coordIndex = indices(fields, g, "coordIndex");
        f.colourIndex = indices(fields, g, "colorIndex");
        use(lineSetMesh(f));
    } else if (kind == GeometryKind::LineSet) {
        FaceSet f = commonFaceSet(fields, g);
        f.colourPerVertex = true;
        std::int64_t next = 0;
        const auto points = std::int64_t(f.points.size());
        for (double count : fields.numbers(g, "vertexCount")) {
            for (std::int64_t k = 0; k < std::int64_t(count) && next < points; ++k)
                f.coordIndex.push_back(next++);
            f.coordIndex.push_back(-1);
            if (next >= points) break;
        }
        use(lineSetMesh(f));
    } else if (kind == GeometryKind::TriangleFanSet || kind == GeometryKind::TriangleStripSet) {
        FaceSet f = commonFaceSet(fields, g);
        const auto groups = kind == GeometryKind::TriangleFanSet
                                ? groupsByCount(fields.numbers(g, "fanCount"), f.points.size())
                                : groupsByCount(fields.numbers(g, "stripCount"), f.points.size());
        use(triangulatedMesh(fields, std::move(f),
                             kind == GeometryKind::TriangleFanSet ? fans(groups) : strips(groups),
                             g));
    } else if (kind == GeometryKind::IndexedTriangleFanSet ||
               kind == GeometryKind::IndexedTriangleStripSet) {
        FaceSet f = commonFaceSet(fields, g);
        const auto groups = groupsByIndex(indices(fields, g, "index"));
        use(triangulatedMesh(
            fields, std::move(f),
            kind == GeometryKind::IndexedTriangleFanSet ? fans(groups) : strips(groups), g));
    } else if (kind == GeometryKind::QuadSet || kind == GeometryKind::IndexedQuadSet) {
        FaceSet f = commonFaceSet(fields, g);
        const std::vector<std::int64_t> corners =
            kind == GeometryKind::QuadSet ? sequence(f.points.size()) : indices(fields, g, "index");
        for (std::size_t i = 0; i + 3 < corners.size(); i += 4)
            f.coordIndex.insert(f.coordIndex.end(),
                                {corners[i], corners[i + 1], corners[i + 2], corners[i + 3], -1});
        smoothUnlessNormalsGiven(fields, f, g);
        use(faceSetMesh(f));
    } else if (isGeometry2D(kind)) {
        use(geometry2DMesh(fields, g, *kind, segments));
    } else if (kind == GeometryKind::Polypoint2D) {
        r.mesh = pointSetMesh(planePoints(fields.numbers(g, "point")), {});
    } else if (kind == GeometryKind::NurbsCurve || kind == GeometryKind::NurbsPatchSurface ||
               kind == GeometryKind::NurbsTrimmedSurface) {
        use(nurbsMesh(fields, g));
    } else if (kind == GeometryKind::Text) {
        if (!text) {
            r.unsupported = "Text is not drawn without a font source (the window, `functionlab "
                            "render` and `functionlab mesh` have one)";
            return r;
        }
        r.mesh = textMesh(textLayoutOf(fields, g), text, &r.warnings);
    } else if (kind == GeometryKind::PointSet) {
        r.mesh = pointSetMesh(pointsOf(fields, g, "coord", "point"), coloursOf(fields, g));
    } else {
        r.unsupported = g.type + " is not drawn yet";
    }
    // Coordinates beyond float's range (about 3.4e38) become infinite on the
    // way to the GPU and the exports: such a shape is not drawn.
    for (const Vec3f& p : r.mesh.positions)
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
            r.warnings.push_back("coordinates too large or not numbers (beyond about 3.4e38); "
                                 "not drawn");
            r.mesh = Mesh{};
            break;
        }
    return r;
}

} // namespace fl::mesh
