#include "window_placement.h"

#include <QMainWindow>
#include <QScreen>
#include <QSettings>

namespace fl::suite {
namespace {

const QString kGeometry = QStringLiteral("window/geometry");
const QString kState = QStringLiteral("window/state");

} // namespace

void restorePlacement(QMainWindow& window) {
    QSettings settings;
    window.restoreGeometry(settings.value(kGeometry).toByteArray());
    window.restoreState(settings.value(kState).toByteArray());
    QSize wanted = settings.contains(kGeometry) ? window.size() : QSize(1280, 800);
    if (const QScreen* s = window.screen()) // room left for the title bar
        wanted = wanted.boundedTo(s->availableGeometry().size() - QSize(0, 32));
    window.resize(wanted);
}

void savePlacement(const QMainWindow& window) {
    QSettings settings;
    settings.setValue(kGeometry, window.saveGeometry());
    settings.setValue(kState, window.saveState());
}

bool placementSaved() {
    return QSettings().contains(kState);
}

} // namespace fl::suite
