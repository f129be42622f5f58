// File → Import Mesh as PDE… driven as a student would (Qt Test, issue 30
// §3): the bunny is fitted on a worker as the slider asks, shown beside the
// original with its error as colour, its figures said; moving the slider
// cancels the fit under way; the curve of error against patches fills;
// Save writes the .pde and a scene that the window opens and draws. A bad
// file is refused with where and why. Screenshots are saved to look at.
#include "suite/window/accuracy_chart.h"
#include "suite/window/main_window.h"
#include "suite/window/pde_import_dialog.h"
#include "viewer/scene_widget.h"
#include "window_screenshot.h"

#include "pde/pde_file.h"
#include "scene/scene_reader.h"

#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QLabel>
#include <QPainter>
#include <QSignalSpy>
#include <QSlider>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

using namespace fl;

namespace {

void save(const QImage& image, const QString& name) {
    QDir().mkpath(FUNCTIONLAB_SCREENSHOT_DIR);
    image.save(QStringLiteral(FUNCTIONLAB_SCREENSHOT_DIR "/") + name + QStringLiteral(".png"));
}

// The dialog as the user sees it: its widgets with the 3D view's frame painted in.
QImage screenshot(suite::PdeImportDialog& d) {
    QImage shot = d.grab().toImage();
    const QImage frame = d.view()->grabFrame();
    if (!frame.isNull()) {
        QPainter p(&shot);
        p.drawImage(QRect(d.view()->mapTo(&d, QPoint(0, 0)), d.view()->size()), frame);
    }
    return shot;
}

// A UV sphere as an OBJ file (a mesh to fit fast when the bunny is not there).
QString sphereObj(const QString& folder) {
    const QString path = folder + QStringLiteral("/sphere.obj");
    std::ofstream out(path.toStdString());
    const int rings = 24, segments = 48;
    out << "v 0 0 1\n";
    for (int i = 1; i < rings; ++i)
        for (int j = 0; j < segments; ++j) {
            const double t = std::numbers::pi * i / rings, p = 2 * std::numbers::pi * j / segments;
            out << "v " << std::sin(t) * std::cos(p) << ' ' << std::sin(t) * std::sin(p) << ' '
                << std::cos(t) << '\n';
        }
    out << "v 0 0 -1\n";
    auto at = [&](int i, int j) { return 2 + (i - 1) * segments + (j % segments); };
    for (int j = 0; j < segments; ++j)
        out << "f 1 " << at(1, j) << ' ' << at(1, j + 1) << '\n';
    for (int i = 1; i + 1 < rings; ++i)
        for (int j = 0; j < segments; ++j)
            out << "f " << at(i, j) << ' ' << at(i + 1, j) << ' ' << at(i + 1, j + 1) << "\nf "
                << at(i, j) << ' ' << at(i + 1, j + 1) << ' ' << at(i, j + 1) << '\n';
    const int south = 2 + (rings - 1) * segments;
    for (int j = 0; j < segments; ++j)
        out << "f " << at(rings - 1, j) << ' ' << south << ' ' << at(rings - 1, j + 1) << '\n';
    return path;
}

QString bunnyOr(const QString& folder) {
    const QString bunny = QStringLiteral(FUNCTIONLAB_MESHES_DIR "/bunny.obj");
    return QFile::exists(bunny) ? bunny : sphereObj(folder);
}

bool waitUntilFitted(suite::PdeImportDialog& d, int ms = 120000) {
    return QTest::qWaitFor([&] { return !d.fitting(); }, ms);
}

} // namespace

