#pragma once
// How the scene is looked at, as menu actions and a tool bar: examine or
// walk (a scene's NavigationInfo picks one when it opens), reset the view,
// shaded / wireframe / points, domain boxes, play and pause, the viewpoint
// list, and a cut across x, y or z.
#include <QObject>

class QAction;
class QMenu;
class QToolBar;

namespace fl::mesh {
struct SceneMeshes;
}
namespace fl::viewer {
class SceneWidget;
}

namespace fl::suite {

class TimelineBar;
class ViewpointBox;

class ViewControls : public QObject {
    Q_OBJECT
  public:
    ViewControls(viewer::SceneWidget* view, TimelineBar* timeline, ViewpointBox* viewpoints,
                 QObject* parent = nullptr);

    // The View menu's actions, and the tool bar with the viewpoints and the cut.
    void fillMenu(QMenu* menu);
    void fillToolBar(QToolBar* bar);
    // A new scene's first frame: walk or examine as its NavigationInfo says.
    void navigateAsTheSceneSays(const mesh::SceneMeshes& meshes);

  private:
    viewer::SceneWidget* view_;
    TimelineBar* timeline_;
    ViewpointBox* viewpoints_;
    QAction *examine_ = nullptr, *walk_ = nullptr;
};

} // namespace fl::suite
