#pragma once
// The haptics panel's live graph: the force of the last second, its size
// and its three components, newest on the right, in newtons.
#include "field/vec3.h"

#include <QWidget>

#include <vector>

namespace fl::suite {

class ForceGraph : public QWidget {
    Q_OBJECT
  public:
    explicit ForceGraph(QWidget* parent = nullptr);

    // Forces, oldest first, one per tick, and the device's maximum; the graph
    // spans `ticksShown` ticks (a second of the loop), newest at the right.
    void setForces(std::vector<field::Vec3> forces, double maxForce, std::size_t ticksShown);
    const std::vector<field::Vec3>& forces() const { return forces_; }
    double scale() const { return scale_; } // newtons at the top of the graph

  protected:
    void paintEvent(QPaintEvent* event) override;

  private:
    std::vector<field::Vec3> forces_;
    double maxForce_ = 1;
    double scale_ = 1;
    std::size_t ticksShown_ = 1000;
};

} // namespace fl::suite
