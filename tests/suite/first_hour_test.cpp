// A student's first hour (issue 29), in the whole window: what the guide
// promises is there — every key it names is bound, the editor's keys are the
// editor's while it has focus, every menu item it names exists — and the
// `&` Lab 1 teaches, typed into an XML scene, is explained where it was
// written and fixed with one key. Screenshots are saved to look at.
#include "courseware/catalogue.h"
#include "editor/code_editor.h"
#include "editor/find_bar.h"
#include "grading/gradebook.h"
#include "suite/window/assignment_panel.h"
#include "suite/window/grading_panel.h"
#include "suite/window/main_window.h"
#include "suite/window/working_copy.h"
#include "viewer/picking.h"
#include "viewer/scene_player.h"
#include "viewer/scene_widget.h"
#include "window_screenshot.h"
#include "window_settle.h"

#include <QAbstractItemView>
#include <QApplication>
#include <QCompleter>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QListWidget>
#include <QMenuBar>
#include <QPushButton>
#include <QRegularExpression>
#include <QShortcut>
#include <QStandardPaths>
#include <QTest>
#include <QTimer>

using namespace fl;

namespace {

void save(const QImage& image, const QString& name) {
    QDir().mkpath(FUNCTIONLAB_SCREENSHOT_DIR);
    image.save(QStringLiteral(FUNCTIONLAB_SCREENSHOT_DIR "/") + name + QStringLiteral(".png"));
}

QString guide() {
    QFile f(QStringLiteral(FUNCTIONLAB_DOCS_DIR "/user-guide.md"));
    if (!f.open(QIODevice::ReadOnly)) return {};
    return QString::fromUtf8(f.readAll());
}

QString plainLabel(QString text) {
    return text.remove('&').remove(QStringLiteral("…")).remove(QStringLiteral("...")).trimmed();
}

// Every key sequence the window answers: actions (menus, panels) and shortcuts.
QList<QKeySequence> boundKeys(const suite::MainWindow& w) {
    QList<QKeySequence> keys;
    for (const QAction* a : w.findChildren<QAction*>())
        keys << a->shortcuts();
    for (const QShortcut* s : w.findChildren<QShortcut*>())
        keys << s->key();
    // The editor's own, handled while it has focus.
    keys << QKeySequence(Qt::CTRL | Qt::Key_Space) << QKeySequence(Qt::CTRL | Qt::Key_Period);
    return keys;
}

} // namespace

