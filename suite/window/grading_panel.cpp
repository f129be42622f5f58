#include "grading_panel.h"

#include "courseware/catalogue.h"
#include "grading/checker.h"
#include "grading/signing.h"
#include "offline_text_browser.h"
#include "plain_text.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QPushButton>
#include <QScreen>
#include <QSignalBlocker>
#include <QSplitter>
#include <QTableWidget>
#include <QTextBrowser>
#include <QVBoxLayout>

#include <cstdlib>
#include <fstream>
#include <map>
#include <utility>

namespace fl::suite {
namespace {

QString number(double v) {
    return QString::number(v, 'g', 6);
}

QString graderName() {
    const char* user = std::getenv("USER");
    return user && *user ? QString::fromUtf8(user) : QStringLiteral("instructor");
}

} // namespace

GradingPanel::GradingPanel(QWidget* parent)
    : Panel(tr("Grading"), QStringLiteral("grading"), Qt::BottomDockWidgetArea, parent),
      assignments_(new QComboBox), table_(new QTableWidget), evidence_(new OfflineTextBrowser),
      rubric_(new QFormLayout), rubricBox_(new QWidget), override_(new QDoubleSpinBox),
      overrideWhy_(new QLineEdit), overrideStatus_(plainLabel()), summary_(plainLabel()),
      integrity_(plainLabel()) {
    auto* box = new QWidget;
    auto* layout = new QVBoxLayout(box);
    auto* top = new QHBoxLayout;
    top->addWidget(new QLabel(tr("Assignment:")));
    top->addWidget(assignments_, 1);
    top->addWidget(summary_, 2);
    layout->addLayout(top);
    integrity_->setWordWrap(true);
    layout->addWidget(integrity_);
    auto* split = new QSplitter;
    split->addWidget(table_);
    auto* details = new QWidget;
    auto* detailsLayout = new QVBoxLayout(details);
    detailsLayout->addWidget(evidence_, 2);
    rubricBox_->setLayout(rubric_);
    detailsLayout->addWidget(rubricBox_);
    auto* save = new QPushButton(tr("Save rubric scores"));
    detailsLayout->addWidget(save);
    auto* overrideRow = new QHBoxLayout;
    override_->setRange(0, 1e6);
    override_->setDecimals(2);
    overrideWhy_->setPlaceholderText(tr("why (kept with the override)"));
    overrideRow->addWidget(new QLabel(tr("Override:")));
    overrideRow->addWidget(override_);
    overrideRow->addWidget(overrideWhy_, 1);
    auto* setOverride = new QPushButton(tr("Set"));
    overrideRow->addWidget(setOverride);
    detailsLayout->addLayout(overrideRow);
    overrideStatus_->setWordWrap(true);
    detailsLayout->addWidget(overrideStatus_);
    auto* open = new QPushButton(tr("Open the submission in the viewer"));
    detailsLayout->addWidget(open);
    split->addWidget(details);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 2);
    layout->addWidget(split, 1);
    setWidget(box);
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    table_->setSelectionMode(QAbstractItemView::SingleSelection);
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->verticalHeader()->hide();

    connect(assignments_, &QComboBox::currentIndexChanged, this, [this] { fillTable(); });
    connect(table_, &QTableWidget::itemSelectionChanged, this, [this] {
        const auto rows = table_->selectionModel()->selectedRows();
        student_ = rows.isEmpty() ? QString() : table_->item(rows.front().row(), 0)->text();
        showStudent();
    });
    connect(save, &QPushButton::clicked, this, [this] { saveManualScores(); });
    connect(setOverride, &QPushButton::clicked, this, [this] { saveOverride(); });
    connect(overrideWhy_, &QLineEdit::textEdited, overrideStatus_, &QLabel::clear);
    connect(open, &QPushButton::clicked, this, [this] {
        if (const grading::GradeRecord* g = gradeOf(student_); g && !g->path.empty())
            Q_EMIT openSubmission(QString::fromStdString(g->path));
    });
}

bool GradingPanel::openGradebook(const QString& path, const QString& assignmentId, QString* error) {
    try {
        book_ = std::make_unique<grading::Gradebook>(path.toStdString());
    } catch (const std::exception& e) {
        if (error) *error = QString::fromStdString(e.what());
        return false;
    }
    const QSignalBlocker quiet(assignments_);
    assignments_->clear();
    for (const grading::AssignmentRecord& a : book_->assignments())
        assignments_->addItem(QString::fromStdString(a.title), QString::fromStdString(a.id));
    if (assignments_->count() == 0) {
        if (error) *error = tr("the gradebook has no assignment yet: run functionlab grade batch");
        return false;
    }
    const int at = assignmentId.isEmpty() ? 0 : assignments_->findData(assignmentId);
    assignments_->setCurrentIndex(std::max(0, at));
    fillTable();
    signAndVerify(false);
    return true;
}

