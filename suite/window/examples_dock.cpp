#include "examples_dock.h"

#include "examples.h"

#include <QListWidget>

namespace fl::suite {

ExamplesDock::ExamplesDock(QWidget* parent, const QString& folder)
    : Panel(tr("Examples"), QStringLiteral("examples"), Qt::RightDockWidgetArea, parent),
      list_(new QListWidget) {
    setWidget(list_);
    for (const Example& e : listExamples(folder.isEmpty() ? examplesFolder() : folder)) {
        auto* item = new QListWidgetItem(e.title, list_);
        item->setToolTip(e.description);
        item->setData(Qt::UserRole, e.path);
    }
    connect(list_, &QListWidget::itemActivated, this, [this](QListWidgetItem* item) {
        Q_EMIT exampleChosen(item->data(Qt::UserRole).toString());
    });
}

} // namespace fl::suite