class FirstHourTest : public QObject {
    Q_OBJECT
  private Q_SLOTS:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("FunctionLabFirstHourTests"));
        QVERIFY(!guide().isEmpty());
    }

    void everyKeyAndMenuItemTheGuideNamesExists() {
        suite::MainWindow w;
        w.setPromptsEnabled(false);
        const QList<QKeySequence> bound = boundKeys(w);
        const QString text = guide();
        QRegularExpression key(
            QStringLiteral("\\b(Ctrl\\+(?:Shift\\+)?(?:[A-Z0-9.]|Space|Return))(?![A-Za-z0-9])"));
        int named = 0;
        for (auto m = key.globalMatch(text); m.hasNext();) {
            const QString k = m.next().captured(1);
            ++named;
            QVERIFY2(bound.contains(QKeySequence::fromString(k)),
                     qPrintable(QStringLiteral("the guide names %1; nothing answers it").arg(k)));
        }
        QVERIFY(named >= 6);
        // "File → Join Class…", "View → Shaded / Wireframe / Points".
        QStringList menuItems;
        for (QAction* top : w.menuBar()->actions())
            if (top->menu())
                for (QAction* a : top->menu()->actions())
                    menuItems << plainLabel(top->text()) + QStringLiteral(" → ") +
                                     plainLabel(a->text());
        // Title-case words, with alternatives after " / ": "Hand In", "Join Class…".
        const QString words = QStringLiteral("[A-Z][a-z]+(?: [A-Z][a-z]+)*…?");
        QRegularExpression item(
            QStringLiteral("\\b(File|Edit|View|Course|Help) → (%1(?: / %1)*)").arg(words));
        int items = 0;
        for (auto m = item.globalMatch(text); m.hasNext();) {
            const auto match = m.next();
            for (const QString& one : match.captured(2).split(QStringLiteral(" / "))) {
                const QString wanted = match.captured(1) + QStringLiteral(" → ") + plainLabel(one);
                ++items;
                const bool found =
                    std::any_of(menuItems.begin(), menuItems.end(),
                                [&](const QString& m) { return m.startsWith(wanted); });
                QVERIFY2(found, qPrintable(QStringLiteral("the guide names %1; the menus have: %2")
                                               .arg(wanted, menuItems.join(QStringLiteral(", ")))));
            }
        }
        QVERIFY(items >= 5);
    }

    void theEditorsKeysAreTheEditorsWhileItHasFocus() {
        suite::MainWindow w;
        QVERIFY(test::shownAt(w));
        w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QVERIFY(w.openFile(QStringLiteral(FUNCTIONLAB_EXAMPLES_DIR "/watermelon.x3d")));
        QVERIFY(test::settle(w));
        editor::CodeEditor* e = w.editor();
        e->setFocus();
        QTRY_VERIFY(e->hasFocus());
        // Ctrl+Space completes, and does not start the clock.
        QTextCursor c = e->textCursor();
        c.movePosition(QTextCursor::End);
        c.insertText(QStringLiteral("\nsph"));
        e->setTextCursor(c);
        QTest::keyClick(e, Qt::Key_Space, Qt::ControlModifier);
        QVERIFY(!w.player()->playing());
        auto* completer = e->findChild<QCompleter*>();
        QVERIFY(completer);
        QTRY_VERIFY(completer->popup()->isVisible());
        save(test::windowScreenshot(w), QStringLiteral("first-hour-completion"));
        QTest::keyClick(completer->popup(), Qt::Key_Escape);
        // Ctrl+H opens find and replace; Ctrl+F find.
        auto* find = w.findChild<editor::FindBar*>();
        QVERIFY(find);
        QTest::keyClick(e, Qt::Key_H, Qt::ControlModifier);
        QTRY_VERIFY(find->isVisible());
        QVERIFY(find->findChild<QWidget*>(QStringLiteral("replaceRow"))->isVisible());
        // Outside the editor Ctrl+Space plays and pauses.
        w.view()->setFocus();
        QTest::keyClick(w.view(), Qt::Key_Space, Qt::ControlModifier);
        QTRY_VERIFY(w.player()->playing());
    }

    void anExampleOpensAsTheStudentsOwnCopy() {
        QVERIFY(qEnvironmentVariableIsSet("FUNCTIONLAB_WORKSPACE"));
        const QString workspace = qEnvironmentVariable("FUNCTIONLAB_WORKSPACE");
        QDir(workspace).removeRecursively();
        suite::MainWindow w;
        QVERIFY(test::shownAt(w));
        QListWidget* examples = w.examples();
        QListWidgetItem* melon = nullptr;
        for (int i = 0; i < examples->count(); ++i)
            if (examples->item(i)->text() == QStringLiteral("Watermelon"))
                melon = examples->item(i);
        QVERIFY(melon);
        const QString course = melon->data(Qt::UserRole).toString();
        QFile original(course);
        QVERIFY(original.open(QIODevice::ReadOnly));
        const QByteArray before = original.readAll();
        Q_EMIT examples->itemActivated(melon);
        QTRY_COMPARE(w.currentPath(),
                     QDir(workspace).filePath(QStringLiteral("examples/watermelon.x3d")));
        QVERIFY(test::settle(w));
        // Ctrl+S writes the copy; the course's file is as it was.
        w.editor()->appendPlainText(QStringLiteral("<!-- mine -->"));
        QAction* saveAction = nullptr;
        for (QAction* a : w.findChildren<QAction*>())
            if (a->shortcuts().contains(QKeySequence(QKeySequence::Save))) saveAction = a;
        QVERIFY(saveAction);
        saveAction->trigger();
        QFile copy(w.currentPath());
        QVERIFY(copy.open(QIODevice::ReadOnly));
        QVERIFY(copy.readAll().contains("<!-- mine -->"));
        QFile again(course);
        QVERIFY(again.open(QIODevice::ReadOnly));
        QCOMPARE(again.readAll(), before);
        save(test::windowScreenshot(w), QStringLiteral("first-hour-own-copy"));
        // A course file opened by hand: Save asks where, starting in the workspace.
        QVERIFY(suite::saveNeedsAPlace(course));
        QVERIFY(suite::saveAsStartFor(course).startsWith(workspace));
        QVERIFY(!suite::saveNeedsAPlace(w.currentPath()));
    }

    void aStartersSaveAsOffersTheStudentsFolderWithoutTheSolution() {
        // Issue 29 §2: Save As offered the installed course's folder, with
        // starter.x3d selected and solution/ beside it.
        const QString workspace = qEnvironmentVariable("FUNCTIONLAB_WORKSPACE");
        QVERIFY(!workspace.isEmpty());
        QDir(workspace).removeRecursively();
        suite::MainWindow w;
        QVERIFY(test::shownAt(w));
        QVERIFY(w.assignmentPanel()->choose(QStringLiteral("implicit-shapes")));
        QPushButton* starter = nullptr;
        for (QPushButton* b : w.assignmentPanel()->findChildren<QPushButton*>())
            if (b->text().contains(QStringLiteral("starter"))) starter = b;
        QVERIFY(starter);
        starter->click();
        QTRY_VERIFY(w.currentPath().startsWith(workspace));
        QVERIFY(test::settle(w));
        QImage dialog;
        QString folder;
        QStringList listed;
        QTimer::singleShot(1000, [&] {
            auto* d = qobject_cast<QFileDialog*>(QApplication::activeModalWidget());
            if (!d) return;
            folder = d->directory().path();
            listed = d->directory().entryList(QDir::AllEntries | QDir::NoDotAndDotDot);
            dialog = d->grab().toImage();
            d->reject();
        });
        QAction* saveAs = nullptr;
        for (QAction* a : w.findChildren<QAction*>())
            if (plainLabel(a->text()) == QStringLiteral("Save As")) saveAs = a;
        QVERIFY(saveAs);
        saveAs->trigger();
        QVERIFY2(!dialog.isNull(), "no Save As dialog");
        QVERIFY2(folder.startsWith(workspace), qPrintable(folder));
        QVERIFY2(!listed.contains(QStringLiteral("solution")), qPrintable(listed.join(' ')));
        save(dialog, QStringLiteral("first-hour-save-as"));
    }

    void theFansInvisibleWindCatchesNoClick() {
        // Issue 29 §4: from the default view, the wind cone (transparency 1)
        // lay in front of the blades and took every click.
        suite::MainWindow w;
        QVERIFY(test::shownAt(w));
        QVERIFY(w.openFile(QStringLiteral(FUNCTIONLAB_EXAMPLES_DIR "/fan.x3d")));
        QVERIFY(test::settle(w));
        const auto meshes = w.view()->meshes();
        int onWind = 0, onFan = 0;
        QPoint sum;
        for (int y = 0; y < w.view()->height(); y += 6)
            for (int x = 0; x < w.view()->width(); x += 6) {
                const auto p =
                    viewer::pick(*meshes, viewer::rayThroughPixel(w.view()->pose(),
                                                                  w.view()->size(), QPointF(x, y)));
                if (!p) continue;
                if (p->shape.find("WIND") != std::string::npos) ++onWind;
                if (!p->touchSensors.empty()) {
                    ++onFan;
                    sum += QPoint(x, y);
                }
            }
        QCOMPARE(onWind, 0);
        QVERIFY(onFan > 0);
        // A click in the middle of what shows the fan starts it.
        QTest::mouseClick(w.view()->renderWindow(), Qt::LeftButton, {}, sum / onFan);
        QTRY_VERIFY_WITH_TIMEOUT(w.player()->inputsKept() > 0, 3000);
        save(test::windowScreenshot(w), QStringLiteral("first-hour-fan-clicked"));
    }

    void aSceneOpenedStartsAtTimeZero() {
        // Issue 29 §7: t went on from the last scene's.
        suite::MainWindow w;
        QVERIFY(test::shownAt(w));
        QVERIFY(w.openFile(QStringLiteral(FUNCTIONLAB_EXAMPLES_DIR "/bouncing_sphere.x3d")));
        QVERIFY(test::settle(w));
        w.player()->seek(0.7);
        QVERIFY(w.player()->sceneSeconds() > 0.5);
        QVERIFY(w.openFile(QStringLiteral(FUNCTIONLAB_EXAMPLES_DIR "/clock.x3d")));
        QVERIFY(test::settle(w));
        QVERIFY2(w.player()->sceneSeconds() < 0.1,
                 qPrintable(QString::number(w.player()->sceneSeconds())));
    }

    void theGradingPanelOpensBesideTheWindowWithoutGrowingIt() {
        // Issue 29 §6: docked, it grew the window from 800 to 879 px.
        const QString dir = QDir::temp().filePath(QStringLiteral("functionlab-first-hour-grades"));
        QDir(dir).removeRecursively();
        QDir().mkpath(dir);
        const QString book = dir + QStringLiteral("/course.sqlite");
        {
            const auto lab = courseware::findAssignment("implicit-shapes");
            QVERIFY(lab.assignment);
            grading::Gradebook g(book.toStdString());
            g.importRoster("id,name\nalice,Alice Smith\n");
            g.registerAssignment(lab.assignment->record());
        }
        suite::MainWindow w;
        QVERIFY(test::shownAt(w));
        QVERIFY(test::settle(w));
        const QSize before = w.size();
        QString why;
        QVERIFY2(w.gradingPanel()->openGradebook(book, {}, &why), qPrintable(why));
        w.gradingPanel()->showBeside();
        QTest::qWait(200);
        QCOMPARE(w.size(), before);
        QVERIFY(w.gradingPanel()->isFloating());
        QVERIFY(w.gradingPanel()->width() >= 800 && w.gradingPanel()->height() >= 500);
        save(w.gradingPanel()->grab().toImage(), QStringLiteral("first-hour-grading-beside"));
    }

    void anAmpersandInAnXmlSceneSaysWhatToWriteAndIsFixedWithOneKey() {
        suite::MainWindow w;
        QVERIFY(test::shownAt(w));
        w.editor()->setPlainText(QStringLiteral(
            "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
            "<X3D profile='Immersive' version='3.3'>\n<Scene>\n"
            "  <FShape>\n"
            "    <FGeometry definition='\"sphere(0, 0, 0, 1) & box(0.7, 0.7, 0.7)\"'\n"
            "               domainMin='-1.2 -1.2 -1.2' domainMax='1.2 1.2 1.2'/>\n"
            "  </FShape>\n</Scene>\n</X3D>\n"));
        QTRY_VERIFY_WITH_TIMEOUT(w.issues()->count() > 0, 10000);
        const QString said = w.issues()->item(0)->text();
        QVERIFY2(said.contains(QStringLiteral("&amp;")) && said.contains(QStringLiteral(":5:")),
                 qPrintable(said));
        QVERIFY(!said.contains(QStringLiteral("Expected '#'")));
        save(test::windowScreenshot(w), QStringLiteral("first-hour-ampersand-explained"));
        w.editor()->goTo(5, 1);
        QTest::keyClick(w.editor(), Qt::Key_Period, Qt::ControlModifier);
        QVERIFY(w.editor()->toPlainText().contains(QStringLiteral("1) &amp; box")));
        QTRY_VERIFY_WITH_TIMEOUT(w.issues()->count() == 0, 10000);
        QVERIFY(test::settle(w));
        save(test::windowScreenshot(w), QStringLiteral("first-hour-ampersand-fixed"));
    }
};

QTEST_MAIN(FirstHourTest)
#include "first_hour_test.moc"
