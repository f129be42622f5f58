#include "assignment_panel.h"

#include "courseware/catalogue.h"
#include "courseware/hand_in.h"
#include "editor/code_editor.h"
#include "editor/live_parser.h"
#include "offline_text_browser.h"
#include "plain_text.h"
#include "working_copy.h"

#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QHeaderView>
#include <QLabel>
#include <QMenu>
#include <QPushButton>
#include <QStatusBar>
#include <QTextBrowser>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <initializer_list>

namespace fl::suite {
namespace {

QString points(double p) {
    return QString::number(p, 'g', 6);
}

} // namespace

QTextBrowser* AssignmentPanel::instructions() const {
    return instructions_;
}

AssignmentPanel::AssignmentPanel(QWidget* parent, const QString& folder)
    : Panel(tr("Assignment"), QStringLiteral("assignment"), Qt::RightDockWidgetArea, parent),
      choice_(new QComboBox), instructions_(new OfflineTextBrowser), checklist_(new QTreeWidget),
      status_(plainLabel()), starter_(new QPushButton(tr("Start from the starter scene"))),
      checker_(
          this, [](const Check& c) { return grading::checkScene(*c.scene, c.requirements); },
          [this](const Check& c, grading::CheckReport report) {
              // A report of a scene or an assignment since replaced is not shown.
              if (c.scene == scene_ && c.assignment == current_) showReport(report);
          }) {
    auto* box = new QWidget;
    auto* layout = new QVBoxLayout(box);
    layout->addWidget(choice_);
    layout->addWidget(instructions_, 2);
    layout->addWidget(starter_);
    layout->addWidget(checklist_, 3);
    layout->addWidget(status_);
    setWidget(box);
    checklist_->setColumnCount(2);
    checklist_->setHeaderLabels({tr("Requirement"), tr("Why")});
    checklist_->header()->setStretchLastSection(true);
    checklist_->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    checklist_->setWordWrap(true);
    checklist_->setRootIsDecorated(false);
    instructions_->setOpenExternalLinks(false);
    status_->setWordWrap(true);
    // Long titles must not widen the dock (and shrink the view) on their own.
    choice_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    choice_->setMinimumContentsLength(16);
    for (QWidget* w : std::initializer_list<QWidget*>{instructions_, checklist_, status_})
        w->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Expanding);
    box->setMinimumWidth(200);

    assignments_ = folder.isEmpty() ? courseware::listAssignments()
                                    : courseware::listAssignments(folder.toStdString());
    choice_->addItem(tr("(no assignment)"));
    for (const courseware::AssignmentLoad& a : assignments_)
        choice_->addItem(a.assignment ? QString::fromStdString(a.assignment->title)
                                      : tr("(a broken manifest)"));
    connect(choice_, &QComboBox::currentIndexChanged, this, [this](int index) {
        current_ = index - 1;
        showAssignment();
    });
    connect(starter_, &QPushButton::clicked, this, [this] {
        if (const courseware::Assignment* a = assignment(); a && !a->starters.empty())
            Q_EMIT starterChosen(QString::fromStdString(a->starters.front().string()));
    });
    connect(checklist_, &QTreeWidget::itemActivated, this, [this](QTreeWidgetItem* item) {
        const int line = item->data(0, Qt::UserRole).toInt();
        if (line > 0) Q_EMIT locationActivated(line, item->data(0, Qt::UserRole + 1).toInt());
    });
    showAssignment();
}

const courseware::Assignment* AssignmentPanel::assignment() const {
    if (current_ < 0 || std::size_t(current_) >= assignments_.size()) return nullptr;
    const auto& a = assignments_[std::size_t(current_)].assignment;
    return a ? &*a : nullptr;
}

bool AssignmentPanel::choose(const QString& id) {
    for (std::size_t i = 0; i < assignments_.size(); ++i)
        if (assignments_[i].assignment && assignments_[i].assignment->id == id.toStdString()) {
            choice_->setCurrentIndex(int(i) + 1);
            return true;
        }
    return false;
}

bool AssignmentPanel::checking() const {
    return checker_.busy();
}

void AssignmentPanel::showAssignment() {
    checklist_->clear();
    report_.reset();
    const courseware::Assignment* a = assignment();
    starter_->setEnabled(a && !a->starters.empty());
    if (!a) {
        instructions_->setMarkdown(
            current_ < 0 ? tr("Choose an assignment to see its instructions and a checklist of "
                              "its requirements as you edit.")
                         : tr("This assignment's manifest has errors; see `functionlab grade "
                              "check --assignment` for where."));
        status_->clear();
        return;
    }
    QFile file(QString::fromStdString(a->instructions.string()));
    instructions_->showMarkdown(file.open(QIODevice::ReadOnly)
                                    ? QString::fromUtf8(file.read(1 << 20))
                                    : tr("(no instructions)"));
    for (const grading::Requirement& r : a->requirements) {
        auto* item = new QTreeWidgetItem(checklist_, {QString::fromStdString(r.id), {}});
        item->setToolTip(0, plainToolTip(QString::fromStdString(r.description)));
        item->setText(1, QString::fromStdString(r.description));
    }
    if (scene_) check(scene_);
}

void AssignmentPanel::sceneChanged(std::shared_ptr<const scene::Scene> scene) {
    scene_ = std::move(scene);
    if (assignment()) check(scene_);
}

