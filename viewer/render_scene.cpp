#include "render_scene.h"

#include "mesh/standard_geometry.h"
#include "mesh_geometry.h"
#include "surface_material.h"

#include <QMatrix4x4>
#include <Qt3DCore/QTransform>

#include <cmath>

namespace fl::viewer {
namespace {

constexpr int kMaxLights = 8; // as in shaders/surface.frag

QMatrix4x4 toMatrix(const field::Matrix4& m) {
    // Column-major in, QMatrix4x4's constructor wants rows.
    return QMatrix4x4(float(m[0]), float(m[4]), float(m[8]), float(m[12]), float(m[1]), float(m[5]),
                      float(m[9]), float(m[13]), float(m[2]), float(m[6]), float(m[10]),
                      float(m[14]), float(m[3]), float(m[7]), float(m[11]), float(m[15]));
}

} // namespace

void Bounds::add(const QVector3D& p) {
    for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], p[k]);
        hi[k] = std::max(hi[k], p[k]);
    }
}

RenderScene::RenderScene(Qt3DCore::QEntity* root) : root_(root), shader_(makeSurfaceShader(root)) {
    setLights({});
    setHeadlight(true);
    setClipPlane(std::nullopt);
}

Qt3DRender::QParameter* RenderScene::parameter(const char* name, const QVariant& value) {
    const QString key = QString::fromLatin1(name);
    for (auto* p : frame_)
        if (p->name() == key) {
            p->setValue(value);
            return p;
        }
    auto* p = new Qt3DRender::QParameter(key, value, root_);
    frame_.push_back(p);
    return p;
}

std::size_t RenderScene::shapeCount() const {
    std::size_t n = 0;
    for (const Drawn& d : drawn_)
        n += d.entity ? 1 : 0;
    return n;
}

void RenderScene::setDrawAs(DrawAs as) {
    drawAs_ = as;
    rebuild();
}

void RenderScene::setShowDomains(bool on) {
    showDomains_ = on;
    rebuild();
}

void RenderScene::rebuild() {
    if (!last_) return;
    auto meshes = last_;
    clearShapes();
    setMeshes(meshes);
}

void RenderScene::clearShapes() {
    for (Drawn& d : drawn_) {
        delete d.entity;
        delete d.outline;
    }
    drawn_.clear();
}

// Whether two meshes draw the same (then only the placement may differ).
static bool sameMesh(const mesh::Mesh& a, const mesh::Mesh& b) {
    return a.primitive == b.primitive && a.positions == b.positions && a.normals == b.normals &&
           a.colours == b.colours && a.triangles == b.triangles && a.texCoords == b.texCoords;
}

void RenderScene::setMeshes(std::shared_ptr<const mesh::SceneMeshes> shared) {
    const std::shared_ptr<const mesh::SceneMeshes> previous = last_;
    last_ = std::move(shared);
    const mesh::SceneMeshes& meshes = *last_;
    // The same shapes as before (a new moment of one scene): each keeps its
    // entity if its mesh did not change, and only its matrix moves.
    bool sameShapes = previous && drawn_.size() == meshes.shapes.size();
    for (std::size_t i = 0; sameShapes && i < drawn_.size(); ++i)
        sameShapes = drawn_[i].shape == meshes.shapes[i].shape;
    if (!sameShapes) clearShapes();
    drawn_.resize(meshes.shapes.size());
    bounds_ = {};
    for (std::size_t i = 0; i < meshes.shapes.size(); ++i) {
        const mesh::ShapeMesh& shape = meshes.shapes[i];
        Drawn& d = drawn_[i];
        const QMatrix4x4 placement = toMatrix(shape.placement);
        const bool drawable = !shape.mesh.empty() && shape.error.empty();
        const bool keep = sameShapes && d.entity && drawable &&
                          sameMesh(previous->shapes[i].mesh, shape.mesh) &&
                          previous->shapes[i].look == shape.look;
        if (!keep) {
            delete d.entity;
            delete d.outline;
            d = Drawn{};
            d.shape = shape.shape;
            if (drawable) {
                d.entity = makeEntity(shape);
                ++rebuilt_;
            }
            if (showDomains_ && shape.geometry && shape.error.empty())
                d.outline = makeOutline(shape);
        }
        for (Qt3DCore::QEntity* e : {d.entity, d.outline})
            if (e)
                for (auto* t : e->componentsOfType<Qt3DCore::QTransform>())
                    t->setMatrix(placement);
        if (drawable)
            for (const mesh::Vec3f& p : shape.mesh.positions)
                bounds_.add(placement.map(QVector3D(p[0], p[1], p[2])));
    }
    setLights(meshes.view.lights);
    setHeadlight(!meshes.view.hasNavigation || meshes.view.navigation.headlight);
}

