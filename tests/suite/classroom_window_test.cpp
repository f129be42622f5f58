// Two windows in one class (Qt Test, issue 17 §1, §3, §5): a server on
// loopback in this process; Ada and Ben join through their Classroom panels.
// Ada's edit takes the lock and reaches Ben's editor and view; Ben's edit
// under Ada's lock is refused — visibly, with her name — and kept; when Ada
// releases, Ben applies his kept edit. A tool removes material at a clicked
// point, through the same protocol. Screenshots of both windows are saved.
#include "editor/code_editor.h"
#include "editor/live_parser.h"
#include "suite/window/classroom_panel.h"
#include "suite/window/main_window.h"
#include "window_screenshot.h"

#include "classroom/class_session.h"
#include "classroom/client.h"
#include "classroom/edit_log.h"
#include "classroom/server.h"
#include "classroom/starter_scene.h"

#include <QDir>
#include <QHostAddress>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>

#include <memory>

using namespace fl;

namespace {

void save(suite::MainWindow& w, const QString& name) {
    QDir().mkpath(QStringLiteral(FUNCTIONLAB_SCREENSHOT_DIR));
    test::windowScreenshot(w).save(QStringLiteral(FUNCTIONLAB_SCREENSHOT_DIR "/") + name +
                                   QStringLiteral(".png"));
}

bool chatHas(const suite::ClassroomPanel* p, const QString& text) {
    for (int i = 0; i < p->chat()->count(); ++i)
        if (p->chat()->item(i)->text().contains(text)) return true;
    return false;
}

} // namespace

