#pragma once
// A screenshot of the whole FunctionLab window for GUI tests: QWidget::grab
// does not see the Qt3D view's OpenGL surface, so its frame is painted in.
#include "suite/window/main_window.h"
#include "viewer/scene_widget.h"

#include <QImage>
#include <QPainter>

namespace fl::test {

inline QImage windowScreenshot(suite::MainWindow& w) {
    QImage shot = w.grab().toImage();
    const QImage frame = w.view()->grabFrame();
    if (!frame.isNull()) {
        QPainter p(&shot);
        const QPoint at = w.view()->mapTo(&w, QPoint(0, 0));
        p.drawImage(QRect(at, w.view()->size()), frame);
    }
    return shot;
}

} // namespace fl::test
