#pragma once
// What accuracy costs in time, drawn: measured max error (a fraction of the
// box diagonal) against milliseconds per mesh, both on log scales, one line
// per method (the adaptive mesher, dense marching cubes). The operating
// point — the resolution the view uses now — is ringed, the level of
// detail's range is a band along the adaptive line; hovering a point
// says its resolution, triangles and evaluations; clicking one chooses it.
#include "accuracy_sweep.h"

#include <QWidget>

#include <utility>
#include <vector>

namespace fl::suite {

class AccuracyChart : public QWidget {
    Q_OBJECT
  public:
    explicit AccuracyChart(QWidget* parent = nullptr);

    void setRows(std::vector<bench::AccuracyRow> rows);
    const std::vector<bench::AccuracyRow>& rows() const { return rows_; }
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

    std::vector<bench::AccuracyRow> rows_;
    double operating_ = 0;
    std::pair<double, double> lod_{0, 0};
    double xLo_ = 0, xHi_ = 1, yLo_ = -4, yHi_ = 0; // decades (log10)
};

} // namespace fl::suite