void RenderScene::setMarker(std::optional<QVector3D> at) {
    delete marker_;
    marker_ = nullptr;
    markerAt_ = at;
    if (!at) return;
    // Magenta, unlit, about 1.5% of the scene across: seen on any surface
    // colour, half sunk into the surface it marks.
    const float radius = 0.015f * bounds_.radius();
    marker_ = new Qt3DCore::QEntity(root_);
    marker_->setObjectName(QStringLiteral("picked point"));
    marker_->addComponent(makeGeometryRenderer(mesh::sphereMesh(radius, 16), {1, 0.1f, 0.8f, 1},
                                               marker_, DrawAs::Faces));
    mesh::SurfaceLook plain;
    plain.lit = false;
    marker_->addComponent(new SurfaceMaterial(plain, {}, shader_, marker_));
    auto* transform = new Qt3DCore::QTransform(marker_);
    transform->setTranslation(*at);
    marker_->addComponent(transform);
}

Qt3DCore::QEntity* RenderScene::makeOutline(const mesh::ShapeMesh& shape) {
    auto* outline = new Qt3DCore::QEntity(root_);
    outline->addComponent(
        makeBoxOutline(shape.domain.lo, shape.domain.hi, {1, 0.85f, 0.2f, 1}, outline));
    mesh::SurfaceLook plain;
    plain.lit = false;
    outline->addComponent(new SurfaceMaterial(plain, {}, shader_, outline));
    outline->addComponent(new Qt3DCore::QTransform(outline));
    return outline;
}

Qt3DCore::QEntity* RenderScene::makeEntity(const mesh::ShapeMesh& shape) {
    auto* entity = new Qt3DCore::QEntity(root_);
    entity->setObjectName(QString::fromStdString(shape.name));
    // No Material: X3D draws white unlit; an FShape without one, lit grey.
    const std::array<float, 4> colour = shape.look.lit ? std::array<float, 4>{0.8f, 0.8f, 0.8f, 1}
                                                       : std::array<float, 4>{1, 1, 1, 1};
    entity->addComponent(makeGeometryRenderer(shape.mesh, colour, entity, drawAs_));
    SurfaceOptions options;
    if (shape.look.texture) options.texture = images_.get(*shape.look.texture);
    options.transparent =
        hasTransparency(shape.mesh, colour) || (options.texture && options.texture->seeThrough);
    options.points = shape.mesh.isPointCloud() || drawAs_ == DrawAs::Vertices;
    options.bothSides = cutOpen_;
    entity->addComponent(new SurfaceMaterial(shape.look, options, shader_, entity));
    entity->addComponent(new Qt3DCore::QTransform(entity));
    return entity;
}

void RenderScene::setLights(const std::vector<mesh::ViewLight>& lights) {
    QVariantList position, colour, attenuation, spot;
    int count = 0;
    for (const mesh::ViewLight& l : lights) {
        if (count == kMaxLights) break;
        ++count;
        const bool directional = l.kind == mesh::ViewLight::Kind::Directional;
        const auto& p = directional ? l.direction : l.location;
        position << QVector4D(float(p[0]), float(p[1]), float(p[2]), directional ? 0.0f : 1.0f);
        colour << QVector4D(l.colour[0] * l.intensity, l.colour[1] * l.intensity,
                            l.colour[2] * l.intensity, l.ambientIntensity);
        attenuation << QVector4D(l.attenuation[0], l.attenuation[1], l.attenuation[2],
                                 float(l.radius));
        const bool isSpot = l.kind == mesh::ViewLight::Kind::Spot;
        spot << QVector4D(float(l.direction[0]), float(l.direction[1]), float(l.direction[2]),
                          isSpot ? float(std::cos(l.cutOffAngle)) : -2.0f);
    }
    // Arrays are always full length: unused entries are never read.
    while (position.size() < kMaxLights) {
        position << QVector4D();
        colour << QVector4D();
        attenuation << QVector4D();
        spot << QVector4D(0, 0, -1, -2);
    }
    parameter("lightCount", count);
    parameter("lightPosition[0]", position);
    parameter("lightColour[0]", colour);
    parameter("lightAttenuation[0]", attenuation);
    parameter("lightSpot[0]", spot);
}

