#pragma once
// Pointing into the 3D view. A click names the point under the cursor (on
// the function itself where the shape is implicit or explicit), marks it,
// lets a TouchSensor over the shape hear it and offers it to the panels
// (PanelContext::pointChosen: the classroom's tools); the status bar's
// error figure follows the shape under the resting cursor.
#include <QObject>
#include <QPointF>
#include <QTimer>

namespace fl::suite {

class PanelContext;
class ScreenErrorMeter;

class ViewPointing : public QObject {
    Q_OBJECT
  public:
    ViewPointing(PanelContext& context, ScreenErrorMeter* meter, QObject* parent = nullptr);

  private:
    void clicked(QPointF pixel);
    void rested();

    PanelContext& context_;
    ScreenErrorMeter* meter_;
    QTimer rest_;
    QPointF restingAt_;
};

} // namespace fl::suite
