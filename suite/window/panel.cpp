#include "panel.h"

namespace fl::suite {

Panel::Panel(const QString& title, const QString& objectName, Qt::DockWidgetArea area,
             QWidget* parent)
    : QDockWidget(title, parent), area_(area) {
    setObjectName(objectName);
}

void Panel::attach(PanelContext&) {}

void Panel::showScene(const scene::Scene&) {}

void Panel::sceneChanged(std::shared_ptr<const scene::Scene> scene) {
    if (scene) showScene(*scene);
}

} // namespace fl::suite
