#pragma once
// A panel of the FunctionLab window: a dock with its title, the object name
// its place is saved under, and the side it goes to. Each panel is its own
// class with a narrow interface (slots to show something, signals for what
// the student did); the main window only assembles them:
//
//     addPanel(new IssuesDock(this));
//
// and hands each the scene when it changes (showScene). The assignment,
// haptics and classroom panels plug in the same way.
#include <QDockWidget>

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