class ClassroomWindowTest : public QObject {
    Q_OBJECT
  private Q_SLOTS:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("FunctionLabTests"));
    }

    void twoStudentsEditInTurnAndTheLockRefusalIsVisible() {
        classroom::SteadyClock clock;
        classroom::ClassConfig config;
        config.classCode = "LAB1";
        config.initialScene = classroom::starterScene();
        QTemporaryDir data; // the class's log: its history can be replayed
        QVERIFY(data.isValid());
        classroom::EditLog log(data.path().toStdString());
        classroom::ClassSession session(config, clock, &log);
        classroom::ClassroomServer server(session);
        QVERIFY(server.listen(QHostAddress::LocalHost, 0));
        const QString url = QStringLiteral("ws://127.0.0.1:%1").arg(server.port());

        suite::MainWindow ada, ben;
        for (suite::MainWindow* w : {&ada, &ben}) {
            w->setPromptsEnabled(false);
            w->resize(1280, 800);
            w->show();
            QVERIFY(QTest::qWaitForWindowExposed(w));
        }
        ada.classroomPanel()->join(url, QStringLiteral("LAB1"), QStringLiteral("Ada"));
        ben.classroomPanel()->join(url, QStringLiteral("LAB1"), QStringLiteral("Ben"));
        auto* adaPanel = ada.classroomPanel();
        auto* benPanel = ben.classroomPanel();
        using State = classroom::ClassroomClient::State;
        QTRY_COMPARE_WITH_TIMEOUT(adaPanel->client()->state(), State::Joined, 10000);
        QTRY_COMPARE_WITH_TIMEOUT(benPanel->client()->state(), State::Joined, 10000);
        // Both editors show the class's scene; both see two members.
        const QString starter = QString::fromStdString(classroom::starterScene());
        QTRY_COMPARE_WITH_TIMEOUT(ada.editor()->toPlainText(), starter, 10000);
        QTRY_COMPARE_WITH_TIMEOUT(ben.editor()->toPlainText(), starter, 10000);
        QTRY_COMPARE_WITH_TIMEOUT(benPanel->members()->count(), 2, 10000);
        QVERIFY(ada.windowTitle().contains(QStringLiteral("untitled"))); // not a file of hers

        // Ada edits: a smaller sphere. Her edit takes the lock and reaches Ben.
        QString adaText = starter;
        QVERIFY(adaText.contains(QStringLiteral("CLASS")));
        adaText.replace(QStringLiteral("</Scene>"),
                        QStringLiteral("<WorldInfo title='Ada was here'/>\n</Scene>"));
        ada.editor()->setPlainText(adaText);
        adaPanel->sendEdit();
        QTRY_VERIFY_WITH_TIMEOUT(adaPanel->client()->holdsLock(), 10000);
        QTRY_COMPARE_WITH_TIMEOUT(ben.editor()->toPlainText(), adaText, 10000);
        QTRY_VERIFY_WITH_TIMEOUT(benPanel->lockStatus()->text().contains(QStringLiteral("Ada")),
                                 10000);

        // Ben edits under Ada's lock: refused, said with her name, kept.
        QString benText = adaText;
        benText.replace(QStringLiteral("Ada was here"), QStringLiteral("Ben was here"));
        ben.editor()->setPlainText(benText);
        benPanel->sendEdit();
        QTRY_VERIFY_WITH_TIMEOUT(benPanel->client()->hasPendingEdit(), 10000);
        QTRY_VERIFY_WITH_TIMEOUT(chatHas(benPanel, QStringLiteral("Ada holds the lock")), 10000);
        QVERIFY(benPanel->pendingStatus()->isVisible());
        QCOMPARE(ada.editor()->toPlainText(), adaText); // nothing of Ben's reached Ada
        QTRY_VERIFY_WITH_TIMEOUT(!ben.busy() && ben.view()->triangleCount() > 0, 20000);
        QTest::qWait(200);
        save(ben, QStringLiteral("classroom-ben-refused"));

        // Ada lets go: Ben is offered his kept edit and applies it.
        QMetaObject::invokeMethod(adaPanel->client(), &classroom::ClassroomClient::releaseLock);
        QTRY_VERIFY_WITH_TIMEOUT(benPanel->applyPendingButton()->isEnabled(), 10000);
        benPanel->applyPendingButton()->click();
        QTRY_COMPARE_WITH_TIMEOUT(ada.editor()->toPlainText(), benText, 10000);
        QTRY_VERIFY_WITH_TIMEOUT(benPanel->client()->holdsLock(), 10000);
        QVERIFY(!benPanel->client()->hasPendingEdit());
        save(ada, QStringLiteral("classroom-ada-sees-ben"));

        // A tool: Ben marks a point on the class shape and removes material
        // there; the class's scene gets a difference, for both.
        benPanel->setToolPoint(field::Vec3{0, 0, 1}, 2);
        QVERIFY(benPanel->toolCommand(suite::ClassroomPanel::Tool::Remove)
                    .startsWith(QStringLiteral("/remove sphere(0, 0, 1, ")));
        QVERIFY(benPanel->useTool(suite::ClassroomPanel::Tool::Remove));
        QTRY_VERIFY_WITH_TIMEOUT(ada.editor()->toPlainText() != benText, 10000);
        QVERIFY(ada.editor()->toPlainText().contains(QStringLiteral("sphere(0, 0, 1, ")));
        QTRY_COMPARE_WITH_TIMEOUT(ben.editor()->toPlainText(), ada.editor()->toPlainText(), 10000);
        // The history: Ada replays version 1 (the starter) in her view, then
        // comes back; the version shown exports as X3D.
        const qint64 now = adaPanel->client()->version();
        QVERIFY(now >= 4);
        QSignalSpy shown(adaPanel, &suite::ClassroomPanel::historyShown);
        adaPanel->replay(1);
        QTRY_COMPARE_WITH_TIMEOUT(shown.count(), 1, 10000);
        const QString past = shown.first().at(0).toString();
        QCOMPARE(shown.first().at(1).toLongLong(), qint64(1));
        QVERIFY2(past.contains(QStringLiteral("CLASS")) &&
                     !past.contains(QStringLiteral("was here")),
                 qPrintable(past));
        QTRY_VERIFY_WITH_TIMEOUT(ada.view()->meshes() && ada.view()->meshes()->source &&
                                     ada.view()->meshes()->source->files[0].text ==
                                         past.toStdString(),
                                 20000);
        // Ada's own text parsed again meanwhile (as a late edit's parse would
        // be) leaves the past in her view: the replay holds it.
        QSignalSpy parsedAgain(ada.parser(), &editor::LiveParser::sceneChanged);
        ada.editor()->setPlainText(ada.editor()->toPlainText());
        QTRY_COMPARE_WITH_TIMEOUT(parsedAgain.count(), 1, 10000);
        QTRY_VERIFY_WITH_TIMEOUT(!ada.busy(), 20000);
        QVERIFY(ada.view()->meshes()->source->files[0].text == past.toStdString());
        QVERIFY2(ada.statusBar()->currentMessage().contains(QStringLiteral("replaying")),
                 qPrintable(ada.statusBar()->currentMessage()));
        QString why;
        const QString x3d = adaPanel->exportX3d(&why);
        QVERIFY2(x3d.contains(QStringLiteral("<X3D")) && !x3d.contains(QStringLiteral("Ada was")),
                 qPrintable(why));
        QCOMPARE(ada.editor()->toPlainText(), ben.editor()->toPlainText()); // the present stays
        adaPanel->leaveReplay();
        QTRY_VERIFY_WITH_TIMEOUT(ada.view()->meshes()->source->files[0].text ==
                                     ada.editor()->toPlainText().toStdString(),
                                 20000);
        QVERIFY(adaPanel->exportX3d().contains(QStringLiteral("Ben was here")));
        // /help is answered to Ben only, never broadcast as chat.
        benPanel->sendChat(QStringLiteral("/help"));
        QTRY_VERIFY_WITH_TIMEOUT(chatHas(benPanel, QStringLiteral("/remove")), 10000);
        QVERIFY(!chatHas(adaPanel, QStringLiteral("/help")));
        save(ben, QStringLiteral("classroom-ben-tool"));
        // Leaving the class during a replay ends it: the view shows the
        // editor's scene again, and later edits reach the view.
        QSignalSpy shownAgain(adaPanel, &suite::ClassroomPanel::historyShown);
        adaPanel->replay(1);
        QTRY_COMPARE_WITH_TIMEOUT(shownAgain.count(), 1, 10000);
        QVERIFY(adaPanel->holdsTheView());
        adaPanel->leave();
        QTRY_VERIFY_WITH_TIMEOUT(!adaPanel->replaying(), 10000);
        QTRY_VERIFY_WITH_TIMEOUT(ada.view()->meshes()->source->files[0].text ==
                                     ada.editor()->toPlainText().toStdString(),
                                 20000);
        benPanel->leave();
    }

    // Issue 26 §2: a name and chat full of markup, a bidirectional override,
    // a tab and a line break are drawn as the characters they are; nothing
    // is read as HTML (an <img src=/dev/zero> label read the file until the
    // window died).
    void textFromOthersIsDrawnLiterally() {
        classroom::SteadyClock clock;
        classroom::ClassConfig config;
        config.classCode = "LAB2";
        config.initialScene = classroom::starterScene();
        classroom::ClassSession session(config, clock, nullptr);
        classroom::ClassroomServer server(session);
        QVERIFY(server.listen(QHostAddress::LocalHost, 0));
        const QString url = QStringLiteral("ws://127.0.0.1:%1").arg(server.port());
        const QString evil = QStringLiteral("<img src=/dev/zero>");

        suite::MainWindow mallory, ben;
        for (suite::MainWindow* w : {&mallory, &ben}) {
            w->setPromptsEnabled(false);
            w->resize(1280, 800);
            w->show();
            QVERIFY(QTest::qWaitForWindowExposed(w));
        }
        mallory.classroomPanel()->join(url, QStringLiteral("LAB2"), evil);
        ben.classroomPanel()->join(url, QStringLiteral("LAB2"), QStringLiteral("Ben"));
        auto* m = mallory.classroomPanel();
        auto* b = ben.classroomPanel();
        using State = classroom::ClassroomClient::State;
        QTRY_COMPARE_WITH_TIMEOUT(m->client()->state(), State::Joined, 10000);
        QTRY_COMPARE_WITH_TIMEOUT(b->client()->state(), State::Joined, 10000);
        const QString starter = QString::fromStdString(classroom::starterScene());
        QTRY_COMPARE_WITH_TIMEOUT(mallory.editor()->toPlainText(), starter, 10000);

        // Mallory takes the lock: Ben's lock label names her, literally.
        QString text = starter;
        text.replace(QStringLiteral("</Scene>"),
                     QStringLiteral("<WorldInfo title='x'/>\n</Scene>"));
        mallory.editor()->setPlainText(text);
        m->sendEdit();
        QTRY_VERIFY_WITH_TIMEOUT(b->lockStatus()->text().contains(evil), 10000);
        QCOMPARE(b->lockStatus()->textFormat(), Qt::PlainText);
        bool listed = false;
        for (int i = 0; i < b->members()->count(); ++i)
            listed = listed || b->members()->item(i)->text().startsWith(evil);
        QVERIFY(listed);

        // Her chat: markup, an override that would reverse the line, a tab.
        m->sendChat(QStringLiteral("<b>bold</b> \u202Eevil\tend"));
        QTRY_VERIFY_WITH_TIMEOUT(chatHas(b, QStringLiteral("<b>bold</b>")), 10000);
        QVERIFY(chatHas(b, QStringLiteral("\u27E8U+202E\u27E9evil")));
        QVERIFY(!chatHas(b, QStringLiteral("\u202E")));
        QVERIFY(chatHas(b, evil + QStringLiteral(": ")));
        QTRY_VERIFY_WITH_TIMEOUT(!ben.busy() && ben.view()->triangleCount() > 0, 20000);
        save(ben, QStringLiteral("classroom-text-from-others"));
        m->leave();
        b->leave();
    }
};

QTEST_MAIN(ClassroomWindowTest)
#include "classroom_window_test.moc"
