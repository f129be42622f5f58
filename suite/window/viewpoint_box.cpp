#include "viewpoint_box.h"

namespace fl::suite {

ViewpointBox::ViewpointBox(QWidget* parent) : QComboBox(parent) {
    setObjectName(QStringLiteral("viewpoints"));
    connect(this, &QComboBox::activated, this,
            [this](int index) { Q_EMIT viewpointChosen(itemData(index).toInt()); });
}

void ViewpointBox::showViewpoints(const QStringList& names) {
    if (names == names_ && count() > 0) return;
    names_ = names;
    clear();
    for (int i = 0; i < names.size(); ++i)
        addItem(names[i], i);
    addItem(tr("Whole scene"), -1);
}

} // namespace fl::suite
