#pragma once
// The Scene tree panel: the scene's nodes as a tree (type and DEF name); a
// node met again through USE is a leaf naming it. Clicking one says where it
// is written.
#include "panel.h"

class QTreeWidget;

namespace fl::suite {

class SceneTreeDock : public Panel {
    Q_OBJECT
  public:
    explicit SceneTreeDock(QWidget* parent = nullptr);
    void attach(PanelContext& context) override;

    QTreeWidget* tree() const { return tree_; }

  public Q_SLOTS:
    void showScene(const fl::scene::Scene& scene) override;

  Q_SIGNALS:
    // Where the node is written (line and column from 1).
    void nodeActivated(int line, int column);

  private:
    QTreeWidget* tree_;
};

} // namespace fl::suite