void GradingPanel::signAndVerify(bool sign) {
    if (!book_) return;
    try {
        if (sign)
            if (const std::string path = grading::defaultSigningKeyPath(); !path.empty()) {
                std::string why;
                if (const auto key = grading::readSigningKey(path, why)) book_->signHead(*key);
            }
        const grading::GradebookCheck c = book_->verify();
        QString text;
        if (!c.intact) {
            text = tr("NOT INTACT: %1").arg(QString::fromStdString(c.problem));
        } else {
            text = tr("Intact: %1 entries in the log; the tables are what it says.").arg(c.entries);
            if (c.signedHead)
                text +=
                    QLatin1Char(' ') +
                    tr("Signed at entry %1 with key %2…%3")
                        .arg(c.signedHead->head.seq)
                        .arg(QString::fromStdString(c.signedHead->publicKey.substr(0, 12)))
                        .arg(c.unsignedEntries
                                 ? tr("; %1 entries since, not yet signed").arg(c.unsignedEntries)
                                 : QString());
            else
                text += QLatin1Char(' ') + tr("Not signed (functionlab grade key new).");
        }
        integrity_->setText(text);
        integrity_->setStyleSheet(c.intact ? QString() : QStringLiteral("color: #c62828"));
    } catch (const std::exception& e) {
        integrity_->setText(tr("cannot be verified: %1").arg(QString::fromStdString(e.what())));
    }
}

const grading::GradeRecord* GradingPanel::gradeOf(const QString& student) const {
    for (const grading::GradeRecord& g : grades_)
        if (QString::fromStdString(g.student) == student) return &g;
    return nullptr;
}

void GradingPanel::fillTable() {
    if (!book_) return;
    // Rebuilding the rows is no choice of the grader's: the student shown
    // stays selected (selectStudent below).
    const QSignalBlocker quiet(table_->selectionModel());
    const QString keep = std::exchange(student_, QString());
    const std::string id = assignments_->currentData().toString().toStdString();
    for (const grading::AssignmentRecord& a : book_->assignments())
        if (a.id == id) record_ = a;
    const courseware::AssignmentLoad load = courseware::findAssignment(id);
    assignment_ = load.assignment;
    grades_ = book_->latestGrades(id);
    std::vector<std::string> requirementIds;
    if (assignment_)
        for (const grading::Requirement& r : assignment_->requirements)
            requirementIds.push_back(r.id);
    else if (!grades_.empty())
        for (const grading::RequirementResult& r : grades_.front().requirements)
            requirementIds.push_back(r.id);
    QStringList headers{tr("student"), tr("name")};
    for (const std::string& r : requirementIds)
        headers << QString::fromStdString(r);
    headers << tr("automatic") << tr("late") << tr("manual") << tr("override") << tr("final");
    table_->clear();
    table_->setColumnCount(int(headers.size()));
    table_->setHorizontalHeaderLabels(headers);
    table_->setRowCount(int(grades_.size()));
    std::map<std::string, grading::Student> names;
    for (grading::Student& s : book_->students())
        names[s.id] = std::move(s);
    double sum = 0;
    for (std::size_t row = 0; row < grades_.size(); ++row) {
        const grading::GradeRecord& g = grades_[row];
        int column = 0;
        auto cell = [&](const QString& text, const QString& tip = {}) {
            auto* item = new QTableWidgetItem(text);
            item->setToolTip(plainToolTip(tip));
            table_->setItem(int(row), column++, item);
            return item;
        };
        cell(QString::fromStdString(g.student));
        cell(QString::fromStdString(names.count(g.student) ? names.at(g.student).name : ""));
        for (const std::string& id : requirementIds) {
            const grading::RequirementResult* found = nullptr;
            for (const auto& r : g.requirements)
                if (r.id == id) found = &r;
            QTableWidgetItem* item =
                cell(found ? (found->met ? QStringLiteral("✔ ") : QStringLiteral("✘ ")) +
                                 number(found->points)
                           : QStringLiteral("–"),
                     found ? QString::fromStdString(found->evidence) : QString());
            if (found)
                item->setForeground(found->met ? QColor(0x2e, 0x7d, 0x32)
                                               : QColor(0xc6, 0x28, 0x28));
        }
        cell(g.gradable ? number(g.score) : tr("not gradable"),
             QString::fromStdString(g.diagnostics));
        cell(g.lateFactor < 1 ? QStringLiteral("×") + number(g.lateFactor) : QString());
        cell(number(book_->manualPoints(g.student, g.assignment)));
        const auto o = book_->overrideScore(g.student, g.assignment);
        cell(o ? number(*o) : QString());
        const double final = book_->finalScore(g);
        sum += final;
        cell(number(final));
    }
    table_->resizeColumnsToContents();
    summary_->setText(
        tr("%1 students; mean final score %2 of %3")
            .arg(grades_.size())
            .arg(grades_.empty() ? QStringLiteral("–") : number(sum / double(grades_.size())))
            .arg(number(record_.maxAutomatic + record_.maxManual)));
    if (!keep.isEmpty()) selectStudent(keep);
    showStudent();
}

