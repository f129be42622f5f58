// The window's layout as a new user first sees it (issue 28), on the most
// common laptop screen (1366×768) and on 1920×1080: the window fits with its
// status bar, the 3D view is the largest thing on screen, every panel's tab
// shows its whole name, and the issues strip is there only while there are
// issues. Screenshots of both sizes are saved to look at.
#include "suite/window/main_window.h"
#include "suite/window/panel.h"
#include "viewer/scene_widget.h"
#include "window_screenshot.h"
#include "window_settle.h"

#include "editor/code_editor.h"

#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QListWidget>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTabBar>
#include <QTest>

using namespace fl;

namespace {

void save(const QImage& image, const QString& name) {
    QDir().mkpath(FUNCTIONLAB_SCREENSHOT_DIR);
    image.save(QStringLiteral(FUNCTIONLAB_SCREENSHOT_DIR "/") + name + QStringLiteral(".png"));
}

} // namespace

class LayoutTest : public QObject {
    Q_OBJECT
  private Q_SLOTS:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("FunctionLabLayoutTests"));
    }

    void theWindowFitsAndTheViewComesFirst_data() {
        QTest::addColumn<QSize>("screen");
        QTest::newRow("1366x768") << QSize(1366, 768);
        QTest::newRow("1920x1080") << QSize(1920, 1080);
    }

    void theWindowFitsAndTheViewComesFirst() {
        QFETCH(QSize, screen);
        // What a window manager leaves of the screen: a panel of 32 pixels
        // and a title bar of 30.
        const QSize room = screen - QSize(0, 62);
        suite::MainWindow w;
        w.setPromptsEnabled(false);
        w.resize(room);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.openFile(QStringLiteral(FUNCTIONLAB_EXAMPLES_DIR "/watermelon.x3d")));
        QVERIFY(test::settle(w));
        save(test::windowScreenshot(w),
             QStringLiteral("layout-%1x%2").arg(screen.width()).arg(screen.height()));

        // It fits, status bar and all.
        QVERIFY2(w.width() <= room.width() && w.height() <= room.height(),
                 qPrintable(QStringLiteral("%1x%2 in %3x%4")
                                .arg(w.width())
                                .arg(w.height())
                                .arg(room.width())
                                .arg(room.height())));
        QVERIFY(w.statusBar()->isVisible());
        QVERIFY(w.statusBar()->geometry().bottom() < w.height());

        // The view is the largest thing on screen.
        const int viewArea = w.view()->width() * w.view()->height();
        for (suite::Panel* p : w.panels()) {
            if (!p->isVisible() || p->visibleRegion().isEmpty()) continue;
            QVERIFY2(p->width() * p->height() < viewArea,
                     qPrintable(p->windowTitle() + QStringLiteral(" is larger than the view")));
        }
        QVERIFY2(w.view()->width() * 10 >= w.width() * 4,
                 qPrintable(QStringLiteral("the view is %1 of %2 pixels wide")
                                .arg(w.view()->width())
                                .arg(w.width())));

        // Every tab names its panel in full.
        int tabs = 0;
        for (QTabBar* bar : w.findChildren<QTabBar*>()) {
            if (!bar->isVisible()) continue;
            for (int i = 0; i < bar->count(); ++i, ++tabs) {
                const QRect r = bar->tabRect(i);
                const int room = std::max(r.width(), r.height());
                const int text = bar->fontMetrics().horizontalAdvance(bar->tabText(i));
                QVERIFY2(room >= text, qPrintable(bar->tabText(i) + QStringLiteral(" is cut")));
                QVERIFY2(bar->rect().contains(r),
                         qPrintable(bar->tabText(i) + QStringLiteral(" is scrolled away")));
            }
        }
        QVERIFY(tabs >= 8); // scene text and tree; examples … classroom

        // No issues, no strip; an issue brings it; fixing it takes it away.
        QVERIFY(w.issues()->count() == 0);
        auto* issues = qobject_cast<QDockWidget*>(w.issues()->parentWidget());
        QVERIFY(issues);
        QVERIFY(!issues->isVisible());
        const QString good = w.editor()->toPlainText();
        w.editor()->setPlainText(good + QStringLiteral("<"));
        QTRY_VERIFY_WITH_TIMEOUT(issues->isVisible(), 10000);
        QTest::qWait(100);
        // The strip lies under the view: the panel bar keeps its height.
        for (QTabBar* bar : w.findChildren<QTabBar*>())
            if (bar->isVisible())
                for (int i = 0; i < bar->count(); ++i)
                    QVERIFY2(bar->rect().contains(bar->tabRect(i)), qPrintable(bar->tabText(i)));
        save(test::windowScreenshot(w),
             QStringLiteral("layout-%1x%2-issues").arg(screen.width()).arg(screen.height()));
        w.editor()->setPlainText(good);
        QTRY_VERIFY_WITH_TIMEOUT(!issues->isVisible(), 10000);
        QVERIFY(test::settle(w));
    }
};

QTEST_MAIN(LayoutTest)
#include "layout_test.moc"
