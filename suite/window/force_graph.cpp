#include "force_graph.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace fl::suite {

ForceGraph::ForceGraph(QWidget* parent) : QWidget(parent) {
    setMinimumHeight(110);
    setAccessibleName(tr("Force of the last second"));
}

void ForceGraph::setForces(std::vector<field::Vec3> forces, double maxForce,
                           std::size_t ticksShown) {
    forces_ = std::move(forces);
    ticksShown_ = std::max<std::size_t>(ticksShown, 2);
    if (forces_.size() > ticksShown_)
        forces_.erase(forces_.begin(), forces_.end() - std::ptrdiff_t(ticksShown_));
    maxForce_ = maxForce > 0 ? maxForce : 1;
    // The scale follows what was felt (a step of 1, 2 or 5), up to the device's maximum.
    double peak = 0;
    for (const field::Vec3& f : forces_)
        peak = std::max(peak, field::length(f));
    scale_ = 0.5;
    for (double step : {1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0, 200.0, 500.0})
        if (scale_ < peak) scale_ = step;
    scale_ = std::min(scale_, std::max(maxForce_, 0.5));
    update();
}

void ForceGraph::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    p.fillRect(rect(), palette().base());
    const QRectF a = QRectF(rect()).adjusted(34, 6, -6, -16);
    p.setPen(palette().mid().color());
    p.drawRect(a);
    const double mid = a.center().y();
    p.drawLine(QPointF(a.left(), mid), QPointF(a.right(), mid));
    p.setPen(palette().text().color());
    QFont small = font();
    small.setPointSizeF(small.pointSizeF() * 0.8);
    p.setFont(small);
    p.drawText(QRectF(0, a.top() - 6, 30, 14), Qt::AlignRight, QString::number(scale_));
    p.drawText(QRectF(0, mid - 7, 30, 14), Qt::AlignRight, QStringLiteral("0"));
    p.drawText(QRectF(0, a.bottom() - 8, 30, 14), Qt::AlignRight, QString::number(-scale_));
    p.drawText(QRectF(a.left(), a.bottom() + 2, a.width(), 14), Qt::AlignHCenter,
               tr("N, the last second"));
    if (forces_.size() < 2) return;
    auto x = [&](std::size_t i) { // the newest at the right edge
        return a.right() - a.width() * double(forces_.size() - 1 - i) / double(ticksShown_ - 1);
    };
    auto y = [&](double v) { return mid - std::clamp(v / scale_, -1.0, 1.0) * a.height() / 2; };
    const QColor colours[4] = {QColor(0xd0, 0x3a, 0x3a), QColor(0x3a, 0xa0, 0x3a),
                               QColor(0x3a, 0x6a, 0xd0), palette().text().color()};
    for (int c = 0; c < 4; ++c) {
        QPainterPath line;
        for (std::size_t i = 0; i < forces_.size(); ++i) {
            const double v = c < 3 ? forces_[i][std::size_t(c)] : field::length(forces_[i]);
            i == 0 ? line.moveTo(x(i), y(v)) : line.lineTo(x(i), y(v));
        }
        p.setPen(QPen(colours[c], c == 3 ? 2 : 1));
        p.drawPath(line);
    }
    const char* names[4] = {"x", "y", "z", "|F|"};
    for (int c = 0; c < 4; ++c) {
        p.setPen(colours[c]);
        p.drawText(QPointF(a.right() - 110 + 26 * c, a.top() + 12), QString::fromLatin1(names[c]));
    }
}

} // namespace fl::suite
