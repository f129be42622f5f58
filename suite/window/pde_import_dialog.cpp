#include "pde_import_dialog.h"

#include "accuracy_chart.h"
#include "plain_text.h"
#include "scene_text_file.h"

#include "courseware/workspace.h"
#include "mesh/mesh_export.h"
#include "mesh/mesh_topology.h"
#include "mesh/obj_reader.h"
#include "mesh/surface_distance.h"
#include "pde/mesh_fit.h"
#include "pde/pde_scene.h"
#include "viewer/scene_widget.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QProgressBar>
#include <QPushButton>
#include <QSlider>
#include <QSplitter>
#include <QVBoxLayout>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>

namespace fl::suite {
namespace {

// The error slider runs on a log scale from 0.05 % to 2 % of the diagonal.
constexpr double kLeastError = 0.0005, kMostError = 0.02;
constexpr int kErrorSteps = 100;
constexpr int kMostPatches = 200;
// Red on the surface means this far from the original, or farther (a fixed
// scale: a better fit is visibly bluer).
constexpr double kRedAt = 0.01;

double errorAt(int step) {
    return kLeastError * std::pow(kMostError / kLeastError, double(step) / kErrorSteps);
}

int stepOf(double error) {
    const double t = std::log(error / kLeastError) / std::log(kMostError / kLeastError);
    return std::clamp(int(std::lround(t * kErrorSteps)), 0, kErrorSteps);
}

// Blue (on the original) through green and yellow to red (kRedAt or more).
std::array<float, 4> errorColour(double fraction) {
    static constexpr std::array<std::array<float, 3>, 4> stops{{{0.16f, 0.40f, 0.85f},
                                                                {0.20f, 0.72f, 0.35f},
                                                                {0.95f, 0.82f, 0.20f},
                                                                {0.85f, 0.15f, 0.10f}}};
    const double t = std::clamp(fraction / kRedAt, 0.0, 1.0) * 3;
    const auto i = std::min<std::size_t>(std::size_t(t), 2);
    const float f = float(t - double(i));
    std::array<float, 4> c{0, 0, 0, 1};
    for (std::size_t k = 0; k < 3; ++k)
        c[k] = stops[i][k] + f * (stops[i + 1][k] - stops[i][k]);
    return c;
}

QString percent(double fraction) {
    return QStringLiteral("%1 %").arg(fraction * 100, 0, 'g', 3);
}

// A shape of the dialog's view: a mesh moved along x.
mesh::ShapeMesh shapeOf(std::string name, mesh::Mesh m, double dx) {
    mesh::ShapeMesh s;
    s.name = std::move(name);
    s.mesh = std::move(m);
    s.placement = field::Affine::translate(dx, 0, 0).matrix();
    s.functionGeometry = false;
    return s;
}

} // namespace

PdeImportDialog::PdeImportDialog(QWidget* parent)
    : QDialog(parent), goals_(new QComboBox), slider_(new QSlider(Qt::Horizontal)),
      goalText_(new QLabel), view_(new viewer::SceneWidget), chart_(new AccuracyChart),
      figuresText_(plainLabel()), legend_(plainLabel()), progress_(new QProgressBar),
      curveButton_(new QPushButton(tr("Measure the curve"))),
      saveButton_(new QPushButton(tr("Save…"))),
      reader_(
          this, [](const QString& path) { return readOriginal(path); },
          [this](const QString& path, Read r) { readDone(path, std::move(r)); }),
      worker_(
          this, [this](const Job& job) { return runFit(job); },
          [this](const Job& job, Outcome r) { fitDone(job, std::move(r)); }) {
    setWindowTitle(tr("Import Mesh as PDE"));
    goals_->addItem(tr("RMS error to reach"));
    goals_->addItem(tr("Number of patches"));
    goals_->setToolTip(tr("Fit as few patches as reach an error (a fraction of the box "
                          "diagonal), or exactly this many patches"));
    auto* goalRow = new QHBoxLayout;
    goalRow->addWidget(goals_);
    goalRow->addWidget(slider_, 1);
    goalText_->setMinimumWidth(120);
    goalRow->addWidget(goalText_);

    chart_->setCurves(ChartCurves::pdeFitting());
    chart_->setMinimumWidth(300);
    view_->setMinimumSize(420, 320);
    auto* split = new QSplitter;
    split->addWidget(view_);
    split->addWidget(chart_);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 2);
    split->setSizes({640, 420}); // the shapes the larger