void RenderScene::setHeadlight(bool on) {
    parameter("headlight", on ? 1 : 0);
}

void RenderScene::setClipPlane(std::optional<QVector4D> plane) {
    // Cut open, a solid shows its inside: its back faces are drawn too.
    if (plane.has_value() != cutOpen_) {
        cutOpen_ = plane.has_value();
        rebuild();
    }
    parameter("clipOn", plane ? 1 : 0);
    parameter("clipPlane", plane.value_or(QVector4D(0, 0, 0, 1)));
}

} // namespace fl::viewer

namespace fl::viewer {

namespace {

// A unit arrow along +y from the origin: a shaft and a head.
mesh::Mesh unitArrow() {
    mesh::Mesh shaft = mesh::cylinderMesh(0.03, 0.8, true, true, true, 12);
    const mesh::Mesh head = mesh::coneMesh(0.08, 0.2, true, true, 12);
    for (auto& p : shaft.positions)
        p[1] += 0.4f;
    const auto base = std::uint32_t(shaft.positions.size());
    for (auto p : head.positions) {
        p[1] += 0.9f;
        shaft.positions.push_back(p);
    }
    shaft.normals.insert(shaft.normals.end(), head.normals.begin(), head.normals.end());
    for (auto t : head.triangles)
        shaft.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    shaft.texCoords.clear();
    shaft.colours.clear();
    return shaft;
}

} // namespace

void RenderScene::setTouch(std::optional<Touch> touch) {
    touchAt_ = touch;
    if (!toolMark_) {
        const float r = 0.02f * std::max(bounds_.radius(), 1e-3f);
        mesh::SurfaceLook plain;
        plain.lit = false;
        auto make = [&](const mesh::Mesh& m, std::array<float, 4> colour, const char* name,
                        Qt3DCore::QTransform*& place) {
            auto* e = new Qt3DCore::QEntity(root_);
            e->setObjectName(QString::fromLatin1(name));
            e->addComponent(makeGeometryRenderer(m, colour, e, DrawAs::Faces));
            e->addComponent(new SurfaceMaterial(plain, {}, shader_, e));
            place = new Qt3DCore::QTransform(e);
            e->addComponent(place);
            return e;
        };
        toolMark_ = make(mesh::sphereMesh(r, 12), {0.2f, 0.45f, 1, 1}, "haptic tool", toolPlace_);
        proxyMark_ = make(mesh::sphereMesh(0.8 * r, 12), {0.2f, 0.85f, 0.3f, 1}, "haptic proxy",
                          proxyPlace_);
        arrowMark_ = make(unitArrow(), {1, 0.55f, 0.1f, 1}, "haptic force", arrowPlace_);
    }
    toolMark_->setEnabled(touch.has_value());
    proxyMark_->setEnabled(touch.has_value());
    if (!touch) {
        arrowMark_->setEnabled(false);
        return;
    }
    toolPlace_->setTranslation(touch->tool);
    proxyPlace_->setTranslation(touch->proxy);
    const float size = touch->force.length();
    arrowMark_->setEnabled(size > 1e-6f);
    if (size <= 1e-6f) return;
    // From a twentieth of the scene for the least force to a quarter at the
    // device's maximum: any force is seen, a larger one is longer.
    const float share = std::min(size / std::max(touch->maxForce, 1e-6f), 1.0f);
    const float length = std::max(bounds_.radius(), 1e-3f) * (0.1f + 0.4f * share);
    arrowPlace_->setTranslation(touch->proxy);
    arrowPlace_->setRotation(QQuaternion::rotationTo(QVector3D(0, 1, 0), touch->force / size));
    arrowPlace_->setScale3D(QVector3D(length, length, length));
}

} // namespace fl::viewer
