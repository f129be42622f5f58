#pragma once
// The instructor's Grading panel: a class's gradebook as a table — students
// by requirements, automatic, manual, override and final scores — and, for
// the selected student, each requirement's evidence, the rubric items to
// score with comments, an override with its reason, and the submission to
// open in the viewer. Everything is written to the SQLite gradebook as it
// is entered (a batch may write beside it: WAL); exports from the same file.
#include "panel.h"

#include "courseware/assignment.h"
#include "grading/grade_export.h"
#include "grading/gradebook.h"

#include <memory>
#include <optional>
#include <vector>

class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QTableWidget;
class QTextBrowser;

namespace fl::suite {

class GradingPanel : public Panel {
    Q_OBJECT
  public:
    explicit GradingPanel(QWidget* parent = nullptr);
    // Its place in the window: Course → Open Gradebook and Export Grades; a
    // submission opens in the editor. Hidden until a gradebook is open.
    void attach(PanelContext& context) override;

    // Opens a gradebook and shows `assignmentId` (or its first assignment).
    // False, with `error`, when it cannot be read.
    bool openGradebook(const QString& path, const QString& assignmentId = {},
                       QString* error = nullptr);
    QTableWidget* table() const { return table_; }
    // The student whose details are shown (empty: none selected).
    QString selectedStudent() const { return student_; }
    void selectStudent(const QString& id);
    // The details' editors: one per rubric item, and the override.
    QDoubleSpinBox* rubricPoints(const QString& item) const;
    QLineEdit* rubricComment(const QString& item) const;
    QDoubleSpinBox* overrideScore() const { return override_; }
    QLineEdit* overrideReason() const { return overrideWhy_; }
    // What the last override said (refused for want of a reason, or set).
    QLabel* overrideStatus() const { return overrideStatus_; }
    // Shows the panel as a window of its own over the main window, most of
    // the screen (Course → Open Gradebook does, once a gradebook is open).
    void showBeside();
    // Writes what the editors hold for the selected student.
    void saveManualScores();
    bool saveOverride(QString* error = nullptr);
    bool exportTo(const QString& path, grading::ExportFormat format, QString* error = nullptr);
    // Whether the gradebook is what its log says, and who signed it.
    QLabel* integrityStatus() const { return integrity_; }

  Q_SIGNALS:
    void openSubmission(const QString& path);

  private:
    void gradebookDialog();
    void exportDialog();
    PanelContext* context_ = nullptr;
    void fillTable();
    // After a change: the head signed with the instructor's key when there is
    // one (FUNCTIONLAB_GRADING_KEY or ~/.config/functionlab/grading.key),
    // then the gradebook verified again.
    void signAndVerify(bool sign);
    void showStudent();
    const grading::GradeRecord* gradeOf(const QString& student) const;

    std::unique_ptr<grading::Gradebook> book_;
    std::optional<courseware::Assignment> assignment_; // from the courseware, when found
    grading::AssignmentRecord record_;
    std::vector<grading::GradeRecord> grades_;
    QString student_;

    QComboBox* assignments_;
    QTableWidget* table_;
    QTextBrowser* evidence_;
    QFormLayout* rubric_;
    QWidget* rubricBox_;
    QDoubleSpinBox* override_;
    QLineEdit* overrideWhy_;
    QLabel* overrideStatus_;
    QLabel* summary_;
    QLabel* integrity_;
    struct RubricEditor {
        QString item;
        QDoubleSpinBox* points;
        QLineEdit* comment;
    };
    std::vector<RubricEditor> editors_;
};

} // namespace fl::suite