    legend_->setText(
        tr("Left: the mesh. Right: the PDE model, coloured by its distance to the mesh — blue "
           "on it, green, yellow, red %1 of the diagonal or more.")
            .arg(percent(kRedAt)));
    legend_->setWordWrap(true);
    figuresText_->setWordWrap(true);
    figuresText_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    progress_->setRange(0, 0);
    progress_->setVisible(false);
    progress_->setTextVisible(true);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close);
    buttons->addButton(curveButton_, QDialogButtonBox::ActionRole);
    buttons->addButton(saveButton_, QDialogButtonBox::AcceptRole);
    curveButton_->setToolTip(tr("Fit 4, 8, 16 … 128 patches, one after another, and draw "
                                "the error each reaches"));
    saveButton_->setToolTip(tr("Write the model (.pde) and a scene that shows it, then open "
                               "the scene"));
    saveButton_->setEnabled(false);

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(goalRow);
    layout->addWidget(split, 1);
    layout->addWidget(legend_);
    layout->addWidget(figuresText_);
    layout->addWidget(progress_);
    layout->addWidget(buttons);
    resize(1100, 640);

    settle_.setSingleShot(true);
    settle_.setInterval(350);
    connect(&settle_, &QTimer::timeout, this, &PdeImportDialog::requestFit);
    connect(goals_, &QComboBox::currentIndexChanged, this, [this](int i) {
        setGoal(i == 1 ? Goal::Patches : Goal::Error,
                i == 1 ? double(figures_ ? figures_->patches : 16) : 0.003);
    });
    connect(slider_, &QSlider::valueChanged, this, [this](int step) {
        value_ = goal_ == Goal::Patches ? double(step) : errorAt(step);
        showGoalText();
        settle_.start();
    });
    connect(curveButton_, &QPushButton::clicked, this, [this] { measureCurve(); });
    connect(saveButton_, &QPushButton::clicked, this, &PdeImportDialog::saveAsked);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(chart_, &AccuracyChart::resolutionChosen, this,
            [this](double patches) { setGoal(Goal::Patches, patches); });
    setGoal(Goal::Error, 0.003);
}

PdeImportDialog::~PdeImportDialog() {
    *alive_ = false; // progress from a fit still running goes nowhere
}

void PdeImportDialog::load(const QString& objPath) {
    objPath_ = objPath;
    original_.reset();
    figures_.reset();
    last_.reset();
    chart_->setRows({});
    saveButton_->setEnabled(false);
    ++generation_; // a fit of the mesh before is no longer shown
    worker_.cancel();
    const QString name = QFileInfo(objPath).fileName();
    setWindowTitle(tr("Import %1 as PDE").arg(visibleText(name)));
    progress_->setVisible(true);
    progress_->setFormat(tr("reading %1…").arg(name));
    reader_.request(objPath);
}

PdeImportDialog::Read PdeImportDialog::readOriginal(const QString& objPath) {
    Read out;
    mesh::ObjReadResult read = mesh::readObjFile(objPath.toStdString());
    if (!read.ok()) {
        out.why = QString::fromStdString(read.error);
        return out;
    }
    auto original = std::make_shared<Original>();
    original->mesh = std::move(*read.mesh);
    if (original->mesh.normals.size() != original->mesh.positions.size())
        original->mesh.normals = mesh::vertexNormals(original->mesh);
    original->lines = std::move(read.triangleLines);
    original->tree = std::make_unique<const mesh::TriangleTree>(original->mesh);
    std::error_code ec;
    original->fileBytes = std::size_t(std::filesystem::file_size(objPath.toStdString(), ec));
    out.original = std::move(original);
    return out;
}

void PdeImportDialog::readDone(const QString& objPath, Read r) {
    if (objPath != objPath_) return; // another file was asked for since
    if (!r.original) {
        progress_->setVisible(false);
        // The message names the file: a name is anybody's text.
        figuresText_->setText(tr("The mesh could not be read: %1").arg(visibleText(r.why, true)));
        Q_EMIT loadFailed(r.why);
        return;
    }
    original_ = std::move(r.original);
    requestFit();
}

double PdeImportDialog::goalValue() const {
    return value_;
}

void PdeImportDialog::setGoal(Goal goal, double value) {
    showGoal(goal, value);
    curve_.clear(); // the student chose: a curve being measured gives way
    if (original_) requestFit();
}

