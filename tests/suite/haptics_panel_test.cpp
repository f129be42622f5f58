// The Haptics panel driven alone (Qt Test): a scene with nothing tangible
// never starts the loop and says why; the watermelon is felt with the
// mouse's device — the tool pressed into its top meets the rind, the force
// pushes back up, the status and the graph show it. A screenshot is saved.
#include "suite/window/force_graph.h"
#include "suite/window/haptics_panel.h"

#include "scene/scene_reader.h"

#include <QComboBox>
#include <QDir>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>

using namespace fl;

namespace {

std::shared_ptr<const scene::Scene> example(const char* name) {
    scene::ReadResult r = scene::readSceneFile(std::string(FUNCTIONLAB_EXAMPLES_DIR) + "/" + name);
    return std::shared_ptr<const scene::Scene>(std::move(r.scene));
}

} // namespace

class HapticsPanelTest : public QObject {
    Q_OBJECT
  private Q_SLOTS:
    void nothingTangibleNeverStartsTheLoop() {
        suite::HapticsPanel panel;
        panel.sceneChanged(example("implicit_gallery.x3d"));
        QVERIFY(!panel.tangible());
        QVERIFY(!panel.feelButton()->isEnabled());
        panel.start();
        QVERIFY(!panel.feeling());
    }

    void findDevicesSaysWhatItFoundEvenNothing() {
        // Issue 29 §7: with no device it said nothing at all.
        suite::HapticsPanel panel;
        panel.findDevices();
        const QString said = panel.notes()->text();
        QVERIFY2(said.contains(QStringLiteral("device")), qPrintable(said));
        if (panel.devices()->count() == 1) // the mouse only: none found here
            QVERIFY2(said.contains(QStringLiteral("mouse")), qPrintable(said));
    }

    void theMouseFeelsTheWatermelonsRind() {
        suite::HapticsPanel panel;
        panel.resize(420, 520);
        panel.sceneChanged(example("watermelon.x3d"));
        QVERIFY(panel.tangible());
        QVERIFY(panel.feelButton()->isEnabled());
        QTRY_VERIFY_WITH_TIMEOUT(!panel.busy(), 20000); // the snapshot is made
        QSignalSpy marks(&panel, &suite::HapticsPanel::touchChanged);
        panel.feelButton()->click();
        QVERIFY(panel.feeling());
        // Above the melon's bottom, then on its surface, pressed in along -normal.
        panel.touchAt(field::Vec3{0, 0, -1.3}, {0, 0, -1});
        QTest::qWait(50);
        panel.touchAt(field::Vec3{0, 0, -1.0}, {0, 0, -1});
        bool pushed = false;
        for (int k = 0; k < 200 && !pushed; ++k) {
            QTest::qWait(20);
            panel.refresh();
            if (marks.isEmpty()) continue;
            const auto m = marks.last().at(0).value<std::optional<suite::TouchMarks>>();
            pushed = m && m->contact && m->force[2] < 0; // the hand is pushed back down
        }
        QVERIFY2(pushed, qPrintable(panel.status()->text()));
        QVERIFY(panel.status()->text().contains(QStringLiteral("Hz")));
        QVERIFY(!panel.graph()->forces().empty());
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        panel.refresh();
        QDir().mkpath(FUNCTIONLAB_SCREENSHOT_DIR);
        QVERIFY(panel.grab().save(FUNCTIONLAB_SCREENSHOT_DIR "/haptics-panel.png"));
        QSignalSpy cleared(&panel, &suite::HapticsPanel::touchChanged);
        panel.feelButton()->click();
        QVERIFY(!panel.feeling());
        QVERIFY(!cleared.isEmpty());
        QVERIFY(!cleared.last().at(0).value<std::optional<suite::TouchMarks>>());
    }
};

QTEST_MAIN(HapticsPanelTest)
#include "haptics_panel_test.moc"
