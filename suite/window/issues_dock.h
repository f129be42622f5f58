#pragma once
// The Issues panel: every diagnostic of the scene text (and of the files it
// inlines), errors in red. Activating or clicking one says where it is.
#include "panel.h"
#include "scene/scene_diagnostic.h"

#include <vector>

class QListWidget;

namespace fl::suite {

class IssuesDock : public Panel {
    Q_OBJECT
  public:
    explicit IssuesDock(QWidget* parent = nullptr);
    void attach(PanelContext& context) override;

    QListWidget* list() const { return list_; }

  public Q_SLOTS:
    void showDiagnostics(const std::vector<fl::scene::SceneDiagnostic>& diagnostics);

  Q_SIGNALS:
    // Where the entry points, as the scene reader counts (line and column from 1).
    void issueActivated(int line, int column);

  private:
    QListWidget* list_;
};

} // namespace fl::suite