void PdeImportDialog::showGoal(Goal goal, double value) {
    const QSignalBlocker quiet(slider_);
    const QSignalBlocker quietToo(goals_);
    goals_->setCurrentIndex(goal == Goal::Patches ? 1 : 0);
    if (goal == Goal::Patches) {
        value = std::clamp(std::round(value), 1.0, double(kMostPatches));
        slider_->setRange(1, kMostPatches);
        slider_->setValue(int(value));
    } else {
        value = std::clamp(value, kLeastError, kMostError);
        slider_->setRange(0, kErrorSteps);
        slider_->setValue(stepOf(value));
    }
    goal_ = goal;
    value_ = value; // as given, not as the slider's step rounds it (0.003 is pde fit's)
    showGoalText();
}

void PdeImportDialog::showGoalText() {
    goalText_->setText(goal_ == Goal::Patches ? tr("%1 patches").arg(value_)
                                              : tr("RMS ≤ %1").arg(percent(goalValue())));
}

bool PdeImportDialog::fitting() const {
    return reader_.busy() || worker_.busy() || settle_.isActive();
}

void PdeImportDialog::requestFit() {
    settle_.stop();
    if (!original_) return;
    Job job{++generation_, original_, goal_, goalValue()};
    if (!curve_.empty()) {
        job.goal = Goal::Patches;
        job.value = double(curve_.front());
        job.curve = true;
    }
    progress_->setVisible(true);
    progress_->setFormat(tr("fitting…"));
    worker_.cancel(); // a fit for an older setting stops
    worker_.request(std::move(job));
}

void PdeImportDialog::measureCurve(std::vector<std::size_t> counts) {
    curve_ = std::move(counts);
    requestFit();
}

PdeImportDialog::Outcome PdeImportDialog::runFit(const Job& job) {
    Outcome out;
    pde::MeshFitOptions o;
    if (job.goal == Goal::Patches)
        o.patches = std::size_t(job.value);
    else
        o.error = job.value;
    o.cancel = worker_.cancelFlag();
    o.progress = [this, alive = alive_, generation = job.generation](std::size_t patches,
                                                                     double rms) {
        QMetaObject::invokeMethod(
            this,
            [this, alive, generation, patches, rms] {
                if (!*alive || generation != generation_) return;
                progress_->setFormat(
                    tr("fitting: %1 patches, RMS %2").arg(patches).arg(percent(rms)));
            },
            Qt::QueuedConnection);
    };
    const auto started = std::chrono::steady_clock::now();
    std::string why;
    const Original& original = *job.original;
    const auto fit = pde::fitMesh(original.mesh, o, &why, &original.lines);
    out.fitMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started)
            .count();
    if (!fit) {
        out.why = QString::fromStdString(why);
        return out;
    }
    pde::MeasureOptions measuring;
    measuring.originalTree = original.tree.get();
    out.measured = pde::measureFit(original.mesh, fit->model, measuring, &why);
    if (!out.measured) {
        out.why = QString::fromStdString(why);
        return out;
    }
    // The reconstruction coloured by each vertex's distance to the mesh.
    mesh::Mesh& rebuilt = out.measured->rebuilt;
    const std::vector<double> d = mesh::vertexDistances(rebuilt, *original.tree);
    rebuilt.colours.resize(d.size());
    for (std::size_t i = 0; i < d.size(); ++i)
        rebuilt.colours[i] = errorColour(d[i] / out.measured->diagonal);
    return out;
}

void PdeImportDialog::fitDone(const Job& job, Outcome r) {
    if (job.generation == generation_) {
        if (r.measured)
            showFit(r);
        else if (r.why != QLatin1String("cancelled")) {
            figuresText_->setText(tr("The mesh could not be fitted: %1").arg(r.why));
            saveButton_->setEnabled(false);
        }
        if (job.curve && r.measured) {
            // The slider says what is shown: the count the curve just fitted.
            showGoal(Goal::Patches, double(r.measured->model.patches.size()));
            curve_.erase(curve_.begin());
        }
        if (job.curve && r.measured && !curve_.empty()) {
            requestFit();
        } else {
            curve_.clear();
            progress_->setVisible(false);
        }
    }
    Q_EMIT fitted();
}

