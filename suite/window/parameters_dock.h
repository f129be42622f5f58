#pragma once
// The Parameters panel: a slider per `param` the scene's formulas declare,
// over its declared range (else around its default). A value the student set
// is kept while the scene still has that parameter. Moving a slider says
// which parameter now has which value.
#include "panel.h"

#include <string>
#include <utility>
#include <vector>

class QFormLayout;

namespace fl::suite {

class ParametersDock : public Panel {
    Q_OBJECT
  public:
    using Values = std::vector<std::pair<std::string, double>>;

    explicit ParametersDock(QWidget* parent = nullptr);
    void attach(PanelContext& context) override;

    // The values set with the sliders (parameters left at their defaults are
    // not listed): what the scene is to be meshed with.
    const Values& values() const { return values_; }

  public Q_SLOTS:
    void showScene(const fl::scene::Scene& scene) override;

  Q_SIGNALS:
    void parameterChanged(const QString& name, double value);
    void valuesChanged(const fl::suite::ParametersDock::Values& values);

  private:
    QWidget* panel_;
    QFormLayout* form_;
    Values values_;
};

} // namespace fl::suite
