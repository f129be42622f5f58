// The Accuracy panel driven alone (Qt Test): the watermelon's shape is
// measured on a worker thread — the same rows `bench accuracy` prints — and
// drawn as error against time; the operating point is ringed; clicking a
// point or typing a target error chooses a resolution; a sweep can be
// cancelled. A screenshot is saved to look at.
#include "accuracy_panel.h"

#include "scene/scene_reader.h"

#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QLabel>
#include <QSignalSpy>
#include <QTest>

using namespace fl;

namespace {

std::shared_ptr<const scene::Scene> watermelon() {
    scene::ReadResult r = scene::readSceneFile(FUNCTIONLAB_EXAMPLES_DIR "/watermelon.x3d");
    return std::shared_ptr<const scene::Scene>(std::move(r.scene));
}

} // namespace

class AccuracyPanelTest : public QObject {
    Q_OBJECT
  private Q_SLOTS:
    void measuresDrawsAndChooses() {
        suite::AccuracyPanel panel;
        panel.resize(560, 520);
        panel.sceneChanged(watermelon());
        QCOMPARE(panel.shapes()->count(), 1);
        QCOMPARE(panel.chart()->operatingResolution(), 64.0); // the file's resolution
        QSignalSpy done(&panel, &suite::AccuracyPanel::measured);
        panel.measure();
        QVERIFY(panel.measuring());
        QVERIFY(done.wait(120000));
        const auto& rows = panel.chart()->rows();
        QCOMPARE(rows.size(), 2 * suite::AccuracyPanel::sweepResolutions().size());
        for (const auto& r : rows) {
            QVERIFY(r.triangles > 0);
            QVERIFY(r.maxError > 0 && r.maxError < 0.1);
        }
        QVERIFY(panel.chart()->xLabel().contains(QStringLiteral("ms")));
        QVERIFY(panel.chart()->yLabel().contains(QStringLiteral("error")));
        // Finer is more accurate: the adaptive error falls from 8 to 96.
        double first = 0, last = 0;
        for (const auto& r : rows)
            if (r.method == "adaptive") (first == 0 ? first : last) = r.maxError;
        QVERIFY2(last < first, qPrintable(QStringLiteral("%1 -> %2").arg(first).arg(last)));
        // Clicking a point chooses its resolution.
        QSignalSpy chosen(&panel, &suite::AccuracyPanel::resolutionChosen);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        QTest::mouseClick(panel.chart(), Qt::LeftButton, {}, panel.chart()->pointOf(0).toPoint());
        QCOMPARE(chosen.count(), 1);
        QCOMPARE(chosen.first().at(1).toDouble(), rows[0].resolution);
        // A target error chooses the coarsest adaptive resolution that reaches it.
        QVERIFY(panel.chooseTargetError(1.0));
        QCOMPARE(panel.chart()->operatingResolution(), 8.0);
        QVERIFY(!panel.chooseTargetError(1e-12));
        panel.chooseTargetError(rows[rows.size() - 2].maxError); // adaptive at 256
        QDir().mkpath(FUNCTIONLAB_SCREENSHOT_DIR);
        QVERIFY(panel.grab().save(FUNCTIONLAB_SCREENSHOT_DIR "/accuracy-panel.png"));
    }

    void aSweepCanBeCancelled() {
        suite::AccuracyPanel panel;
        panel.sceneChanged(watermelon());
        QSignalSpy done(&panel, &suite::AccuracyPanel::measured);
        panel.measure();
        panel.cancel();
        QVERIFY(!panel.measuring() || done.wait(30000));
        QVERIFY(panel.chart()->rows().size() < 2 * suite::AccuracyPanel::sweepResolutions().size());
    }
};

QTEST_MAIN(AccuracyPanelTest)
#include "accuracy_panel_test.moc"