void PdeImportDialog::showFit(const Outcome& r) {
    const pde::FitMeasure& m = *r.measured;
    Figures f;
    f.patches = m.model.patches.size();
    f.maxRadii = m.model.maxRadii();
    f.bytes = m.bytes.size();
    f.objBytes = original_ ? original_->fileBytes : 0;
    f.rms = m.rms();
    f.hausdorff = m.hausdorff();
    f.fitMs = r.fitMs;
    figures_ = f;
    last_ = m;
    addChartRow(f);
    saveButton_->setEnabled(true);
    const QLocale locale;
    figuresText_->setText(
        tr("%1 patches (at most %2 radii) · %3 bytes (the OBJ: %4 bytes, %5× more) · RMS %6, "
           "Hausdorff %7 of the diagonal · fitted in %8 s")
            .arg(f.patches)
            .arg(f.maxRadii)
            .arg(locale.toString(qulonglong(f.bytes)))
            .arg(locale.toString(qulonglong(f.objBytes)))
            .arg(f.bytes ? double(f.objBytes) / double(f.bytes) : 0.0, 0, 'f', 0)
            .arg(percent(f.rms))
            .arg(percent(f.hausdorff))
            .arg(f.fitMs / 1000, 0, 'f', 1));
    // Side by side: the mesh on the left, the model on the right.
    const double width = m.model.hi[0] - m.model.lo[0];
    const double apart = 0.55 * (width > 0 ? width : m.diagonal) + 0.05 * m.diagonal;
    auto meshes = std::make_shared<mesh::SceneMeshes>();
    meshes->shapes.push_back(shapeOf("the mesh", original_->mesh, -apart));
    meshes->shapes.push_back(shapeOf("the PDE model", m.rebuilt, apart));
    view_->setMeshes(meshes);
}

void PdeImportDialog::addChartRow(const Figures& f) {
    std::vector<measure::AccuracyRow> rows = chart_->rows();
    std::erase_if(rows,
                  [&](const measure::AccuracyRow& r) { return r.resolution == double(f.patches); });
    measure::AccuracyRow row;
    row.method = measure::Method::PdeFit;
    row.resolution = double(f.patches);
    row.milliseconds = f.fitMs;
    row.maxError = f.hausdorff;
    row.meanError = f.rms;
    rows.push_back(row);
    std::sort(rows.begin(), rows.end(),
              [](const auto& a, const auto& b) { return a.resolution < b.resolution; });
    chart_->setRows(std::move(rows));
    chart_->setOperatingResolution(double(f.patches));
}

std::optional<QString> PdeImportDialog::save(const QString& pdePath, QString* why) {
    if (!last_) {
        if (why) *why = tr("there is no fit to save yet");
        return std::nullopt;
    }
    const QFileInfo info(pdePath);
    if (info.suffix().compare(QLatin1String("pde"), Qt::CaseInsensitive) != 0) {
        if (why) *why = tr("%1: name the model .pde").arg(pdePath);
        return std::nullopt;
    }
    // The scene names the file: XML holds no control character but tab and
    // line breaks, so a name with another could not be read back.
    for (const QChar c : info.fileName())
        if (c.unicode() < 0x20 && c != QLatin1Char('\t') && c != QLatin1Char('\n') &&
            c != QLatin1Char('\r')) {
            if (why)
                *why = tr("%1: a scene cannot name a file with control characters in its name: "
                          "choose another name")
                           .arg(visibleText(pdePath));
            return std::nullopt;
        }
    std::string failed;
    if (!mesh::writeFileReplacing(pdePath.toStdString(), last_->bytes, failed)) {
        if (why) *why = QString::fromStdString(failed);
        return std::nullopt;
    }
    // The scene names the model by its file name: beside it, inside the
    // scene's folder as an FPdeSurface url must be.
    const QString scenePath =
        info.path() + QLatin1Char('/') + info.completeBaseName() + QStringLiteral(".x3d");
    QString problem;
    if (!writeSceneText(
            scenePath,
            QString::fromStdString(pde::modelScene(info.fileName().toStdString(), false)),
            problem)) {
        if (why) *why = problem;
        return std::nullopt;
    }
    return scenePath;
}

void PdeImportDialog::saveAsked() {
    // The student's own folder: the mesh may lie in the course's.
    const std::filesystem::path folder = courseware::workspaceFolder();
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    const QString start = QString::fromStdString(
        (folder / (QFileInfo(objPath_).completeBaseName().toStdString() + ".pde")).string());
    const QString path = QFileDialog::getSaveFileName(this, tr("Save the PDE model"), start,
                                                      tr("PDE models (*.pde)"));
    if (path.isEmpty()) return;
    QString why;
    const auto scene = save(path, &why);
    if (!scene) {
        warnPlainly(this, windowTitle(), why);
        return;
    }
    Q_EMIT sceneSaved(*scene);
    accept();
}

} // namespace fl::suite
