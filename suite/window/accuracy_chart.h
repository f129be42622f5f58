#pragma once
// What accuracy costs in time, drawn: measured max error (a fraction of the
// box diagonal) against milliseconds per mesh, both on log scales, one line
// per method (the adaptive mesher, dense marching cubes). The operating
// point — the resolution the view uses now — is ringed, the level of
// detail's range is a band along the adaptive line; hovering a point
// says its resolution, triangles and evaluations; clicking one chooses it.
#include "measure/accuracy_sweep.h"

#include <QColor>
#include <QWidget>

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace fl::suite {

// What the chart's lines are: each a method of the rows, with its colour and
// legend; one of them carries the operating point. Meshing (the adaptive
// mesher against dense marching cubes) is the first kind; touch (function
// contact against polygon contact, haptics) the second; more costs come the
// same way.
struct ChartCurves {
    QString xLabel, yLabel, timeUnit; // the chart shows time in timeUnit
    double unitsPerMillisecond = 1;   // the rows' milliseconds in timeUnit
    double xFloor = 0.01;             // the least time shown
    double yFloor = 1e-7;             // the least error shown
    struct Line {
        measure::Method method;
        QString legend;
        QColor colour;
    };
    std::vector<Line> lines;
    measure::Method operatingMethod =
        measure::Method::Adaptive; // whose row nearest the operating resolution is ringed
    std::optional<measure::Method>
        bandMethod; // whose rows within the level of detail's range are banded
    // Where a row is drawn, when not at its time (x, in timeUnit) and its max
    // error (y); and what hovering it says, when not its time and error.
    std::function<double(const measure::AccuracyRow&)> x, y;
    std::function<QString(const measure::AccuracyRow&)> describe;
    QString operatingLabel = QStringLiteral("now (%1)"); // %1: the ringed row's resolution
    static ChartCurves meshing();
    static ChartCurves touch();
    // A PDE model drawn at resolutions: max distance to its finest drawing
    // against the time to mesh it (the Accuracy panel, for an FPdeSurface).
    static ChartCurves pdeDrawing();
    // A mesh fitted with more and more patches (Import Mesh as PDE): the
    // RMS distance to the mesh (a row's mean error) against the patch count
    // (its resolution).
    static ChartCurves pdeFitting();
};

class AccuracyChart : public QWidget {
    Q_OBJECT
  public:
    explicit AccuracyChart(QWidget* parent = nullptr);

    void setCurves(ChartCurves curves);
    const ChartCurves& curves() const { return curves_; }

    void setRows(std::vector<measure::AccuracyRow> rows);
    const std::vector<measure::AccuracyRow>& rows() const { return rows_; }
    void setOperatingResolution(double resolution);
    double operatingResolution() const { return operating_; }
    // The level of detail's range (coarsest, finest), drawn as a band along
    // the adaptive curve; {0, 0}: the shape has no level of detail.
    void setLevelOfDetailRange(double coarsest, double finest);
    std::pair<double, double> levelOfDetailRange() const { return lod_; }

    // Where row `i` is drawn (for tests and the mouse), and its row under a pixel.
    QPointF pointOf(std::size_t i) const;
    int rowAt(QPointF pixel) const; // -1: none within 8 pixels
    QString xLabel() const;
    QString yLabel() const;

  Q_SIGNALS:
    void resolutionChosen(double resolution);

  protected:
    void paintEvent(QPaintEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;

  private:
    QRectF plotArea() const;
    double xOf(const measure::AccuracyRow& r) const; // in the chart's unit
    double yOf(const measure::AccuracyRow& r) const;

    std::vector<measure::AccuracyRow> rows_;
    ChartCurves curves_ = ChartCurves::meshing();
    double operating_ = 0;
    std::pair<double, double> lod_{0, 0};
    double xLo_ = 0, xHi_ = 1, yLo_ = -4, yHi_ = 0; // decades (log10)
};

} // namespace fl::suite
