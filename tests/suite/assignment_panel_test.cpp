// The Assignment panel driven alone (Qt Test): it lists the courseware's
// assignments, shows a lab's instructions, ticks requirements off as the
// scene changes (the checker on a worker thread; only the newest scene
// counts), says why one is not met and where, and jumps there. A screenshot
// of the panel is saved to look at.
#include "suite/window/assignment_panel.h"

#include "scene/scene_reader.h"

#include <QApplication>
#include <QDir>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>
#include <QTextBrowser>
#include <QTreeWidget>

#include <memory>

using namespace fl;

namespace {

std::shared_ptr<const scene::Scene> read(const std::string& path) {
    scene::ReadResult r = scene::readSceneFile(path);
    return std::shared_ptr<const scene::Scene>(std::move(r.scene));
}

const std::string kLab = FUNCTIONLAB_COURSEWARE_DIR "/assignments/implicit-fantasies";

bool waitChecked(suite::AssignmentPanel& panel) {
    QSignalSpy spy(&panel, &suite::AssignmentPanel::checked);
    return spy.wait(20000);
}

} // namespace

class AssignmentPanelTest : public QObject {
    Q_OBJECT
  private Q_SLOTS:
    void listsTheLabsAndShowsInstructions() {
        suite::AssignmentPanel panel;
        QVERIFY(panel.choose(QStringLiteral("implicit-fantasies")));
        QVERIFY(panel.assignment());
        QCOMPARE(panel.checklist()->topLevelItemCount(), 8);
        QVERIFY(panel.instructions()->toPlainText().contains(QStringLiteral("What counts")));
        QVERIFY(!panel.choose(QStringLiteral("no-such-lab")));
    }

    void ticksRequirementsOffAsTheSceneChanges() {
        suite::AssignmentPanel panel;
        panel.resize(520, 760);
        QVERIFY(panel.choose(QStringLiteral("implicit-fantasies")));
        panel.sceneChanged(read(kLab + "/starter.x3d"));
        QVERIFY(waitChecked(panel));
        QVERIFY(panel.report());
        QCOMPARE(panel.report()->score, 10.0); // the starter's explicit ball
        QTreeWidgetItem* implicitItem = panel.checklist()->topLevelItem(0);
        QVERIFY(implicitItem->text(0).startsWith(QStringLiteral("✘ implicit")));
        QVERIFY(implicitItem->text(1).contains(QStringLiteral("implicit surface")));
        // Three scenes in a row: only the newest is shown in the end.
        panel.sceneChanged(read(kLab + "/starter.x3d"));
        panel.sceneChanged(read(kLab + "/starter.x3d"));
        panel.sceneChanged(read(kLab + "/solution/fantasy.x3d"));
        while (panel.checking())
            QVERIFY(waitChecked(panel));
        QCOMPARE(panel.report()->score, 100.0);
        QVERIFY(panel.status()->text().contains(QStringLiteral("100 of 100")));
        // A met requirement jumps to its place.
        QSignalSpy jump(&panel, &suite::AssignmentPanel::locationActivated);
        QTreeWidgetItem* ops = panel.checklist()->topLevelItem(3);
        QVERIFY(ops->text(0).startsWith(QStringLiteral("✔ set-operations")));
        Q_EMIT panel.checklist()->itemActivated(ops, 0);
        QCOMPARE(jump.count(), 1);
        QCOMPARE(jump.first().at(0).toInt(), 28);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        QDir().mkpath(FUNCTIONLAB_SCREENSHOT_DIR);
        QVERIFY(panel.grab().save(FUNCTIONLAB_SCREENSHOT_DIR "/assignment-panel.png"));
    }

    void aStarterCanBeChosen() {
        suite::AssignmentPanel panel;
        QVERIFY(panel.choose(QStringLiteral("time")));
        QSignalSpy starter(&panel, &suite::AssignmentPanel::starterChosen);
        QTest::mouseClick(panel.findChild<QPushButton*>(), Qt::LeftButton);
        QCOMPARE(starter.count(), 1);
        QVERIFY(starter.first().at(0).toString().endsWith(QStringLiteral("time/starter.x3d")));
    }
};

QTEST_MAIN(AssignmentPanelTest)
#include "assignment_panel_test.moc"
