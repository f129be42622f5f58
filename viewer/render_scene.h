#pragma once
// The Qt3D entities of a meshed scene: one entity per shape (its mesh, its
// placement as a transform, its material), and the scene-wide shader inputs
// (lights, headlight, clip plane) as parameters for the frame graph.
#include "mesh/scene_meshing.h"
#include "mesh_geometry.h"
#include "texture_image.h"

#include <QVector3D>
#include <QVector4D>
#include <Qt3DCore/QEntity>
#include <Qt3DRender/QParameter>
#include <Qt3DRender/QShaderProgram>

#include <memory>
#include <vector>

namespace Qt3DCore {
class QTransform;
}

namespace fl::viewer {

struct Bounds {
    QVector3D lo{1e30f, 1e30f, 1e30f}, hi{-1e30f, -1e30f, -1e30f};
    bool empty() const { return !(lo.x() <= hi.x()); }
    QVector3D centre() const { return (lo + hi) / 2; }
    float radius() const { return empty() ? 1.0f : (hi - lo).length() / 2; }
    void add(const QVector3D& p);
};

class RenderScene {
  public:
    // Entities are made under `root`, which the caller owns (or an aspect engine).
    explicit RenderScene(Qt3DCore::QEntity* root);

    // Replaces every shape with the meshes' (kept in their own coordinates
    // with their placement, or already placed in the scene: both work).
    void setMeshes(std::shared_ptr<const mesh::SceneMeshes> meshes);
    const Bounds& bounds() const { return bounds_; }
    std::size_t shapeCount() const;
    // Entities made since the start: a new moment whose meshes did not
    // change (a clock turning its hands) makes none, it only moves matrices.
    std::size_t entitiesMade() const { return rebuilt_; }

    // Parameters every pass reads: attach them to the frame graph's technique filter.
    const std::vector<Qt3DRender::QParameter*>& frameParameters() const { return frame_; }
    void setHeadlight(bool on);
    // Shaded faces, wireframe edges or vertices as points (re-made from the last meshes).
    void setDrawAs(DrawAs as);
    DrawAs drawAs() const { return drawAs_; }
    // The domain boxes of function shapes, drawn as outlines.
    void setShowDomains(bool on);
    // Points where a·x + b·y + c·z + d < 0 are cut away; nullopt: no cut.
    void setClipPlane(std::optional<QVector4D> plane);
    // A small bright ball at a picked point (sized to the scene); nullopt removes it.
    void setMarker(std::optional<QVector3D> at);
    std::optional<QVector3D> marker() const { return markerAt_; }
    // The haptic tool (blue), its proxy on the surface (green) and the force
    // on the hand as an arrow from the proxy, longer for more force up to
    // `maxForce`; nullopt hides them. Cheap to call at every frame.
    struct Touch {
        QVector3D tool, proxy, force;
        float maxForce = 1;
    };
    void setTouch(std::optional<Touch> touch);
    std::optional<Touch> touch() const { return touchAt_; }

  private:
    void setLights(const std::vector<mesh::ViewLight>& lights);
    Qt3DRender::QParameter* parameter(const char* name, const QVariant& value);

    Qt3DCore::QEntity* root_;
    Qt3DRender::QShaderProgram* shader_;
    struct Drawn {
        const scene::Node* shape = nullptr;
        Qt3DCore::QEntity* entity = nullptr;  // null when the shape has nothing to draw
        Qt3DCore::QEntity* outline = nullptr; // its domain box, when shown
    };
    void rebuild(); // every entity again (a new drawing mode)
    void clearShapes();
    Qt3DCore::QEntity* makeEntity(const mesh::ShapeMesh& shape);
    Qt3DCore::QEntity* makeOutline(const mesh::ShapeMesh& shape);
    std::vector<Drawn> drawn_;
    std::size_t rebuilt_ = 0;
    std::vector<Qt3DRender::QParameter*> frame_;
    Bounds bounds_;
    DrawAs drawAs_ = DrawAs::Faces;
    bool showDomains_ = false;
    bool cutOpen_ = false; // a clip plane is on: inner faces show through the cut
    std::shared_ptr<const mesh::SceneMeshes> last_; // for re-making in another mode
    Qt3DCore::QEntity* marker_ = nullptr;
    TextureImages images_;
    std::optional<QVector3D> markerAt_;
    Qt3DCore::QEntity *toolMark_ = nullptr, *proxyMark_ = nullptr, *arrowMark_ = nullptr;
    Qt3DCore::QTransform *toolPlace_ = nullptr, *proxyPlace_ = nullptr, *arrowPlace_ = nullptr;
    std::optional<Touch> touchAt_;
};

} // namespace fl::viewer
