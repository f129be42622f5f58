// The Accuracy panel driven alone (Qt Test): the watermelon's shape is
// measured on a worker thread — the same rows `bench accuracy` prints — and
// drawn as error against time; the operating point is ringed; clicking a
// point or typing a target error chooses a resolution; a sweep can be
// cancelled. A screenshot is saved to look at.
#include "suite/window/accuracy_panel.h"

#include "scene/field_access.h"
#include "scene/scene_edit.h"
#include "scene/scene_reader.h"

#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>

#include <functional>

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
            if (r.method == fl::measure::Method::Adaptive) (first == 0 ? first : last) = r.maxError;
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

    void theLevelOfDetailRangeIsMarkedAndTheChoiceWritten() {
        suite::AccuracyPanel panel;
        const auto scene = watermelon();
        panel.sceneChanged(scene);
        // The watermelon's FGeometry has the default `lod TRUE` over 8..256.
        QCOMPARE(panel.chart()->levelOfDetailRange(), (std::pair<double, double>{8, 256}));
        QVERIFY(!panel.writeButton()->isEnabled()); // nothing chosen yet
        panel.setResolutions({16, 32});
        QSignalSpy done(&panel, &suite::AccuracyPanel::measured);
        panel.measure();
        QVERIFY(done.wait(60000));
        QCOMPARE(panel.chart()->rows().size(), std::size_t(4));
        QVERIFY(panel.chooseTargetError(1.0));
        QVERIFY(panel.writeButton()->isEnabled());
        QSignalSpy write(&panel, &suite::AccuracyPanel::writeRequested);
        panel.writeButton()->click();
        QCOMPARE(write.count(), 1);
        QCOMPARE(write.first().at(1).toDouble(), 16.0);
        // The edits: resolution 16, lodRange from 16; read back, they are the file's.
        const auto* geometry =
            static_cast<const scene::Node*>(write.first().at(0).value<const scene::Node*>());
        QVERIFY(geometry);
        std::string why;
        const auto edit = scene::resolutionEdit(*scene, *geometry, 16, &why);
        QVERIFY2(edit && edit->edits().size() == 2, why.c_str());
        const std::string text = edit->appliedTo(scene->files[0].text);
        const scene::ReadResult again = scene::readSceneBytes(text, "watermelon.x3d");
        QVERIFY(again.ok());
        const scene::Node* g = nullptr;
        std::function<void(const scene::Node*)> find = [&](const scene::Node* n) {
            if (!n || g) return;
            if (n->type == "FGeometry") g = n;
            for (const auto& f : n->fields)
                for (const scene::Node* c : f.value.nodes)
                    find(c);
        };
        for (const scene::Node* n : again.scene->roots)
            find(n);
        QVERIFY(g);
        QCOMPARE(scene::numberField(*g, "resolution"), 16.0);
        QCOMPARE(scene::numbersField(*g, "lodRange"), (std::vector<double>{16, 256}));
    }

    void touchIsMeasuredTheSameWay() {
        // The haptics issue's curve, through the same panel: touching the
        // watermelon's function against touching its triangles.
        suite::AccuracyPanel panel;
        panel.resize(560, 520);
        panel.sceneChanged(watermelon());
        panel.setCost(suite::AccuracyPanel::Cost::Touch);
        panel.setResolutions({16, 32, 64});
        QSignalSpy done(&panel, &suite::AccuracyPanel::measured);
        panel.measure();
        QVERIFY(done.wait(120000));
        const auto& rows = panel.chart()->rows();
        QCOMPARE(rows.size(), std::size_t(4));
        QVERIFY(rows[0].method == fl::measure::Method::Function);
        QVERIFY2(rows[0].maxError < 1e-12, qPrintable(QString::number(rows[0].maxError)));
        for (std::size_t i = 1; i < rows.size(); ++i) {
            QVERIFY(rows[i].method == fl::measure::Method::Polygons);
            QVERIFY(rows[i].triangles > 0 && rows[i].milliseconds > 0);
            QVERIFY(rows[i].maxError > rows[0].maxError); // the chart's error: the mean
        }
        QVERIFY2(rows.back().maxError < rows[1].maxError,
                 qPrintable(QStringLiteral("finer triangles touch closer: %1 at 64, %2 at 16")
                                .arg(rows.back().maxError)
                                .arg(rows[1].maxError)));
        QVERIFY(panel.chart()->xLabel().contains(QStringLiteral("µs")));
        QVERIFY(panel.status()->text().contains(QStringLiteral("touching the function")));
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        QDir().mkpath(FUNCTIONLAB_SCREENSHOT_DIR);
        QVERIFY(panel.grab().save(FUNCTIONLAB_SCREENSHOT_DIR "/accuracy-touch.png"));
        // Back to meshing: the chart's curves are the mesher's again.
        panel.setCost(suite::AccuracyPanel::Cost::Meshing);
        QVERIFY(panel.chart()->xLabel().contains(QStringLiteral("mesh")));
        QVERIFY(panel.chart()->rows().empty());
    }

    void aPdeModelsDrawingIsMeasured() {
        // Issue 30 §4: a PDE model's curve — the time to mesh it at each
        // resolution against how far that mesh is from its finest drawing.
        scene::ReadResult r = scene::readSceneFile(FUNCTIONLAB_EXAMPLES_DIR "/pde_bunny.x3d");
        QVERIFY(r.ok());
        suite::AccuracyPanel panel;
        panel.resize(560, 520);
        panel.sceneChanged(std::shared_ptr<const scene::Scene>(std::move(r.scene)));
        int bunny = -1;
        for (int i = 0; i < panel.shapes()->count(); ++i)
            if (panel.shapes()->itemText(i).contains(QStringLiteral("BUNNY"))) bunny = i;
        QVERIFY2(bunny >= 0, qPrintable(panel.shapes()->itemText(0)));
        panel.shapes()->setCurrentIndex(bunny);
        QVERIFY(panel.chart()->xLabel().contains(QStringLiteral("model")));
        panel.setResolutions({8, 16, 32, 64});
        QSignalSpy done(&panel, &suite::AccuracyPanel::measured);
        panel.measure();
        QVERIFY(done.wait(120000));
        const auto& rows = panel.chart()->rows();
        QCOMPARE(rows.size(), std::size_t(4));
        for (std::size_t i = 0; i < rows.size(); ++i) {
            QVERIFY(rows[i].method == fl::measure::Method::PdeMesh);
            QVERIFY(rows[i].triangles > 0 && rows[i].milliseconds > 0);
            QVERIFY(rows[i].meanError <= rows[i].maxError);
            if (i > 0) { // finer is closer, and costs more triangles
                QVERIFY2(rows[i].maxError < rows[i - 1].maxError,
                         qPrintable(QStringLiteral("%1 at %2, %3 at %4")
                                        .arg(rows[i].maxError)
                                        .arg(rows[i].resolution)
                                        .arg(rows[i - 1].maxError)
                                        .arg(rows[i - 1].resolution)));
                QVERIFY(rows[i].triangles > rows[i - 1].triangles);
            }
        }
        QVERIFY(panel.status()->text().contains(QStringLiteral("PDE model")));
        // A target error chooses a resolution of the model, as for any shape.
        QVERIFY(panel.chooseTargetError(rows[2].maxError));
        QCOMPARE(panel.chart()->operatingResolution(), 32.0);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        QDir().mkpath(FUNCTIONLAB_SCREENSHOT_DIR);
        QVERIFY(panel.grab().save(FUNCTIONLAB_SCREENSHOT_DIR "/accuracy-pde.png"));
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
