#pragma once
// The Examples panel: the example scenes that come with FunctionLab, each
// with its title and, as a tooltip, its description. Activating one chooses it.
#include "panel.h"

class QListWidget;

namespace fl::suite {

class ExamplesDock : public Panel {
    Q_OBJECT
  public:
    // The examples of `folder` (default: examplesFolder()).
    explicit ExamplesDock(QWidget* parent = nullptr, const QString& folder = {});
    void attach(PanelContext& context) override;

    QListWidget* list() const { return list_; }

  Q_SIGNALS:
    void exampleChosen(const QString& path);

  private:
    QListWidget* list_;
};

} // namespace fl::suite
