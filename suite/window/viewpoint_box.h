#pragma once
// The Viewpoint chooser of the view toolbar: the scene's viewpoints by name,
// then "Whole scene". Choosing one says which (its index among the
// viewpoints; -1 for the whole scene).
#include <QComboBox>

namespace fl::suite {

class ViewpointBox : public QComboBox {
    Q_OBJECT
  public:
    explicit ViewpointBox(QWidget* parent = nullptr);

  public Q_SLOTS:
    // Refills the list only when the names differ from those shown.
    void showViewpoints(const QStringList& names);

  Q_SIGNALS:
    void viewpointChosen(int index);

  private:
    QStringList names_;
};

} // namespace fl::suite
