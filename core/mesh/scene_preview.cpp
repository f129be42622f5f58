#include "scene_preview.h"

#include "scene/node_building.h"
#include "scene/node_catalogue.h"
#include "scene/preview_marker.h"
#include "scene_meshing.h"

#include <charconv>
#include <cmath>

namespace fl::mesh {
namespace {

// The decimal a float prints as, read back as a double: the writer prints
// doubles exactly, and 0.1f as a double would print 0.10000000149011612.
double shortDecimal(float v) {
    char buf[32];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    double out = 0;
    std::from_chars(buf, end, out);
    return ec == std::errc() ? out : double(v);
}

// Normals and colours need no more than 4 digits to look the same.
double fourDigits(float v) {
    return std::round(double(v) * 1e4) / 1e4;
}

class PreviewBuilder {
  public:
    explicit PreviewBuilder(scene::Scene& scene) : scene_(scene) {}

    scene::Node* node(std::string_view type) { return scene::newCatalogueNode(scene_, type); }

    static void setNodes(scene::Node& n, std::string name, scene::FieldType type,
                         std::vector<scene::Node*> nodes) {
        scene::addNodesField(n, std::move(name), type, std::move(nodes));
    }

    static void setNumbers(scene::Node& n, std::string name, scene::FieldType type,
                           std::vector<double> numbers) {
        scene::addNumbersField(n, std::move(name), type, std::move(numbers));
    }

    // A Coordinate, Normal or Color node of the faces: the first three numbers
    // of each element, rounded by `round`.
    template <class Elements>
    void faceData(scene::Node& faces, const char* field, std::string_view type,
                  const char* valueField, scene::FieldType valueType, const Elements& elements,
                  double (*round)(float)) {
        scene::Node* data = node(type);
        std::vector<double> numbers;
        numbers.reserve(elements.size() * 3);
        for (const auto& e : elements)
            for (std::size_t k = 0; k < 3; ++k)
                numbers.push_back(round(e[k]));
        setNumbers(*data, valueField, valueType, std::move(numbers));
        setNodes(faces, field, scene::FieldType::SFNode, {data});
    }

    scene::Node* shape(const ShapeMesh& s) {
        const Mesh& m = s.mesh;
        scene::Node* geometry = nullptr;
        if (m.isPointCloud()) {
            geometry = node("PointSet");
        } else if (m.isLines()) {
            geometry = node("IndexedLineSet");
            std::vector<double> index;
            index.reserve(m.segments.size() * 3);
            for (const Segment& g : m.segments)
                index.insert(index.end(), {double(g[0]), double(g[1]), -1.0});
            setNumbers(*geometry, "coordIndex", scene::FieldType::MFInt32, std::move(index));
        } else {
            geometry = node("IndexedFaceSet");
            std::vector<double> index;
            index.reserve(m.triangles.size() * 4);
            for (const Triangle& t : m.triangles)
                index.insert(index.end(), {double(t[0]), double(t[1]), double(t[2]), -1.0});
            // Implicit surfaces are open and seen from both sides.
            setNumbers(*geometry, "solid", scene::FieldType::SFBool, {s.look.solid ? 1.0 : 0.0});
            setNumbers(*geometry, "coordIndex", scene::FieldType::MFInt32, std::move(index));
        }
        faceData(*geometry, "coord", "Coordinate", "point", scene::FieldType::MFVec3f, m.positions,
                 shortDecimal);
        // Points and lines are drawn unlit (X3D §11.4.9): no normals.
        if (!m.isPointCloud() && !m.isLines() && m.normals.size() == m.positions.size())
            faceData(*geometry, "normal", "Normal", "vector", scene::FieldType::MFVec3f, m.normals,
                     fourDigits);
        // Color (RGB), not ColorRGBA: VRML97 has only the former.
        if (m.colours.size() == m.positions.size())
            faceData(*geometry, "color", "Color", "color", scene::FieldType::MFColor, m.colours,
                     fourDigits);

        scene::Node* material = node("Material");
        setNumbers(*material, "diffuseColor", scene::FieldType::SFColor, {0.8, 0.8, 0.8});
        // Color has no alpha: a see-through shape (the fan's wind, the shark's
        // water) keeps its mean opacity as the material's transparency.
        if (m.colours.size() == m.positions.size() && !m.colours.empty()) {
            double opacity = 0;
            for (const auto& c : m.colours)
                opacity += c[3];
            opacity /= double(m.colours.size());
            if (opacity < 0.999)
                setNumbers(*material, "transparency", scene::FieldType::SFFloat,
                           {fourDigits(float(1.0 - opacity))});
        }
        setNumbers(*material, "specularColor", scene::FieldType::SFColor,
                   {fourDigits(s.look.specular[0]), fourDigits(s.look.specular[1]),
                    fourDigits(s.look.specular[2])});
        scene::Node* appearance = node("Appearance");
        setNodes(*appearance, "material", scene::FieldType::SFNode, {material});

        scene::Node* result = node("Shape");
        setNodes(*result, "appearance", scene::FieldType::SFNode, {appearance});
        setNodes(*result, "geometry", scene::FieldType::SFNode, {geometry});
        return result;
    }

  private:
    scene::Scene& scene_;
};

} // namespace

scene::Node* standardShapeNode(scene::Scene& into, const ShapeMesh& shape) {
    return PreviewBuilder(into).shape(shape);
}

PreviewResult addPreview(scene::Scene& scene, const PreviewOptions& options) {
    SceneMeshOptions so;
    so.mesh.resolution = options.resolution;
    so.mesh.threads = options.threads;
    so.useFileResolution = false;
    so.standardShapes = false; // other browsers draw those themselves
    so.placeInScene = true;
    SceneMeshes meshes = meshScene(scene, so);

    PreviewResult result;
    PreviewBuilder build(scene);
    std::vector<scene::Node*> shapes;
    for (const ShapeMesh& s : meshes.shapes) {
        for (const std::string& w : s.warnings)
            result.warnings.push_back(s.name + ": " + w);
        if (!s.error.empty()) result.warnings.push_back(s.name + ": " + s.error);
        // Triangles only: curves and point clouds are left to FunctionLab.
        if (!s.functionGeometry || s.mesh.primitive != Primitive::Triangles || s.mesh.empty())
            continue;
        shapes.push_back(build.shape(s));
        ++result.shapes;
        result.triangles += s.mesh.triangleCount();
    }
    if (shapes.empty()) return result;
    scene::Node* group = build.node("Group");
    group->defName = std::string(scene::kPreviewDefName);
    PreviewBuilder::setNodes(*group, "children", scene::FieldType::MFNode, std::move(shapes));
    scene.roots.push_back(group);
    return result;
}

} // namespace fl::mesh
