#pragma once
// A panel of the FunctionLab window: a dock with its title, the object name
// its place is saved under, and the side it goes to. Each panel is its own
// class: it wires itself to the window's editor, view, player and menus in
// attach() (panel_context.h), and the window only adds it:
//
//     addPanel(new IssuesDock);
//
// and hands it the scene when it changes (showScene). Hand-in lives in the
// Assignment panel, gradebooks in the Grading panel, joining a class and
// the shared scene in the Classroom panel.
#include <QDockWidget>

#include "panel_context.h"

#include <memory>

namespace fl::scene {
struct Scene;
}

namespace fl::suite {

class Panel : public QDockWidget {
    Q_OBJECT
  public:
    Panel(const QString& title, const QString& objectName, Qt::DockWidgetArea area,
          QWidget* parent = nullptr);

    Qt::DockWidgetArea area() const { return area_; }

    // Called once, when the window adds the panel: it wires itself to the
    // editor, the view, the player and the menus it needs (panel_context.h).
    virtual void attach(PanelContext& context);
    // Working on something the window should wait for (tests ask).
    virtual bool busy() const { return false; }
    // Showing a scene of its own in the view (the class's past, replayed):
    // the editor's scenes do not replace it until the panel lets go, and the
    // panel then shows the editor's newest good scene itself.
    virtual bool holdsTheView() const { return false; }

  public Q_SLOTS:
    // The scene the window now shows (a new one after every good edit). Most
    // panels show something of it; the default shows nothing.
    virtual void showScene(const fl::scene::Scene& scene);
    // The same scene, shared: a panel that works on it off the interface
    // thread (the assignment checklist) keeps it alive this way. By default
    // it calls showScene.
    virtual void sceneChanged(std::shared_ptr<const fl::scene::Scene> scene);

  private:
    Qt::DockWidgetArea area_;
};

} // namespace fl::suite