void GradingPanel::selectStudent(const QString& id) {
    for (int row = 0; row < table_->rowCount(); ++row)
        if (table_->item(row, 0)->text() == id) {
            table_->selectRow(row);
            student_ = id;
            showStudent();
            return;
        }
}

void GradingPanel::showStudent() {
    // Rebuild the rubric editors for this student.
    while (rubric_->rowCount() > 0)
        rubric_->removeRow(0);
    editors_.clear();
    const grading::GradeRecord* g = gradeOf(student_);
    if (!g || !book_) {
        evidence_->setPlainText(tr("Select a student."));
        return;
    }
    QString text =
        QStringLiteral("<b>%1</b> — submitted %2, graded %3 by checker %4<br/>")
            .arg(student_.toHtmlEscaped(), QString::fromStdString(g->submittedAt).toHtmlEscaped(),
                 QString::fromStdString(g->gradedAt).toHtmlEscaped(),
                 QString::fromStdString(g->checkerVersion).toHtmlEscaped());
    if (!g->gradable)
        text += QStringLiteral("<p style='color:#c62828'>%1</p>")
                    .arg(QString::fromStdString(g->diagnostics).toHtmlEscaped());
    for (const grading::RequirementResult& r : g->requirements)
        text += QStringLiteral("<p><b style='color:%1'>%2 %3</b> (%4/%5): %6</p>")
                    .arg(r.met ? QStringLiteral("#2e7d32") : QStringLiteral("#c62828"),
                         r.met ? QStringLiteral("✔") : QStringLiteral("✘"),
                         QString::fromStdString(r.id).toHtmlEscaped(), number(r.points),
                         number(r.maxPoints), QString::fromStdString(r.evidence).toHtmlEscaped());
    evidence_->setHtml(text);
    const auto scores = book_->manualScores(g->student, g->assignment);
    if (assignment_)
        for (const courseware::RubricItem& item : assignment_->rubric) {
            auto* points = new QDoubleSpinBox;
            points->setRange(0, item.points);
            points->setDecimals(1);
            auto* comment = new QLineEdit;
            comment->setPlaceholderText(tr("comment for the student"));
            for (const grading::ManualScore& s : scores)
                if (s.item == item.id) {
                    points->setValue(s.points);
                    comment->setText(QString::fromStdString(s.comment));
                }
            auto* row = new QWidget;
            auto* rowLayout = new QHBoxLayout(row);
            rowLayout->setContentsMargins(0, 0, 0, 0);
            rowLayout->addWidget(points);
            rowLayout->addWidget(comment, 1);
            rubric_->addRow(
                plainLabel(QStringLiteral("%1 (of %2)")
                               .arg(QString::fromStdString(item.id), number(item.points))),
                row);
            row->setToolTip(plainToolTip(QString::fromStdString(item.description)));
            editors_.push_back({QString::fromStdString(item.id), points, comment});
        }
    const auto o = book_->overrideScore(g->student, g->assignment);
    override_->setValue(o.value_or(0));
}

QDoubleSpinBox* GradingPanel::rubricPoints(const QString& item) const {
    for (const RubricEditor& e : editors_)
        if (e.item == item) return e.points;
    return nullptr;
}

QLineEdit* GradingPanel::rubricComment(const QString& item) const {
    for (const RubricEditor& e : editors_)
        if (e.item == item) return e.comment;
    return nullptr;
}

void GradingPanel::saveManualScores() {
    const grading::GradeRecord* g = gradeOf(student_);
    if (!g || !book_) return;
    for (const RubricEditor& e : editors_)
        book_->setManualScore(g->student, g->assignment, e.item.toStdString(), e.points->value(),
                              e.comment->text().toStdString(), graderName().toStdString());
    fillTable();
    signAndVerify(true);
}

