#include "parameters_dock.h"

#include "mesh/scene_meshing.h"
#include "viewer/scene_player.h"

#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QSlider>

#include <algorithm>
#include <cmath>

namespace fl::suite {

ParametersDock::ParametersDock(QWidget* parent)
    : Panel(tr("Parameters"), QStringLiteral("parameters"), Qt::RightDockWidgetArea, parent),
      panel_(new QWidget), form_(new QFormLayout(panel_)) {
    setWidget(panel_);
    form_->addRow(new QLabel(tr("The scene's formulas have no `param` to adjust.")));
}

void ParametersDock::showScene(const scene::Scene& scene) {
    while (form_->rowCount() > 0)
        form_->removeRow(0);
    const auto params = mesh::sceneParameters(scene);
    // Values the sliders had for names still there are kept.
    Values kept;
    for (const auto& p : params)
        for (const auto& [name, v] : values_)
            if (name == p.name) kept.emplace_back(name, v);
    values_ = kept;
    if (params.empty()) {
        form_->addRow(new QLabel(tr("The scene's formulas have no `param` to adjust.")));
        return;
    }
    for (const formula::ParameterInfo& p : params) {
        const double lo = p.hasRange ? p.lo : std::min(0.0, 2 * p.defaultValue);
        const double hi = p.hasRange ? p.hi : std::max(1.0, 2 * p.defaultValue);
        double value = p.defaultValue;
        for (const auto& [name, v] : values_)
            if (name == p.name) value = v;
        auto* slider = new QSlider(Qt::Horizontal);
        slider->setObjectName(QString::fromStdString("param-" + p.name));
        slider->setRange(0, 1000);
        slider->setValue(hi > lo ? int(std::lround((value - lo) / (hi - lo) * 1000)) : 0);
        auto* label = new QLabel(QString::number(value, 'g', 4));
        auto* row = new QWidget;
        auto* layout = new QHBoxLayout(row);
        layout->setContentsMargins(0, 0, 0, 0);
        layout->addWidget(slider, 1);
        layout->addWidget(label);
        form_->addRow(QString::fromStdString(p.name), row);
        connect(slider, &QSlider::valueChanged, this, [this, name = p.name, lo, hi, label](int v) {
            const double value = lo + (hi - lo) * v / 1000.0;
            label->setText(QString::number(value, 'g', 4));
            bool found = false;
            for (auto& [n, x] : values_)
                if (n == name) x = value, found = true;
            if (!found) values_.emplace_back(name, value);
            Q_EMIT parameterChanged(QString::fromStdString(name), value);
            Q_EMIT valuesChanged(values_);
        });
    }
}

void ParametersDock::attach(PanelContext& context) {
    connect(this, &ParametersDock::valuesChanged, context.player,
            [&context](const Values& values) { context.player->setParameters(values); });
}

} // namespace fl::suite
