#pragma once
// The Classroom panel (issue 17 §1, §3, §5; docs/classroom.md): join a
// class's server, see who is in it and who holds the lock, chat and type
// modelling commands, send the editor's scene as an edit, have an edit
// refused under another's lock kept and offered again when the lock is
// free, and use the modelling tools at the marked point — remove material,
// deposit it, or paint — each a chat command through the same protocol, so
// locked, checked, logged and undoable like any edit. An instructor also
// freezes the class, pushes a scene, takes snapshots, shows names
// anonymised and takes or breaks locks.
#include "panel.h"

#include "classroom/protocol.h"
#include "field/vec3.h"

#include <functional>
#include <memory>
#include <optional>

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;
class QSlider;
class QWidget;

namespace fl::classroom {
class ClassroomClient;
}

namespace fl::suite {

class ClassroomPanel : public Panel {
    Q_OBJECT
  public:
    explicit ClassroomPanel(QWidget* parent = nullptr);
    ~ClassroomPanel() override;

    // Where the scene the student edits comes from (the window's editor).
    void setTextSource(std::function<QString()> source) { text_ = std::move(source); }

    // Its place in the window: the editor's text is what it sends, the
    // class's scene comes into the editor and the view, a chosen point of
    // the scene is the tools' place; File → Join Class.
    void attach(PanelContext& context) override;

    // Joins (a student unless `role` says otherwise), once unsaved work in
    // the editor is saved or kept; the answer comes as signals and in the panel.
    void join(const QString& url, const QString& classCode, const QString& name,
              classroom::Role role = classroom::Role::Student, const QString& key = {});
    classroom::Role chosenRole() const;
    void leave();
    // Sends the editor's text as an edit (taking the lock).
    void sendEdit();
    void sendChat(const QString& text);
    // The tool's place: a point on the class shape, in its own coordinates,
    // and the shape's size there (tools are a fraction of it); none: unmarked.
    void setToolPoint(std::optional<field::Vec3> point, double shapeSize = 1);
    enum class Tool { Remove, Deposit, Paint };
    // The command the tool sends at the marked point ("" when nothing is marked).
    QString toolCommand(Tool tool) const;
    bool useTool(Tool tool);

    classroom::ClassroomClient* client() const { return client_.get(); }
    QListWidget* members() const { return members_; }
    QListWidget* chat() const { return chat_; }
    QLabel* lockStatus() const { return lock_; }
    QLabel* pendingStatus() const { return pending_; }
    QPushButton* applyPendingButton() const { return applyPending_; }
    QLineEdit* urlField() const { return url_; }
    QSlider* history() const { return history_; }
    // The class's scene at `version`, asked of the server; comes back as
    // historyShown (the window shows it until the replay is left).
    void replay(qint64 version);
    void leaveReplay();
    bool replaying() const { return replaying_; }
    bool holdsTheView() const override { return replaying_; }
    // The function description of the version shown in the replay (else the
    // newest) as X3D XML; empty with `why` when there is nothing to export.
    QString exportX3d(QString* why = nullptr) const;

  Q_SIGNALS:
    // A version of the history to show (the text), or the end of the replay (empty).
    void historyShown(const QString& text, qint64 version);
    // A new shared scene (from anyone, the student's own applied edit too):
    // the window shows it in the editor and the view.
    void sharedSceneChanged(const QString& text, qint64 version, const QString& author);

  private:
    // The class's scene into the editor, never over unsent work (the
    // student sends it, or undoes it to see the class's).
    void showSharedScene(const QString& text, qint64 version, const QString& author);
    void refreshMembers();
    void refreshLock();
    void refreshState();
    void say(const QString& line); // into the chat view, as the panel's own note

    PanelContext* context_ = nullptr;
    QString lastSharedScene_; // the class's scene as last shown in the editor
    std::unique_ptr<classroom::ClassroomClient> client_;
    std::function<QString()> text_;
    std::optional<field::Vec3> toolPoint_;
    double shapeSize_ = 1;
    QLineEdit *url_, *code_, *name_, *key_, *say_;
    QComboBox *role_, *tool_, *paint_;
    QSlider *toolSize_, *history_;
    QLabel* historyLabel_;
    bool replaying_ = false;
    qint64 replayVersion_ = 0;
    QString replayText_;
    QPushButton *join_, *send_, *release_, *applyPending_, *discardPending_, *useTool_;
    QLabel *state_, *lock_, *pending_;
    QListWidget *members_, *chat_;
    QWidget* instructor_;
    QCheckBox *freeze_, *anonymous_;
};

} // namespace fl::suite
