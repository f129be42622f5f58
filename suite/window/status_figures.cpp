#include "status_figures.h"

#include "mesh/scene_meshing.h"
#include "plain_text.h"
#include "screen_error_meter.h"
#include "viewer/scene_player.h"
#include "viewer/scene_widget.h"

#include <QLabel>
#include <QStatusBar>

namespace fl::suite {

StatusFigures::StatusFigures(QStatusBar* bar, viewer::SceneWidget* view,
                             viewer::ScenePlayer* player, ScreenErrorMeter* meter, QObject* parent)
    : QObject(parent), view_(view), player_(player), triangles_(new QLabel), meshTime_(new QLabel),
      screenError_(plainLabel()), frameRate_(new QLabel), timeLabel_(new QLabel) {
    for (QLabel* l : {triangles_, meshTime_, screenError_, frameRate_, timeLabel_})
        bar->addPermanentWidget(l);
    connect(meter, &ScreenErrorMeter::measured, screenError_,
            [this](const QString& text) { screenError_->setText(visibleText(text)); });
    connect(player, &viewer::ScenePlayer::timeChanged, timeLabel_, [this](double s) {
        timeLabel_->setText(QStringLiteral("t = %1 s").arg(s, 0, 'f', 2));
    });
    rate_.setInterval(1000);
    connect(&rate_, &QTimer::timeout, this, [this] {
        const std::size_t frames = player_->framesDelivered();
        frameRate_->setText(tr("%1 frames/s").arg(frames - framesAtLastRate_));
        framesAtLastRate_ = frames;
    });
    rate_.start();
}

void StatusFigures::frameShown(const mesh::SceneMeshes& meshes) {
    double ms = 0;
    for (const auto& s : meshes.shapes)
        ms += s.stats.milliseconds;
    triangles_->setText(tr("%1 triangles").arg(view_->triangleCount()));
    meshTime_->setText(tr("meshed in %1 ms").arg(ms, 0, 'f', 0));
}

QString StatusFigures::screenErrorText() const {
    return screenError_->text();
}

} // namespace fl::suite
