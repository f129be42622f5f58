#include "classroom_panel.h"

#include "editor/code_editor.h"
#include "editor/live_parser.h"
#include "plain_text.h"
#include "viewer/scene_widget.h"

#include "classroom/client.h"
#include "classroom/scene_policy.h"
#include "mesh/scene_meshing.h"

#include "scene/scene_reader.h"
#include "scene/scene_writer.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QPushButton>
#include <QSaveFile>
#include <QShortcut>
#include <QSlider>
#include <QStatusBar>
#include <QTextDocument>
#include <QUrl>
#include <QVBoxLayout>

namespace fl::suite {

using classroom::ClassroomClient;

namespace {

QString reasonText(const ClassroomClient::Refusal& r) {
    switch (r.reason) {
    case classroom::RefusalReason::Locked:
        return ClassroomPanel::tr("%1 holds the lock; your edit is kept and offered again when "
                                  "the lock is free")
            .arg(r.holder);
    case classroom::RefusalReason::Stale:
        return ClassroomPanel::tr("the scene changed since your version; your edit is kept: "
                                  "apply it on the new scene, or discard it");
    case classroom::RefusalReason::Invalid:
        return ClassroomPanel::tr("the scene has errors: %1").arg(r.message);
    case classroom::RefusalReason::ReadOnly:
        return ClassroomPanel::tr("read-only: %1").arg(r.message);
    case classroom::RefusalReason::Rate:
        return ClassroomPanel::tr("too many edits at once: wait a moment");
    case classroom::RefusalReason::TooLarge:
        return ClassroomPanel::tr("too large: %1").arg(r.message);
    case classroom::RefusalReason::TooCostly:
        return ClassroomPanel::tr("it would cost every window in the class too much work: %1")
            .arg(r.message);
    }
    return r.message;
}

// A number as a formula writes it: short, exact enough for a tool.
QString num(double v) {
    return QString::number(v, 'g', 6);
}

} // namespace

ClassroomPanel::ClassroomPanel(QWidget* parent)
    : Panel(tr("Classroom"), QStringLiteral("classroom"), Qt::RightDockWidgetArea, parent),
      client_(std::make_unique<ClassroomClient>()), url_(new QLineEdit), code_(new QLineEdit),
      name_(new QLineEdit), key_(new QLineEdit), say_(new QLineEdit), role_(new QComboBox),
      tool_(new QComboBox), paint_(new QComboBox), toolSize_(new QSlider(Qt::Horizontal)),
      history_(new QSlider(Qt::Horizontal)), historyLabel_(plainLabel()),
      join_(new QPushButton(tr("Join"))), send_(new QPushButton(tr("Send my edit"))),
      release_(new QPushButton(tr("Release lock"))), applyPending_(new QPushButton(tr("Apply"))),
      discardPending_(new QPushButton(tr("Discard"))), useTool_(new QPushButton(tr("Use"))),
      state_(plainLabel()), lock_(plainLabel()), pending_(plainLabel()), members_(new QListWidget),
      chat_(new QListWidget), instructor_(new QWidget), freeze_(new QCheckBox(tr("Freeze"))),
      anonymous_(new QCheckBox(tr("Anonymous names"))) {
    auto* box = new QWidget;
    auto* layout = new QVBoxLayout(box);
    auto* form = new QFormLayout;
    url_->setPlaceholderText(QStringLiteral("ws://127.0.0.1:8765"));
    code_->setPlaceholderText(tr("the class code"));
    name_->setPlaceholderText(tr("your name"));
    key_->setEchoMode(QLineEdit::Password);
    key_->setPlaceholderText(tr("instructor key"));
    for (const classroom::Role r :
         {classroom::Role::Student, classroom::Role::Instructor, classroom::Role::Observer})
        role_->addItem(QString::fromLatin1(classroom::nameOf(r).data(),
                                           qsizetype(classroom::nameOf(r).size())),
                       int(r));
    form->addRow(tr("Server:"), url_);
    form->addRow(tr("Class:"), code_);
    form->addRow(tr("Name:"), name_);
    auto* roleRow = new QHBoxLayout;
    roleRow->addWidget(role_);
    roleRow->addWidget(key_, 1);
    roleRow->addWidget(join_);
    form->addRow(tr("Role:"), roleRow);
    layout->addLayout(form);
    state_->setWordWrap(true); // says why a join stopped
    layout->addWidget(state_);
    // A few members in view, the rest scrolled: the room goes to the chat.
    members_->setMaximumHeight(members_->fontMetrics().lineSpacing() * 7);
    layout->addWidget(members_);
    auto* lockRow = new QHBoxLayout;
    lockRow->addWidget(lock_, 1);
    lockRow->addWidget(send_);
    lockRow->addWidget(release_);
    layout->addLayout(lockRow);
    auto* pendingRow = new QHBoxLayout;
    pending_->setWordWrap(true);
    pendingRow->addWidget(pending_, 1);
    pendingRow->addWidget(applyPending_);
    pendingRow->addWidget(discardPending_);
    layout->addLayout(pendingRow);
    // The tools: at the point marked by a click in the view.
    auto* toolRow = new QHBoxLayout;
    tool_->addItems({tr("remove"), tr("deposit"), tr("paint")});
    paint_->addItems({QStringLiteral("red"), QStringLiteral("green"), QStringLiteral("blue"),
                      QStringLiteral("yellow"), QStringLiteral("orange"), QStringLiteral("purple"),
                      QStringLiteral("white"), QStringLiteral("black")});
    toolSize_->setRange(1, 50);
    toolSize_->setValue(10);
    toolSize_->setToolTip(tr("The tool's radius: 1% to 50% of the shape's size"));
    toolRow->addWidget(new QLabel(tr("Tool:")));
    toolRow->addWidget(tool_);
    toolRow->addWidget(paint_);
    toolRow->addWidget(toolSize_, 1);
    toolRow->addWidget(useTool_);
    layout->addLayout(toolRow);
    // The history: a slider over the versions; the view shows the one chosen.
    auto* historyRow = new QHBoxLayout;
    history_->setRange(1, 1);
    history_->setToolTip(tr("Replay the class's history: the view shows the version chosen"));
    auto* exportButton = new QPushButton(tr("Export…"));
    exportButton->setToolTip(tr("Save the version shown (or the newest) as X3D"));
    auto* back = new QPushButton(tr("Now"));
    historyRow->addWidget(new QLabel(tr("History:")));
    historyRow->addWidget(history_, 1);
    historyRow->addWidget(historyLabel_);
    historyRow->addWidget(back);
    historyRow->addWidget(exportButton);
    layout->addLayout(historyRow);
    connect(history_, &QSlider::sliderReleased, this, [this] { replay(history_->value()); });
    connect(history_, &QSlider::valueChanged, this, [this](int v) {
        if (!history_->isSliderDown()) replay(v);
    });
    connect(back, &QPushButton::clicked, this, &ClassroomPanel::leaveReplay);
    connect(exportButton, &QPushButton::clicked, this, [this] {
        QString why;
        const QString x3d = exportX3d(&why);
        if (x3d.isEmpty()) {
            say(why);
            return;
        }
        const QString path = QFileDialog::getSaveFileName(
            this, tr("Export the class's scene"),
            tr("class-version-%1.x3d").arg(replaying_ ? replayVersion_ : client_->version()),
            tr("X3D (*.x3d)"));
        if (path.isEmpty()) return;
        QSaveFile f(path);
        if (!f.open(QIODevice::WriteOnly) || f.write(x3d.toUtf8()) < 0 || !f.commit())
            say(tr("could not write %1: %2").arg(path, f.errorString()));
        else
            say(tr("saved %1").arg(path));
    });
    chat_->setWordWrap(true);
    chat_->setMinimumHeight(chat_->fontMetrics().lineSpacing() * 8);
    layout->addWidget(chat_, 1);
    say_->setPlaceholderText(tr("chat, or a command: /help"));
    layout->addWidget(say_);
    auto* instructorRow = new QHBoxLayout(instructor_);
    instructorRow->setContentsMargins(0, 0, 0, 0);
    auto* push = new QPushButton(tr("Push my scene"));
    auto* snapshot = new QPushButton(tr("Snapshot"));
    auto* take = new QPushButton(tr("Take lock"));
    auto* brk = new QPushButton(tr("Break lock"));
    for (QWidget* w :
         std::initializer_list<QWidget*>{freeze_, anonymous_, push, snapshot, take, brk})
        instructorRow->addWidget(w);
    layout->addWidget(instructor_);
    setWidget(box);

    connect(join_, &QPushButton::clicked, this, [this] {
        if (client_->state() == ClassroomClient::State::Disconnected)
            join(url_->text(), code_->text(), name_->text(), chosenRole(), key_->text());
        else
            leave();
    });
    connect(send_, &QPushButton::clicked, this, &ClassroomPanel::sendEdit);
    connect(release_, &QPushButton::clicked, client_.get(), &ClassroomClient::releaseLock);
    connect(applyPending_, &QPushButton::clicked, this, [this] {
        if (client_->reofferPendingEdit()) say(tr("your kept edit is sent again"));
    });
    connect(discardPending_, &QPushButton::clicked, client_.get(),
            &ClassroomClient::discardPendingEdit);
    connect(say_, &QLineEdit::returnPressed, this, [this] {
        sendChat(say_->text());
        say_->clear();
    });
    connect(useTool_, &QPushButton::clicked, this,
            [this] { useTool(Tool(std::clamp(tool_->currentIndex(), 0, 2))); });
    connect(tool_, &QComboBox::currentIndexChanged, this,
            [this](int i) { paint_->setEnabled(i == int(Tool::Paint)); });
    connect(freeze_, &QCheckBox::clicked, client_.get(), &ClassroomClient::setFrozen);
    connect(anonymous_, &QCheckBox::clicked, client_.get(), &ClassroomClient::setAnonymous);
    connect(push, &QPushButton::clicked, this, [this] {
        if (text_) client_->pushScene(text_());
    });
    connect(snapshot, &QPushButton::clicked, this,
            [this] { client_->takeSnapshot(tr("snapshot by %1").arg(client_->shownName())); });
    connect(take, &QPushButton::clicked, client_.get(), &ClassroomClient::takeLock);
    connect(brk, &QPushButton::clicked, client_.get(), &ClassroomClient::breakLock);

    ClassroomClient* c = client_.get();
    connect(c, &ClassroomClient::stateChanged, this, [this] {
        // Out of the class (left, refused, cut off): its history with it.
        if (client_->state() == ClassroomClient::State::Disconnected) leaveReplay();
        refreshState();
    });
    connect(c, &ClassroomClient::joined, this, [this](bool resumed) {
        say(resumed ? tr("back in the class (your seat and lock were kept)")
                    : tr("joined the class as %1").arg(client_->shownName()));
        refreshState();
    });
    connect(c, &ClassroomClient::sceneChanged, this,
            [this](qint64 version, const QString& author, const QString& scene) {
                Q_EMIT sharedSceneChanged(scene, version, author);
                const QSignalBlocker quiet(history_);
                history_->setRange(1, int(std::max<qint64>(version, 1)));
                if (!replaying_) history_->setValue(int(version));
                refreshState();
            });
    connect(c, &ClassroomClient::versionReceived, this,
            [this](qint64 version, const QString& author, const QString& scene) {
                if (!replaying_ || version != replayVersion_) return;
                replayText_ = scene;
                historyLabel_->setText(tr("v%1, %2").arg(version).arg(visibleText(author)));
                Q_EMIT historyShown(scene, version);
            });
    connect(c, &ClassroomClient::chatReceived, this,
            [this](const QString& from, const QString& text) {
                // Both come from others: drawn as the characters they hold.
                chat_->addItem(visibleText(from) + QStringLiteral(": ") + visibleText(text, true));
                chat_->scrollToBottom();
            });
    connect(c, &ClassroomClient::noticeReceived, this, [this](const QString& t) { say(t); });
    connect(c, &ClassroomClient::refused, this, [this](const ClassroomClient::Refusal& r) {
        QString line = tr("refused: %1").arg(reasonText(r));
        for (const classroom::RefusalDiagnostic& d : r.diagnostics)
            line += QStringLiteral("\n  %1:%2: %3")
                        .arg(d.line)
                        .arg(d.column)
                        .arg(QString::fromStdString(d.message));
        say(line);
        refreshLock();
    });
    connect(c, &ClassroomClient::errorReceived, this,
            [this](classroom::ErrorCode, const QString& message) {
                say(tr("the server says: %1").arg(message));
            });
    connect(c, &ClassroomClient::membersChanged, this, &ClassroomPanel::refreshMembers);
    connect(c, &ClassroomClient::lockChanged, this, [this] {
        refreshLock();
        refreshMembers();
    });
    connect(c, &ClassroomClient::frozenChanged, this, [this](bool frozen) {
        freeze_->setChecked(frozen);
        say(frozen ? tr("the class is frozen: edits wait") : tr("the class is open again"));
        refreshLock();
    });
    connect(c, &ClassroomClient::saved, this, [this](qint64 version, const QString& label) {
        say(tr("snapshot of version %1 kept: %2").arg(version).arg(label));
    });
    connect(c, &ClassroomClient::pendingEditChanged, this, &ClassroomPanel::refreshLock);
    connect(c, &ClassroomClient::pendingEditCanBeApplied, this, [this] {
        refreshLock();
        pending_->setText(tr("The lock is free: apply your kept edit now?"));
        applyPending_->setEnabled(true);
    });
    auto* sendShortcut = new QShortcut(QKeySequence(Qt::CTRL | Qt::Key_Return), box);
    connect(sendShortcut, &QShortcut::activated, this, &ClassroomPanel::sendEdit);
    refreshState();
}

ClassroomPanel::~ClassroomPanel() = default;

classroom::Role ClassroomPanel::chosenRole() const {
    return classroom::Role(role_->currentData().toInt());
}

void ClassroomPanel::join(const QString& url, const QString& classCode, const QString& name,
                          classroom::Role role, const QString& key) {
    // The class's scene will take the editor: unsaved work is saved or kept first.
    if (context_ && !context_->keepChanges()) return;
    leaveReplay();
    lastSharedScene_.clear();
    show();
    raise();
    const QUrl u(url.trimmed());
    if (!u.isValid() ||
        (u.scheme() != QStringLiteral("ws") && u.scheme() != QStringLiteral("wss"))) {
        say(tr("the server is a ws:// address, e.g. ws://127.0.0.1:8765"));
        return;
    }
    if (classCode.trimmed().isEmpty() || name.trimmed().isEmpty()) {
        say(tr("give the class code and your name"));
        return;
    }
    url_->setText(url);
    code_->setText(classCode);
    name_->setText(name);
    role_->setCurrentIndex(role_->findData(int(role)));
    ClassroomClient::JoinOptions o;
    o.url = u;
    o.classCode = classCode.trimmed();
    o.name = name.trimmed();
    o.role = role;
    o.key = key;
    client_->join(o);
    refreshState();
}

void ClassroomPanel::leave() {
    client_->leave();
    refreshState();
}

void ClassroomPanel::sendEdit() {
    if (!text_ || client_->state() != ClassroomClient::State::Joined) return;
    client_->submitEdit(text_());
}

void ClassroomPanel::sendChat(const QString& text) {
    if (text.trimmed().isEmpty()) return;
    client_->sendChat(text.trimmed());
}

void ClassroomPanel::setToolPoint(std::optional<field::Vec3> point, double shapeSize) {
    toolPoint_ = point;
    shapeSize_ = shapeSize > 0 ? shapeSize : 1;
    useTool_->setEnabled(point.has_value() && client_->state() == ClassroomClient::State::Joined);
}

QString ClassroomPanel::toolCommand(Tool tool) const {
    if (!toolPoint_) return {};
    const field::Vec3& p = *toolPoint_;
    const double r = shapeSize_ * toolSize_->value() / 100.0;
    const QString ball =
        QStringLiteral("sphere(%1, %2, %3, %4)").arg(num(p[0]), num(p[1]), num(p[2]), num(r));
    switch (tool) {
    case Tool::Remove:
        return QStringLiteral("/remove ") + ball;
    case Tool::Deposit:
        return QStringLiteral("/add ") + ball + QStringLiteral(" union");
    case Tool::Paint:
        return QStringLiteral("/paint ") + paint_->currentText() + QLatin1Char(' ') + ball;
    }
    return {};
}

bool ClassroomPanel::useTool(Tool tool) {
    const QString command = toolCommand(tool);
    if (command.isEmpty()) {
        say(tr("click the class shape in the view to mark where the tool goes"));
        return false;
    }
    sendChat(command);
    return true;
}

void ClassroomPanel::replay(qint64 version) {
    if (client_->state() != ClassroomClient::State::Joined) return;
    if (version >= client_->version()) {
        leaveReplay();
        return;
    }
    replaying_ = true;
    replayVersion_ = version;
    historyLabel_->setText(tr("v%1…").arg(version));
    client_->requestVersion(version);
}

void ClassroomPanel::leaveReplay() {
    if (!replaying_) return;
    replaying_ = false;
    replayText_.clear();
    historyLabel_->clear();
    const QSignalBlocker quiet(history_);
    history_->setValue(history_->maximum());
    Q_EMIT historyShown({}, client_->version());
}

QString ClassroomPanel::exportX3d(QString* why) const {
    const QString text = replaying_ && !replayText_.isEmpty() ? replayText_ : client_->scene();
    if (text.isEmpty()) {
        if (why) *why = tr("join a class first: there is no class scene to export");
        return {};
    }
    // The function description as X3D XML, whatever encoding the class uses.
    const scene::ReadResult r = scene::readSceneBytes(text.toStdString(), "class.x3d");
    if (!r.ok()) {
        if (why) *why = tr("the class scene could not be read back");
        return {};
    }
    return QString::fromStdString(scene::writeXml(*r.scene));
}

void ClassroomPanel::say(const QString& line) {
    // What is said quotes the server and other members: drawn literally.
    auto* item = new QListWidgetItem(visibleText(line, true));
    item->setForeground(palette().placeholderText());
    chat_->addItem(item);
    chat_->scrollToBottom();
}

void ClassroomPanel::refreshMembers() {
    members_->clear();
    const auto holder = client_->lockHolder();
    for (const ClassroomClient::Member& m : client_->members()) {
        QString line = visibleText(m.name) + QStringLiteral(" (") +
                       QString::fromUtf8(classroom::nameOf(m.role).data(),
                                         qsizetype(classroom::nameOf(m.role).size())) +
                       QLatin1Char(')');
        if (holder && holder->id == m.id) line += tr(" — holds the lock");
        if (!m.connected) line += tr(" — away");
        if (m.id == client_->memberId()) line += tr(" — you");
        auto* item = new QListWidgetItem(line);
        if (!m.connected) item->setForeground(palette().placeholderText());
        members_->addItem(item);
    }
}

void ClassroomPanel::refreshLock() {
    const auto holder = client_->lockHolder();
    lock_->setText(client_->frozen()      ? tr("the class is frozen")
                   : !holder              ? tr("the lock is free")
                   : client_->holdsLock() ? tr("you hold the lock")
                                          : tr("%1 holds the lock").arg(visibleText(holder->name)));
    const bool pending = client_->hasPendingEdit();
    pending_->setVisible(pending);
    applyPending_->setVisible(pending);
    discardPending_->setVisible(pending);
    if (pending && !applyPending_->isEnabled())
        pending_->setText(
            tr("Your refused edit is kept; it can be applied when the lock is free."));
    if (!pending)
        applyPending_->setEnabled(false);
    else if (!holder || client_->holdsLock())
        applyPending_->setEnabled(true);
    release_->setEnabled(client_->holdsLock());
}

void ClassroomPanel::refreshState() {
    const auto s = client_->state();
    const bool in = s == ClassroomClient::State::Joined;
    const QString why = visibleText(client_->stopReason());
    const QString lost = visibleText(client_->lastNetworkError());
    state_->setText(s == ClassroomClient::State::Disconnected
                        ? (why.isEmpty() ? tr("not in a class") : tr("not in a class: %1").arg(why))
                    : s == ClassroomClient::State::Connecting ? tr("connecting…")
                    : s == ClassroomClient::State::Reconnecting
                        ? (lost.isEmpty() ? tr("connection lost: reconnecting…")
                                          : tr("connection lost (%1): reconnecting…").arg(lost))
                        : tr("in class %1 as %2, version %3")
                              .arg(visibleText(code_->text()), visibleText(client_->shownName()))
                              .arg(client_->version()));
    join_->setText(s == ClassroomClient::State::Disconnected ? tr("Join") : tr("Leave"));
    for (QWidget* w : std::initializer_list<QWidget*>{url_, code_, name_, role_, key_})
        w->setEnabled(s == ClassroomClient::State::Disconnected);
    const bool observer = chosenRole() == classroom::Role::Observer;
    send_->setEnabled(in && !observer);
    useTool_->setEnabled(in && !observer && toolPoint_.has_value());
    say_->setEnabled(in);
    instructor_->setVisible(chosenRole() == classroom::Role::Instructor);
    refreshLock();
    if (in) refreshMembers();
}

void ClassroomPanel::attach(PanelContext& context) {
    context_ = &context;
    setTextSource([&context] { return context.editor->toPlainText(); });
    // In a class, the text is (or becomes) the class's scene: it is read with
    // the class's bounds on size and work, as the server checks it.
    connect(client_.get(), &ClassroomClient::stateChanged, this, [this, &context] {
        const bool inClass = client_->state() != ClassroomClient::State::Disconnected;
        context.parser->setLimits(inClass ? editor::ParseLimits{classroom::readOptionsFor({}),
                                                                classroom::workBudgetFor({})}
                                          : editor::ParseLimits{});
    });
    connect(this, &ClassroomPanel::sharedSceneChanged, this, &ClassroomPanel::showSharedScene);
    // Replaying the class's history: the view shows a past version; the
    // editor keeps the present (and anything unsent).
    connect(this, &ClassroomPanel::historyShown, this,
            [&context](const QString& text, qint64 version) {
                if (text.isEmpty()) { // back to now: the editor's scene again
                    if (const auto now = context.parser->lastGoodScene()) context.showScene(now);
                    context.status->showMessage(tr("the class scene as it is now"), 3000);
                    return;
                }
                scene::ReadResult r = scene::readSceneBytes(text.toStdString(), "class.x3d");
                if (!r.ok()) return;
                context.showScene(std::shared_ptr<const scene::Scene>(std::move(r.scene)));
                context.status->showMessage(
                    tr("replaying the class: version %1 (press Now to come back)").arg(version));
            });
    // The tools go to the point chosen: on the clicked shape, or on the
    // function shape the haptic tool touches, in that shape's coordinates.
    connect(&context, &PanelContext::pointChosen, this,
            [this, &context](field::Vec3 point, int shape) {
                const auto meshes = context.view->meshes();
                if (!meshes) return;
                for (std::size_t i = 0; i < meshes->shapes.size(); ++i) {
                    const mesh::ShapeMesh& s = meshes->shapes[i];
                    if (shape >= 0 && i != std::size_t(shape)) continue;
                    if (shape < 0 && !s.field) continue;
                    const auto local = mesh::shapeCoordinates(s, point);
                    if (shape < 0 && (!local || !s.field->box.contains(*local))) continue;
                    setToolPoint(local, s.field ? s.field->box.diagonal() : s.domain.diagonal());
                    return;
                }
            });
    context.fileMenu->addAction(tr("&Join Class…"), this, [this] {
        show();
        raise();
        url_->setFocus();
    });
}

void ClassroomPanel::showSharedScene(const QString& text, qint64 version, const QString& author) {
    PanelContext& c = *context_;
    const QString mine = c.editor->toPlainText();
    // Unsent work in the editor is never overwritten: the student sends it
    // (refused as stale, it is kept and applied on the new version) or
    // discards it with Undo.
    if (!lastSharedScene_.isEmpty() && mine != lastSharedScene_ && mine != text) {
        lastSharedScene_ = text;
        c.status->showMessage(
            tr("The class scene is at version %1 (%2); your unsent edit stays in the editor: "
               "send it, or undo it to see the class's")
                .arg(version)
                .arg(visibleText(author)));
        return;
    }
    const bool first = lastSharedScene_.isEmpty();
    lastSharedScene_ = text;
    // The class's scene is nobody's file: Save asks where, never over the
    // file that was open before joining.
    if (first) c.forgetPath();
    if (mine != text) {
        c.editor->setPlainText(text);
        c.editor->document()->setModified(false);
    }
    c.status->showMessage(tr("class scene, version %1 by %2").arg(version).arg(visibleText(author)),
                          5000);
}

} // namespace fl::suite