bool GradingPanel::saveOverride(QString* error) {
    const grading::GradeRecord* g = gradeOf(student_);
    if (!g || !book_) {
        overrideStatus_->setText(tr("Choose a student first."));
        if (error) *error = overrideStatus_->text();
        return false;
    }
    if (overrideWhy_->text().trimmed().isEmpty()) {
        // Said beside the field, not only to the caller (it was refused silently).
        overrideStatus_->setText(
            tr("Not set: an override needs a reason, kept with it in the gradebook's log."));
        if (error) *error = tr("an override needs a reason");
        overrideWhy_->setFocus();
        return false;
    }
    book_->addOverride(g->student, g->assignment, override_->value(), graderName().toStdString(),
                       overrideWhy_->text().toStdString());
    overrideWhy_->clear();
    overrideStatus_->setText(
        tr("Override %1 set for %2.")
            .arg(number(override_->value()), QString::fromStdString(g->student)));
    fillTable();
    signAndVerify(true);
    return true;
}

bool GradingPanel::exportTo(const QString& path, grading::ExportFormat format, QString* error) {
    if (!book_) return false;
    try {
        if (format == grading::ExportFormat::Gradescope) {
            grading::exportGradescope(*book_, record_, path.toStdString());
            return true;
        }
        std::ofstream out(path.toStdString(), std::ios::binary);
        out << grading::exportCsvText(*book_, record_, format);
        if (!out) throw std::runtime_error("cannot write " + path.toStdString());
    } catch (const std::exception& e) {
        if (error) *error = QString::fromStdString(e.what());
        return false;
    }
    return true;
}

void GradingPanel::attach(PanelContext& context) {
    context_ = &context;
    hide(); // until a gradebook is open
    connect(this, &GradingPanel::openSubmission, this, [&context](const QString& where) {
        const QString file = QString::fromStdString(grading::sceneFileOf(where.toStdString()));
        if (context.keepChanges()) context.open(file.isEmpty() ? where : file);
    });
    context.courseMenu->addAction(tr("Open &Gradebook…"), this, &GradingPanel::gradebookDialog);
    context.courseMenu->addAction(tr("&Export Grades…"), this, &GradingPanel::exportDialog);
}

void GradingPanel::gradebookDialog() {
    const QString path =
        QFileDialog::getOpenFileName(context_->window, tr("Open a gradebook"), QString(),
                                     tr("Gradebooks (*.sqlite *.db);;All (*)"));
    if (path.isEmpty()) return;
    QString why;
    if (!openGradebook(path, {}, &why)) {
        context_->problem(tr("Cannot open the gradebook %1: %2").arg(path, why));
        return;
    }
    showBeside();
}

void GradingPanel::showBeside() {
    // A class's table wants room the window's docks do not have (docked, it
    // also grew the window past a laptop's screen): a window of its own,
    // most of the screen, over the main window.
    if (!isFloating()) {
        setFloating(true);
        const QRect screen = (context_ && context_->window->screen())
                                 ? context_->window->screen()->availableGeometry()
                                 : QRect(0, 0, 1280, 800);
        resize(screen.width() * 3 / 4, screen.height() * 3 / 4);
        move(screen.center() - rect().center());
    }
    show();
    raise();
}

void GradingPanel::exportDialog() {
    if (!book_) {
        context_->problem(tr("Open a gradebook first (Course → Open Gradebook)."));
        return;
    }
    // The format is the chosen line, matched whole (a translated label is
    // never read for its first word).
    const std::pair<QString, grading::ExportFormat> formats[] = {
        {tr("Canvas CSV (*.csv)"), grading::ExportFormat::Canvas},
        {tr("Moodle CSV (*.csv)"), grading::ExportFormat::Moodle},
        {tr("Full CSV (*.csv)"), grading::ExportFormat::Csv},
        {tr("Gradescope folder (*)"), grading::ExportFormat::Gradescope}};
    QStringList filters;
    for (const auto& [label, format] : formats)
        filters << label;
    QString chosen;
    const QString path = QFileDialog::getSaveFileName(context_->window, tr("Export grades"),
                                                      QString(), filters.join(";;"), &chosen);
    if (path.isEmpty()) return;
    grading::ExportFormat format = grading::ExportFormat::Csv;
    for (const auto& [label, f] : formats)
        if (label == chosen) format = f;
    QString why;
    if (!exportTo(path, format, &why)) context_->problem(tr("Not exported: %1").arg(why));
}

} // namespace fl::suite
