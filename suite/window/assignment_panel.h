#pragma once
// The Assignment panel: pick a lab, read its instructions, and watch a live
// checklist of its requirements as you edit — the same checker `functionlab
// grade check` runs, on a worker thread (only the newest scene is checked;
// the interface never waits). Each requirement says why it is met or what
// is missing; activating one jumps to its place in the scene text.
#include "panel.h"

#include "courseware/assignment.h"
#include "grading/checker.h"

#include "platform/newest_only_worker.h"

#include <memory>
#include <optional>
#include <vector>

class QComboBox;
class QLabel;
class QPushButton;
class QTextBrowser;
class QTreeWidget;

namespace fl::suite {

class OfflineTextBrowser;

class AssignmentPanel : public Panel {
    Q_OBJECT
  public:
    // `folder`: where the assignments are (the courseware's by default).
    explicit AssignmentPanel(QWidget* parent = nullptr, const QString& folder = {});

    const courseware::Assignment* assignment() const;
    bool choose(const QString& id); // false when there is no such assignment
    // The last report for the newest scene (none while checking or before).
    const std::optional<grading::CheckReport>& report() const { return report_; }
    bool checking() const;

    QTreeWidget* checklist() const { return checklist_; }
    QTextBrowser* instructions() const;
    QLabel* status() const { return status_; }

    // Its place in the window: requirements and the starter open in the
    // editor; File → Hand In.
    void attach(PanelContext& context) override;
    // Hand in: checks once more, then packs the scene and the files it uses
    // into `folder` (a new one). False, said through the window, if not.
    bool handIn(const QString& folder);
    // What Hand In checks before it asks where: an assignment chosen, the
    // scene saved and without errors (said when not).
    bool readyToHandIn();
    bool busy() const override { return checking(); }

  public Q_SLOTS:
    void sceneChanged(std::shared_ptr<const fl::scene::Scene> scene) override;

  Q_SIGNALS:
    // A requirement's place in the scene text (line and column from 1).
    void locationActivated(int line, int column);
    // "Start from the starter": the scene to open.
    void starterChosen(const QString& path);
    // A new report is shown.
    void checked();

  private:
    void handInDialog();
    void showAssignment();
    void check(std::shared_ptr<const scene::Scene> scene);
    void showReport(const grading::CheckReport& report);

    std::vector<courseware::AssignmentLoad> assignments_;
    int current_ = -1;
    QComboBox* choice_;
    OfflineTextBrowser* instructions_;
    QTreeWidget* checklist_;
    QLabel* status_;
    QPushButton* starter_;
    std::shared_ptr<const scene::Scene> scene_;
    std::optional<grading::CheckReport> report_;
    PanelContext* context_ = nullptr;

    // One check at a time on a worker, the newest scene next.
    struct Check {
        std::shared_ptr<const scene::Scene> scene;
        int assignment; // current_ when asked
        std::vector<grading::Requirement> requirements;
    };
    platform::NewestOnlyWorker<Check, grading::CheckReport> checker_;
};

} // namespace fl::suite
