#include "accuracy_chart.h"

#include <QFontMetricsF>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QToolTip>

#include <algorithm>
#include <cmath>

namespace fl::suite {
ChartCurves ChartCurves::meshing() {
    ChartCurves c;
    c.xLabel = AccuracyChart::tr("time per mesh (ms, log scale)");
    c.yLabel = AccuracyChart::tr("max error (of the box diagonal, log scale)");
    c.timeUnit = QStringLiteral("ms");
    c.lines = {{measure::Method::Dense, AccuracyChart::tr("● dense marching cubes"),
                QColor(0x86, 0x8e, 0x96)},
               {measure::Method::Adaptive, AccuracyChart::tr("● adaptive (ours)"),
                QColor(0x1c, 0x7e, 0xd6)}};
    c.operatingMethod = measure::Method::Adaptive;
    c.bandMethod = measure::Method::Adaptive;
    return c;
}

ChartCurves ChartCurves::touch() {
    ChartCurves c;
    c.xLabel = AccuracyChart::tr("time per force tick (µs, p50, log scale)");
    // The mean: a path's few ticks at sharp edges would make the max say little.
    c.yLabel = AccuracyChart::tr("mean contact error (of the diagonal, log scale)");
    c.timeUnit = QStringLiteral("µs");
    c.unitsPerMillisecond = 1000;
    c.xFloor = 0.01;
    c.yFloor = 1e-17; // touching the function is exact to rounding
    c.lines = {{measure::Method::Polygons, AccuracyChart::tr("● polygon contact (its mesh)"),
                QColor(0xe0, 0x8a, 0x1c)},
               {measure::Method::Function, AccuracyChart::tr("● function contact (ours)"),
                QColor(0x2a, 0xa0, 0x4a)}};
    c.operatingMethod = measure::Method::Polygons;
    return c;
}

ChartCurves ChartCurves::pdeDrawing() {
    ChartCurves c;
    c.xLabel = AccuracyChart::tr("time to mesh the model (ms, log scale)");
    c.yLabel = AccuracyChart::tr("max error (of the box diagonal, log scale)");
    c.timeUnit = QStringLiteral("ms");
    c.lines = {{measure::Method::PdeMesh, AccuracyChart::tr("● PDE model at a resolution"),
                QColor(0x8a, 0x3f, 0xc4)}};
    c.operatingMethod = measure::Method::PdeMesh;
    c.bandMethod = measure::Method::PdeMesh;
    c.describe = [](const measure::AccuracyRow& r) {
        return AccuracyChart::tr("the model at resolution %1\n%2 triangles in %3 ms\nmax error "
                                 "%4, RMS %5 of the diagonal")
            .arg(r.resolution)
            .arg(r.triangles)
            .arg(r.milliseconds, 0, 'g', 3)
            .arg(r.maxError, 0, 'g', 3)
            .arg(r.meanError, 0, 'g', 3);
    };
    return c;
}

ChartCurves ChartCurves::pdeFitting() {
    ChartCurves c;
    c.xLabel = AccuracyChart::tr("patches (log scale)");
    c.yLabel = AccuracyChart::tr("RMS distance to the mesh (of the diagonal, log)");
    c.timeUnit = AccuracyChart::tr("patches");
    c.xFloor = 1;
    // The RMS: what --error and the slider aim at (the Hausdorff distance
    // is in the tooltip and the dialog's figures).
    c.x = [](const measure::AccuracyRow& r) { return r.resolution; };
    c.y = [](const measure::AccuracyRow& r) { return r.meanError; };
    c.lines = {{measure::Method::PdeFit, AccuracyChart::tr("● PDE patches fitted"),
                QColor(0x8a, 0x3f, 0xc4)}};
    c.operatingMethod = measure::Method::PdeFit;
    c.operatingLabel = AccuracyChart::tr("this fit (%1)");
    c.describe = [](const measure::AccuracyRow& r) {
        return AccuracyChart::tr("%1 patches, fitted in %2 s\nRMS %3, Hausdorff %4 of the diagonal")
            .arg(r.resolution)
            .arg(r.milliseconds / 1000, 0, 'f', 1)
            .arg(r.meanError, 0, 'g', 3)
            .arg(r.maxError, 0, 'g', 3);
    };
    return c;
}

AccuracyChart::AccuracyChart(QWidget* parent) : QWidget(parent) {
    setMouseTracking(true);
    setMinimumSize(260, 200);
}

void AccuracyChart::setCurves(ChartCurves curves) {
    curves_ = std::move(curves);
    setRows({});
}

void AccuracyChart::setRows(std::vector<measure::AccuracyRow> rows) {
    rows_ = std::move(rows);
    // Whole decades round everything measured (time at least 0.01 ms, error at least 1e-7).
    double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
    for (const measure::AccuracyRow& r : rows_) {
        const double x = std::log10(xOf(r)), y = std::log10(yOf(r));
        xmin = std::min(xmin, x), xmax = std::max(xmax, x);
        ymin = std::min(ymin, y), ymax = std::max(ymax, y);
    }
    if (!rows_.empty()) {
        xLo_ = std::floor(xmin), xHi_ = std::max(std::ceil(xmax), xLo_ + 1);
        yLo_ = std::floor(ymin), yHi_ = std::max(std::ceil(ymax), yLo_ + 1);
    }
    update();
}

void AccuracyChart::setOperatingResolution(double resolution) {
    operating_ = resolution;
    update();
}

void AccuracyChart::setLevelOfDetailRange(double coarsest, double finest) {
    lod_ = {coarsest, finest};
    update();
}

QString AccuracyChart::xLabel() const {
    return curves_.xLabel;
}

QString AccuracyChart::yLabel() const {
    return curves_.yLabel;
}

QRectF AccuracyChart::plotArea() const {
    return QRectF(64, 14, std::max(40, width() - 80), std::max(40, height() - 56));
}

double AccuracyChart::xOf(const measure::AccuracyRow& r) const {
    const double x = curves_.x ? curves_.x(r) : r.milliseconds * curves_.unitsPerMillisecond;
    return std::max(x, curves_.xFloor);
}

double AccuracyChart::yOf(const measure::AccuracyRow& r) const {
    return std::max(curves_.y ? curves_.y(r) : r.maxError, curves_.yFloor);
}

QPointF AccuracyChart::pointOf(std::size_t i) const {
    const measure::AccuracyRow& r = rows_[i];
    const QRectF a = plotArea();
    const double x = (std::log10(xOf(r)) - xLo_) / (xHi_ - xLo_);
    const double y = (std::log10(yOf(r)) - yLo_) / (yHi_ - yLo_);
    return {a.left() + x * a.width(), a.bottom() - y * a.height()};
}

int AccuracyChart::rowAt(QPointF pixel) const {
    int best = -1;
    double nearest = 8;
    for (std::size_t i = 0; i < rows_.size(); ++i) {
        const double d = QLineF(pointOf(i), pixel).length();
        if (d <= nearest) {
            nearest = d;
            best = int(i);
        }
    }
    return best;
}

void AccuracyChart::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    p.fillRect(rect(), palette().base());
    const QRectF a = plotArea();
    p.setPen(palette().text().color());
    p.drawRect(a);
    // Decade ticks and labels.
    QFont small = font();
    small.setPointSizeF(small.pointSizeF() * 0.8);
    p.setFont(small);
    for (double d = xLo_; d <= xHi_ + 1e-9; d += 1) {
        const double x = a.left() + (d - xLo_) / (xHi_ - xLo_) * a.width();
        p.drawLine(QPointF(x, a.bottom()), QPointF(x, a.bottom() + 4));
        p.drawText(QRectF(x - 30, a.bottom() + 5, 60, 14), Qt::AlignHCenter,
                   QString::number(std::pow(10.0, d), 'g', 3));
    }
    for (double d = yLo_; d <= yHi_ + 1e-9; d += 1) {
        const double y = a.bottom() - (d - yLo_) / (yHi_ - yLo_) * a.height();
        p.drawLine(QPointF(a.left() - 4, y), QPointF(a.left(), y));
        p.drawText(QRectF(0, y - 7, a.left() - 6, 14), Qt::AlignRight | Qt::AlignVCenter,
                   QStringLiteral("1e%1").arg(int(d)));
    }
    p.drawText(QRectF(a.left(), height() - 16, a.width(), 14), Qt::AlignHCenter, xLabel());
    p.save();
    p.translate(10, a.center().y());
    p.rotate(-90);
    // Up the side of a short chart the title would be cut at both ends: a
    // smaller font first (down to 7 points), then an ellipsis.
    QFont titleFont = p.font();
    QFontMetricsF fits(titleFont);
    while (fits.horizontalAdvance(yLabel()) > a.height() && titleFont.pointSizeF() > 7) {
        titleFont.setPointSizeF(titleFont.pointSizeF() - 0.5);
        fits = QFontMetricsF(titleFont);
    }
    p.setFont(titleFont);
    p.drawText(QRectF(-a.height() / 2, -8, a.height(), 14), Qt::AlignHCenter,
               fits.elidedText(yLabel(), Qt::ElideRight, a.height()));
    p.restore();
    // The level of detail's range: a band under the adaptive points it may use.
    if (lod_.second > 0) {
        QPainterPath band;
        bool first = true;
        for (std::size_t i = 0; i < rows_.size(); ++i) {
            const measure::AccuracyRow& r = rows_[i];
            if (r.method != curves_.bandMethod || r.resolution < lod_.first ||
                r.resolution > lod_.second)
                continue;
            first ? band.moveTo(pointOf(i)) : band.lineTo(pointOf(i));
            first = false;
        }
        if (!first) {
            p.setPen(QPen(QColor(0xf0, 0xa0, 0x20, 110), 14, Qt::SolidLine, Qt::RoundCap,
                          Qt::RoundJoin));
            p.setBrush(Qt::NoBrush);
            p.drawPath(band);
        }
    }
    // One line per method, in resolution order.
    for (const ChartCurves::Line& l : curves_.lines) {
        const measure::Method method = l.method;
        const QColor& colour = l.colour;
        QPainterPath line;
        bool first = true;
        for (std::size_t i = 0; i < rows_.size(); ++i) {
            if (rows_[i].method != method) continue;
            const QPointF q = pointOf(i);
            first ? line.moveTo(q) : line.lineTo(q);
            first = false;
        }
        p.setPen(QPen(colour, 2));
        p.setBrush(Qt::NoBrush);
        p.drawPath(line);
        p.setBrush(colour);
        for (std::size_t i = 0; i < rows_.size(); ++i)
            if (rows_[i].method == method) p.drawEllipse(pointOf(i), 3.5, 3.5);
    }
    // The operating point: the adaptive row nearest the resolution in use.
    int now = -1;
    for (std::size_t i = 0; i < rows_.size(); ++i)
        if (rows_[i].method == curves_.operatingMethod &&
            (now < 0 || std::abs(rows_[i].resolution - operating_) <
                            std::abs(rows_[std::size_t(now)].resolution - operating_)))
            now = int(i);
    if (now >= 0 && operating_ > 0) {
        p.setPen(QPen(QColor(0xe0, 0x31, 0x31), 2));
        p.setBrush(Qt::NoBrush);
        const QPointF q = pointOf(std::size_t(now));
        p.drawEllipse(q, 8, 8);
        p.drawText(q + QPointF(10, -8),
                   curves_.operatingLabel.arg(rows_[std::size_t(now)].resolution));
    }
    // The legend, in the plot's corner with the fewest points.
    const bool band = lod_.second > 0 && curves_.bandMethod.has_value();
    const double legendHeight = 14.0 * double(curves_.lines.size() + (band ? 1 : 0)) + 4;
    QRectF legend;
    std::size_t fewest = rows_.size() + 1;
    for (const QPointF corner : {a.topRight() + QPointF(-176, 2), a.topLeft() + QPointF(6, 2),
                                 a.bottomRight() + QPointF(-176, -legendHeight - 2),
                                 a.bottomLeft() + QPointF(6, -legendHeight - 2)}) {
        const QRectF box(corner, QSizeF(172, legendHeight));
        std::size_t inside = 0;
        for (std::size_t i = 0; i < rows_.size(); ++i)
            inside += box.adjusted(-12, -12, 12, 12).contains(pointOf(i));
        if (inside < fewest) {
            fewest = inside;
            legend = box;
        }
    }
    double legendY = legend.top() + 12;
    for (auto it = curves_.lines.rbegin(); it != curves_.lines.rend(); ++it) {
        p.setPen(it->colour);
        p.drawText(QPointF(legend.left(), legendY), it->legend);
        legendY += 14;
    }
    if (band) {
        p.setPen(QColor(0xc0, 0x78, 0x10));
        p.drawText(QPointF(legend.left(), legendY),
                   tr("▬ level of detail %1–%2").arg(lod_.first).arg(lod_.second));
    }
}

void AccuracyChart::mouseMoveEvent(QMouseEvent* event) {
    const int i = rowAt(event->position());
    if (i < 0) {
        QToolTip::hideText();
        return;
    }
    const measure::AccuracyRow& r = rows_[std::size_t(i)];
    if (curves_.describe) {
        QToolTip::showText(event->globalPosition().toPoint(), curves_.describe(r), this);
        return;
    }
    QToolTip::showText(event->globalPosition().toPoint(),
                       tr("%1 at resolution %2\n%3 triangles, %4 evaluations\n%5 %6, max error %7")
                           .arg(QString::fromLatin1(measure::methodName(r.method)))
                           .arg(r.resolution)
                           .arg(r.triangles)
                           .arg(r.evaluations)
                           .arg(r.milliseconds * curves_.unitsPerMillisecond, 0, 'g', 3)
                           .arg(curves_.timeUnit)
                           .arg(r.maxError, 0, 'g', 3),
                       this);
}

void AccuracyChart::mousePressEvent(QMouseEvent* event) {
    const int i = rowAt(event->position());
    if (i >= 0) Q_EMIT resolutionChosen(rows_[std::size_t(i)].resolution);
}

} // namespace fl::suite
