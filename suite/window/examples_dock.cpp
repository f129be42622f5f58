#include "examples_dock.h"

#include "plain_text.h"
#include "working_copy.h"

#include "courseware/catalogue.h"
#include "examples.h"

#include <QListWidget>

namespace fl::suite {

ExamplesDock::ExamplesDock(QWidget* parent, const QString& folder)
    : Panel(tr("Examples"), QStringLiteral("examples"), Qt::RightDockWidgetArea, parent),
      list_(new QListWidget) {
    setWidget(list_);
    const QString from = folder.isEmpty() ? examplesFolder() : folder;
    for (const courseware::ExampleScene& e : courseware::listExamples(from.toStdString())) {
        auto* item = new QListWidgetItem(QString::fromStdString(e.title), list_);
        item->setToolTip(plainToolTip(QString::fromStdString(e.description)));
        item->setData(Qt::UserRole, QString::fromStdString(e.path.string()));
    }
    connect(list_, &QListWidget::itemActivated, this, [this](QListWidgetItem* item) {
        Q_EMIT exampleChosen(item->data(Qt::UserRole).toString());
    });
}

void ExamplesDock::attach(PanelContext& context) {
    connect(this, &ExamplesDock::exampleChosen, this, [&context](const QString& path) {
        if (context.keepChanges()) openWorkingCopy(context, path, QStringLiteral("examples"));
    });
}

} // namespace fl::suite
