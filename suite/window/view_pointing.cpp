#include "view_pointing.h"

#include "mesh/scene_meshing.h"
#include "panel_context.h"
#include "plain_text.h"
#include "screen_error_meter.h"
#include "viewer/picking.h"
#include "viewer/scene_player.h"
#include "viewer/scene_widget.h"

#include <QStatusBar>
#include <QVector3D>

namespace fl::suite {

ViewPointing::ViewPointing(PanelContext& context, ScreenErrorMeter* meter, QObject* parent)
    : QObject(parent), context_(context), meter_(meter) {
    connect(context.view, &viewer::SceneWidget::clicked, this, &ViewPointing::clicked);
    rest_.setSingleShot(true);
    rest_.setInterval(200);
    connect(context.view, &viewer::SceneWidget::hovered, this, [this](QPointF pixel) {
        restingAt_ = pixel;
        rest_.start();
    });
    connect(&rest_, &QTimer::timeout, this, &ViewPointing::rested);
}

void ViewPointing::clicked(QPointF pixel) {
    viewer::SceneWidget* view = context_.view;
    const auto meshes = view->meshes();
    if (!meshes) return;
    const auto p =
        viewer::pick(*meshes, viewer::rayThroughPixel(view->pose(), view->size(), pixel));
    if (!p) {
        view->setMarker(std::nullopt);
        context_.status->showMessage(tr("Nothing there"), 3000);
        return;
    }
    view->setMarker(QVector3D(float(p->point[0]), float(p->point[1]), float(p->point[2])));
    Q_EMIT context_.pointChosen(p->point, int(p->shapeIndex));
    // A TouchSensor over the shape hears the click (the fan starts).
    if (meshes->source == context_.scene())
        for (const scene::Node* sensor : p->touchSensors)
            context_.player->touch(*sensor);
    context_.status->showMessage(tr("(%1, %2, %3) on %4%5")
                                     .arg(p->point[0], 0, 'g', 6)
                                     .arg(p->point[1], 0, 'g', 6)
                                     .arg(p->point[2], 0, 'g', 6)
                                     .arg(visibleText(QString::fromStdString(p->shape)))
                                     .arg(p->onFunction ? tr(", on f = 0") : QString()));
}

void ViewPointing::rested() {
    viewer::SceneWidget* view = context_.view;
    const auto meshes = view->meshes();
    if (!meshes || meshes->source != context_.scene()) return;
    const auto p =
        viewer::pick(*meshes, viewer::rayThroughPixel(view->pose(), view->size(), restingAt_));
    meter_->focusOn(p ? meshes->shapes[p->shapeIndex].shape : nullptr);
}

} // namespace fl::suite
