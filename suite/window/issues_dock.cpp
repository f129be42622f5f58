#include "issues_dock.h"

#include "editor/live_parser.h"
#include "scene/scene_diagnostic.h"

#include <QListWidget>

namespace fl::suite {

IssuesDock::IssuesDock(QWidget* parent)
    : Panel(tr("Issues"), QStringLiteral("issues"), Qt::BottomDockWidgetArea, parent),
      list_(new QListWidget) {
    setWidget(list_);
    list_->setWordWrap(true); // the end of a message says what to do
    auto activated = [this](QListWidgetItem* item) {
        Q_EMIT issueActivated(item->data(Qt::UserRole).toInt(),
                              item->data(Qt::UserRole + 1).toInt());
    };
    connect(list_, &QListWidget::itemActivated, this, activated);
    connect(list_, &QListWidget::itemClicked, this, activated);
}

void IssuesDock::attach(PanelContext& context) {
    connect(this, &IssuesDock::issueActivated, this,
            [&context](int line, int column) { context.goTo(line, column); });
    connect(context.parser, &editor::LiveParser::parsed, this,
            [this](const editor::ParseOutcome& outcome) { showDiagnostics(outcome.all); });
}

void IssuesDock::showDiagnostics(const std::vector<scene::SceneDiagnostic>& diagnostics) {
    // The strip takes room from the view only while there is something in it.
    setVisible(!diagnostics.empty());
    list_->clear();
    for (const auto& d : diagnostics) {
        QString text = QString::fromStdString(scene::formatSceneDiagnostic(d));
        if (d.fix)
            text += tr("  [click, then Ctrl+. to %1]").arg(QString::fromStdString(d.fix->label));
        auto* item = new QListWidgetItem(text, list_);
        item->setToolTip(text);
        item->setData(Qt::UserRole, d.pos.line);
        item->setData(Qt::UserRole + 1, d.pos.column);
        item->setForeground(d.severity == scene::Severity::Error ? QColor(Qt::red)
                                                                 : palette().color(QPalette::Text));
    }
}

} // namespace fl::suite