class PdeImportTest : public QObject {
    Q_OBJECT
  private Q_SLOTS:
    void fitsShowsTheErrorAndSaysTheFigures() {
        QTemporaryDir dir;
        suite::PdeImportDialog d;
        QSignalSpy failed(&d, &suite::PdeImportDialog::loadFailed);
        d.load(bunnyOr(dir.path()));
        d.show();
        QVERIFY(QTest::qWaitForWindowExposed(&d));
        QVERIFY(waitUntilFitted(d));
        QCOMPARE(failed.count(), 0);
        QVERIFY(d.figures().has_value());
        const auto f = *d.figures();
        // The default goal: RMS 0.3 % of the diagonal, as `pde fit` without options.
        QCOMPARE(d.goal(), suite::PdeImportDialog::Goal::Error);
        QCOMPARE(d.goalValue(), 0.003); // not the slider step's rounding of it
        QVERIFY2(f.rms <= 0.0035, qPrintable(QString::number(f.rms)));
        QVERIFY(f.hausdorff >= f.rms && f.hausdorff < 0.05);
        QVERIFY(f.patches >= 1 && f.bytes > 0 && f.bytes < f.objBytes);
        QVERIFY(d.figuresLabel()->text().contains(QStringLiteral("patches")));
        QVERIFY(d.figuresLabel()->text().contains(QStringLiteral("Hausdorff")));
        // The mesh and the model side by side; the model coloured by its error.
        const auto meshes = d.view()->meshes();
        QVERIFY(meshes);
        QCOMPARE(meshes->shapes.size(), 2u);
        const mesh::Mesh& model = meshes->shapes[1].mesh;
        QCOMPARE(model.colours.size(), model.positions.size());
        QVERIFY(meshes->shapes[0].placement[12] < 0 && meshes->shapes[1].placement[12] > 0);
        QCOMPARE(d.chart()->rows().size(), 1u);
        QTest::qWait(300); // the frame drawn
        const QImage first = screenshot(d);
        save(first, QStringLiteral("pde-import-default"));

        // Moving the slider to patch counts: the fit under way gives way to
        // the newest setting; each fit is a point of the chart.
        d.setGoal(suite::PdeImportDialog::Goal::Patches, 64);
        d.setGoal(suite::PdeImportDialog::Goal::Patches, 8);
        QVERIFY(waitUntilFitted(d));
        QCOMPARE(d.figures()->patches, 8u);
        QCOMPARE(d.slider()->value(), 8);
        d.measureCurve({4, 16});
        QVERIFY(waitUntilFitted(d));
        std::vector<double> counts;
        for (const auto& r : d.chart()->rows())
            counts.push_back(r.resolution);
        QVERIFY2(counts.size() >= 3, qPrintable(QString::number(counts.size())));
        QVERIFY(std::is_sorted(counts.begin(), counts.end()));
        // More patches miss less (the curve falls from 4 to 16).
        const auto& rows = d.chart()->rows();
        QVERIFY(rows.back().meanError < rows.front().meanError);
        QTest::qWait(300);
        save(screenshot(d), QStringLiteral("pde-import-curve"));
    }

    void saveWritesTheModelAndASceneTheWindowOpens() {
        QTemporaryDir dir;
        suite::MainWindow w;
        w.setPromptsEnabled(false);
        w.resize(1200, 800);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        suite::PdeImportDialog d;
        QString why;
        d.load(sphereObj(dir.path()));
        QVERIFY(waitUntilFitted(d));
        QVERIFY(d.figures().has_value());
        QVERIFY(!d.save(dir.path() + QStringLiteral("/model.txt"), &why));
        QVERIFY(why.contains(QStringLiteral(".pde")));
        // A name XML cannot hold (a control character) is refused, nothing written.
        const QString control = dir.path() + QStringLiteral("/bell\u0007.pde");
        QVERIFY(!d.save(control, &why));
        QVERIFY2(why.contains(QStringLiteral("control characters")), qPrintable(why));
        QVERIFY(!QFile::exists(control));
        // A name a scene must quote: the url is escaped, and reads back.
        const QString pde = dir.path() + QStringLiteral("/my 'round' & \"sphere\".pde");
        const auto scenePath = d.save(pde, &why);
        QVERIFY2(scenePath, qPrintable(why));
        QVERIFY(QFile::exists(pde));
        QVERIFY(pde::readModelFile(pde.toStdString()).ok());
        const scene::ReadResult read = scene::readSceneFile(scenePath->toStdString());
        QVERIFY2(read.scene, read.diagnostics.empty() ? "" : read.diagnostics[0].message.c_str());
        QVERIFY(w.openFile(*scenePath));
        QVERIFY(QTest::qWaitFor([&] { return !w.busy() && w.view()->triangleCount() > 0; }, 60000));
        QVERIFY(w.lastProblem().isEmpty());
        save(test::windowScreenshot(w), QStringLiteral("pde-import-opened"));
    }

