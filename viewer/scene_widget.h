#pragma once
// The interactive 3D view: a Qt3D window inside a widget, showing the meshes
// the ScenePlayer delivers. Examine (orbit: left drag, pan: right or middle
// drag, zoom: wheel) or walk (arrow keys or WASD to move, drag to look);
// jump between the scene's Viewpoints, reset the view, grab a frame.
#include "camera_pose.h"
#include "frame_graph.h"
#include "mesh/scene_meshing.h"
#include "render_scene.h"

#include <QImage>
#include <QPoint>
#include <QPointF>
#include <QWidget>

#include <memory>
#include <optional>

namespace Qt3DExtras {
class Qt3DWindow;
}

namespace fl::viewer {

class SceneWidget : public QWidget {
    Q_OBJECT
  public:
    enum class Navigation { Examine, Walk };

    explicit SceneWidget(QWidget* parent = nullptr);
    ~SceneWidget() override;

    // Shows these meshes. The first time (and after resetView) the camera
    // goes to the bound Viewpoint, or to a view of everything. Later, the
    // scene's own binding is followed: a set_bind event that binds another
    // viewpoint takes the camera there, and while the scene's bound
    // viewpoint is the one shown, the camera moves with it when ROUTEs
    // animate it.
    void setMeshes(std::shared_ptr<const mesh::SceneMeshes> meshes);
    std::shared_ptr<const mesh::SceneMeshes> meshes() const { return meshes_; }
    std::size_t triangleCount() const { return triangles_; }

    QStringList viewpointNames() const;
    void bindViewpoint(int index); // -1: a view of the whole scene
    void resetView();              // the bound viewpoint again
    // The next meshes are a new scene: the camera goes to its first viewpoint.
    void placeCameraOnNextMeshes() { cameraPlaced_ = false; }
    void setNavigation(Navigation n);
    Navigation navigation() const { return navigation_; }
    CameraPose pose() const { return pose_; }
    void setPose(const CameraPose& pose);
    void setClipPlane(std::optional<QVector4D> plane);
    void setDrawAs(DrawAs as) { scene_->setDrawAs(as); }
    void setShowDomains(bool on) { scene_->setShowDomains(on); }
    void setMarker(std::optional<QVector3D> at) { scene_->setMarker(at); }
    // The haptic tool, its proxy and the force arrow (RenderScene::setTouch).
    void setTouch(std::optional<RenderScene::Touch> touch) { scene_->setTouch(touch); }
    std::optional<RenderScene::Touch> touch() const { return scene_->touch(); }
    const Bounds& bounds() const { return scene_->bounds(); }
    QWindow* renderWindow() const;

    // The frame on screen now, as an image (empty after `timeoutMs`).
    QImage grabFrame(int timeoutMs = 5000);

  Q_SIGNALS:
    void poseChanged();
    // The scene bound a NavigationInfo of another type (a set_bind event):
    // the widget moves that way now; a window shows it in its controls.
    void navigationBound(fl::viewer::SceneWidget::Navigation n);
    // A click (press and release without dragging) at this pixel of the view.
    void clicked(QPointF pixel);
    // The mouse moved over the view with no button pressed (a window may ask
    // what is under it: the status bar's error figure follows the cursor).
    void hovered(QPointF pixel);

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    void applyPose();
    float aspect() const;

    Qt3DExtras::Qt3DWindow* window_;
    QWidget* container_;
    Qt3DCore::QEntity* root_;
    std::unique_ptr<RenderScene> scene_;
    FrameGraph frameGraph_;
    std::shared_ptr<const mesh::SceneMeshes> meshes_;
    std::size_t triangles_ = 0;
    CameraPose pose_;
    int boundViewpoint_ = 0;
    // What the scene bound (SceneView::boundViewpoint) and how, last frame.
    int sceneBound_ = -1;
    std::optional<mesh::ViewPoint> sceneBoundPose_;
    std::vector<std::string> sceneNavigationTypes_;
    bool cameraPlaced_ = false;
    Navigation navigation_ = Navigation::Examine;
    QPoint lastMouse_, pressedAt_;
    Qt::MouseButtons buttons_;
};

} // namespace fl::viewer