void AssignmentPanel::check(std::shared_ptr<const scene::Scene> scene) {
    status_->setText(tr("checking…"));
    checker_.request({std::move(scene), current_, assignment()->requirements});
}

void AssignmentPanel::showReport(const grading::CheckReport& report) {
    report_ = report;
    const std::string mainFile = scene_ ? scene_->pathOf(0) : std::string{};
    for (int i = 0; i < checklist_->topLevelItemCount(); ++i) {
        QTreeWidgetItem* item = checklist_->topLevelItem(i);
        if (std::size_t(i) >= report.requirements.size()) break;
        const grading::RequirementResult& r = report.requirements[std::size_t(i)];
        item->setText(0, QStringLiteral("%1 %2  (%3/%4)")
                             .arg(r.met ? QStringLiteral("✔") : QStringLiteral("✘"))
                             .arg(QString::fromStdString(r.id))
                             .arg(points(r.points))
                             .arg(points(r.maxPoints)));
        item->setForeground(0, r.met ? QColor(0x2e, 0x7d, 0x32) : QColor(0xc6, 0x28, 0x28));
        item->setText(1, QString::fromStdString(r.evidence));
        item->setToolTip(1, plainToolTip(QString::fromStdString(r.evidence)));
        // The first place in the scene text itself (not in an Inline file).
        item->setData(0, Qt::UserRole, 0);
        for (const grading::Location& l : r.locations)
            if (l.file == mainFile) {
                item->setData(0, Qt::UserRole, l.line);
                item->setData(0, Qt::UserRole + 1, l.column);
                break;
            }
    }
    status_->setText(report.gradable
                         ? tr("%1 of %2 points from the checker; your instructor grades %3 more")
                               .arg(points(report.score))
                               .arg(points(report.maxScore))
                               .arg(points(assignment() ? assignment()->manualPoints() : 0))
                         : tr("the scene cannot be graded yet: fix the errors in Issues"));
    Q_EMIT checked();
}

void AssignmentPanel::attach(PanelContext& context) {
    context_ = &context;
    connect(this, &AssignmentPanel::locationActivated, this,
            [&context](int line, int column) { context.goTo(line, column); });
    connect(this, &AssignmentPanel::starterChosen, this, [this, &context](const QString& path) {
        const courseware::Assignment* a = assignment();
        if (a && context.keepChanges())
            openWorkingCopy(context, path, QString::fromStdString(a->id));
    });
    context.fileMenu->addAction(tr("&Hand In…"), this, &AssignmentPanel::handInDialog);
}

void AssignmentPanel::handInDialog() {
    PanelContext& c = *context_;
    // Checked first: what cannot be handed in is said before any dialog.
    if (!readyToHandIn()) return;
    const QString path = c.path();
    const QString name = QStringLiteral("%1-%2").arg(QFileInfo(path).completeBaseName(),
                                                     QString::fromStdString(assignment()->id));
    // The submission's own folder, a new one: typed as a name, made here.
    const QString folder =
        QFileDialog::getSaveFileName(c.window, tr("Hand in: a new folder for your submission"),
                                     QDir(QFileInfo(path).path()).filePath(name), QString(),
                                     nullptr, QFileDialog::DontConfirmOverwrite);
    if (folder.isEmpty()) return;
    if (handIn(folder) && c.prompts())
        informPlainly(c.window, tr("Handed in"),
                      tr("Your submission is in %1.\n%2").arg(folder, c.status->currentMessage()));
}

bool AssignmentPanel::readyToHandIn() {
    PanelContext& c = *context_;
    if (!assignment()) {
        c.problem(tr("Choose the assignment in the Assignment panel first."));
        return false;
    }
    if (c.path().isEmpty()) {
        c.problem(tr("Save the scene first: a submission is a scene file and what it uses."));
        return false;
    }
    if (!c.parser->lastGoodScene() || !c.textParses()) {
        c.problem(tr("The scene has errors: fix them (see Issues) before handing in."));
        return false;
    }
    return true;
}

bool AssignmentPanel::handIn(const QString& folder) {
    PanelContext& c = *context_;
    if (!readyToHandIn()) return false;
    const courseware::Assignment* a = assignment();
    const QString path = c.path();
    // The editor's scene, not the one shown (a class's past, replayed).
    const auto scene = c.parser->lastGoodScene();
    // The last check, on this very text, before it leaves.
    const grading::CheckReport report = grading::checkScene(*scene, a->requirements);
    const courseware::HandIn done = courseware::packSubmission(
        *scene, path.toStdString(), c.editor->toPlainText().toStdString(), folder.toStdString());
    if (!done.ok) {
        c.problem(tr("Not handed in: %1")
                      .arg(QString::fromStdString(done.problems.empty() ? "" : done.problems[0])));
        return false;
    }
    c.status->showMessage(tr("Handed in %1 file(s); the checker gives %2 of %3 points%4")
                              .arg(done.packed.size())
                              .arg(report.score)
                              .arg(report.maxScore)
                              .arg(done.problems.empty()
                                       ? QString()
                                       : tr(" (%1 file(s) not packed: %2)")
                                             .arg(done.problems.size())
                                             .arg(QString::fromStdString(done.problems[0]))));
    return true;
}

} // namespace fl::suite