    void aFileThatIsNotAMeshIsRefusedWithWhere() {
        QTemporaryDir dir;
        const QString path = dir.path() + QStringLiteral("/notes.obj");
        std::ofstream(path.toStdString()) << "v 0 0 0\nv 1 0 x\n";
        suite::PdeImportDialog d;
        QSignalSpy failed(&d, &suite::PdeImportDialog::loadFailed);
        d.load(path);
        QVERIFY(failed.wait(10000));
        const QString why = failed.front().front().toString();
        QVERIFY2(why.contains(QStringLiteral("notes.obj:2:")), qPrintable(why));
        QVERIFY(!d.figures());
        QVERIFY(!d.fitting());
        QVERIFY(d.figuresLabel()->text().contains(QStringLiteral("notes.obj:2:")));
    }

    void aFileNameOfMarkupAndControlsIsShownAsText() {
        // A name with markup and a right-to-left override: the title and the
        // message show it as characters, the override made visible.
        QTemporaryDir dir;
        const QString name = QStringLiteral("<b>evil &amp; \u202Egpj.obj");
        const QString path = dir.path() + "/" + name;
        std::ofstream(path.toStdString()) << "v 0 0 0\nv 1 0 x\n";
        suite::PdeImportDialog d;
        QSignalSpy failed(&d, &suite::PdeImportDialog::loadFailed);
        d.load(path);
        QVERIFY(failed.wait(10000));
        QVERIFY(!d.windowTitle().contains(QChar(0x202E)));
        QVERIFY(d.windowTitle().contains(QStringLiteral("<b>evil &amp;")));
        const QString shown = d.figuresLabel()->text();
        QVERIFY2(!shown.contains(QChar(0x202E)), qPrintable(shown));
        QVERIFY2(shown.contains(QStringLiteral("<b>evil &amp;")), qPrintable(shown));
        QCOMPARE(d.figuresLabel()->textFormat(), Qt::PlainText);
    }

    void theFileIsReadWithoutHoldingTheWindow() {
        // A mesh of 200 000 faces (about 7 MB) takes the reader a while: the
        // dialog has returned from load() at once and keeps answering events
        // while it reads; a second load() wins over the first.
        QTemporaryDir dir;
        const QString big = dir.path() + QStringLiteral("/big.obj");
        {
            std::ofstream out(big.toStdString());
            const int n = 317; // a grid of n x n vertices, two faces per cell
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j)
                    out << "v " << i << ' ' << j << ' ' << ((i * j) % 7) * 0.1 << '\n';
            for (int i = 0; i + 1 < n; ++i)
                for (int j = 0; j + 1 < n; ++j) {
                    const int a = i * n + j + 1, b = a + 1, c = a + n, e = c + 1;
                    out << "f " << a << ' ' << b << ' ' << e << "\nf " << a << ' ' << e << ' ' << c
                        << '\n';
                }
        }
        suite::PdeImportDialog d;
        QSignalSpy failed(&d, &suite::PdeImportDialog::loadFailed);
        QElapsedTimer held;
        held.start();
        d.load(big);
        QVERIFY2(held.elapsed() < 1000, qPrintable(QString::number(held.elapsed())));
        QVERIFY(d.fitting()); // reading
        QTemporaryDir other;
        d.load(sphereObj(other.path())); // the student picked another file
        QVERIFY(waitUntilFitted(d));
        QCOMPARE(failed.count(), 0);
        QVERIFY(d.figures().has_value());
        QVERIFY(d.windowTitle().contains(QStringLiteral("sphere")));
    }
};

QTEST_MAIN(PdeImportTest)
#include "pde_import_test.moc"
