#include "accuracy_panel.h"

#include "editor/code_editor.h"
#include "plain_text.h"

#include "haptics/haptics_bench.h"
#include "measure/accuracy_sweep.h"
#include "measure/pde_drawing_sweep.h"
#include "mesh/scene_meshing.h"
#include "scene/field_access.h"
#include "scene/scene_edit.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QStatusBar>
#include <QTextCursor>
#include <QTextDocument>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace fl::suite {

std::vector<double> AccuracyPanel::sweepResolutions() {
    return {8, 12, 16, 24, 32, 48, 64, 96, 128, 192, 256};
}

void AccuracyPanel::setResolutions(std::vector<double> resolutions) {
    dropSweep();
    resolutions_ = std::move(resolutions);
    progress_->setRange(0, int(resolutions_.size()));
}

AccuracyPanel::AccuracyPanel(QWidget* parent)
    : Panel(tr("Accuracy"), QStringLiteral("accuracy"), Qt::RightDockWidgetArea, parent),
      shapes_(new QComboBox), costs_(new QComboBox), chart_(new AccuracyChart),
      progress_(new QProgressBar), measure_(new QPushButton(tr("Measure"))),
      cancel_(new QPushButton(tr("Cancel"))), write_(new QPushButton(tr("Write into the scene"))),
      target_(new QLineEdit), status_(plainLabel()),
      worker_(
          this, [this](const Sweep& sweep) { return runSweep(sweep); },
          [this](const Sweep& sweep, SweepResult r) { sweepFinished(sweep, std::move(r)); }) {
    auto* box = new QWidget;
    auto* layout = new QVBoxLayout(box);
    auto* top = new QHBoxLayout;
    top->addWidget(shapes_, 1);
    costs_->addItem(tr("meshing"));
    costs_->addItem(tr("touch"));
    costs_->setToolTip(tr("What accuracy costs: in time per mesh (the adaptive mesher against "
                          "dense marching cubes), or in time per force tick (touching the "
                          "function against touching its triangles)"));
    top->addWidget(costs_);
    layout->addLayout(top);
    // The buttons on a row of their own: the panel stays narrow enough
    // for the view to be the largest thing on a 1366-pixel screen.
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(measure_);
    buttons->addWidget(cancel_);
    buttons->addStretch(1);
    layout->addLayout(buttons);
    layout->addWidget(chart_, 1);
    layout->addWidget(progress_);
    auto* targetRow = new QHBoxLayout;
    targetRow->addWidget(new QLabel(tr("Target error:")));
    target_->setPlaceholderText(tr("e.g. 0.001 of the diagonal"));
    targetRow->addWidget(target_, 1);
    layout->addLayout(targetRow);
    auto* writeRow = new QHBoxLayout;
    writeRow->addStretch(1);
    writeRow->addWidget(write_);
    layout->addLayout(writeRow);
    write_->setToolTip(tr("Make the chosen resolution part of the scene text (resolution, and "
                          "the coarsest end of lodRange): undo with Ctrl+Z in the editor"));
    write_->setEnabled(false);
    status_->setWordWrap(true);
    layout->addWidget(status_);
    shapes_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    shapes_->setMinimumContentsLength(10);
    setWidget(box);
    cancel_->setEnabled(false);
    progress_->setRange(0, int(resolutions_.size()));
    progress_->setValue(0);
    connect(measure_, &QPushButton::clicked, this, [this] { measure(); });
    connect(cancel_, &QPushButton::clicked, this, [this] { cancel(); });
    connect(write_, &QPushButton::clicked, this, [this] { writeChoice(); });
    connect(chart_, &AccuracyChart::resolutionChosen, this, [this](double r) { choose(r); });
    connect(costs_, &QComboBox::currentIndexChanged, this,
            [this](int i) { setCost(i == 1 ? Cost::Touch : Cost::Meshing); });
    connect(target_, &QLineEdit::returnPressed, this, [this] {
        bool ok = false;
        const double t = target_->text().toDouble(&ok);
        if (!ok || !(t > 0)) {
            status_->setText(tr("a target error is a positive number, e.g. 0.001"));
            return;
        }
        if (!chooseTargetError(t))
            status_->setText(
                tr("no measured resolution reaches %1: measure, or aim higher").arg(t));
    });
    connect(shapes_, &QComboBox::currentIndexChanged, this, [this](int i) {
        chart_->setRows({});
        write_->setEnabled(false);
        if (i >= 0 && std::size_t(i) < candidates_.size()) {
            const Candidate& c = candidates_[std::size_t(i)];
            chart_->setCurves(curvesFor(&c));
            chart_->setOperatingResolution(c.resolution);
            chart_->setLevelOfDetailRange(c.lodRange.first, c.lodRange.second);
        }
    });
}

AccuracyPanel::~AccuracyPanel() {
    *alive_ = false; // the worker stops and joins the sweep as it goes
}

void AccuracyPanel::sceneChanged(std::shared_ptr<const scene::Scene> scene) {
    dropSweep();
    scene_ = std::move(scene);
    candidates_.clear();
    const QSignalBlocker quiet(shapes_);
    shapes_->clear();
    chart_->setRows({});
    // The function shapes as meshed (coarsely: only their fields are wanted).
    mesh::SceneMeshOptions o;
    o.useFileResolution = false;
    o.mesh.resolution = 4;
    o.mesh.threads = 1;
    o.standardShapes = false;
    o.placeInScene = false;
    const mesh::SceneMeshes meshes = mesh::meshScene(*scene_, o);
    for (const mesh::ShapeMesh& s : meshes.shapes) {
        // A function shape's field, or a PDE model (meshed from its patches).
        const std::shared_ptr<const pde::Model>& model = s.pdeModel;
        if ((!s.field && !model) || !s.shape) continue;
        const scene::Node* key = s.geometry ? s.geometry : s.shape;
        const double resolution =
            s.geometry ? scene::numberField(*s.geometry, "resolution", 0, 32) : 32;
        std::pair<double, double> lod{0, 0};
        if (s.geometry && scene::boolField(*s.geometry, "lod")) {
            const auto range = scene::numbersField(*s.geometry, "lodRange");
            lod = range.size() == 2 ? std::pair{range[0], range[1]} : std::pair{8.0, 256.0};
        }
        const bool written = s.geometry && s.geometry->file == 0 && !s.geometry->inProtoBody &&
                             !s.geometry->instance;
        const QString name = QString::fromStdString(s.shape->defName.empty()
                                                        ? s.shape->type + " at line " +
                                                              std::to_string(s.shape->where.line)
                                                        : s.shape->type + " " + s.shape->defName);
        candidates_.push_back({key, name, s.field, resolution, written, lod, model});
        shapes_->addItem(name);
    }
    write_->setEnabled(false);
    chart_->setCurves(curvesFor(candidates_.empty() ? nullptr : &candidates_.front()));
    if (!candidates_.empty()) {
        chart_->setOperatingResolution(candidates_.front().resolution);
        chart_->setLevelOfDetailRange(candidates_.front().lodRange.first,
                                      candidates_.front().lodRange.second);
    }
    status_->setText(candidates_.empty()
                         ? tr("no implicit, explicit or PDE shape to measure in this scene")
                         : tr("Measure: how far each mesh is from the true surface, and what it "
                              "costs"));
}

bool AccuracyPanel::measuring() const {
    return running_;
}

void AccuracyPanel::cancel() {
    worker_.cancel(); // what it measured so far is shown, "cancelled"
}

void AccuracyPanel::dropSweep() {
    ++generation_;
    worker_.cancel();
    running_ = false;
    measure_->setEnabled(true);
    cancel_->setEnabled(false);
}

void AccuracyPanel::setCost(Cost cost) {
    dropSweep();
    cost_ = cost;
    {
        const QSignalBlocker quiet(costs_);
        costs_->setCurrentIndex(cost == Cost::Touch ? 1 : 0);
    }
    const int index = shapes_->currentIndex();
    chart_->setCurves(curvesFor(index >= 0 && std::size_t(index) < candidates_.size()
                                    ? &candidates_[std::size_t(index)]
                                    : nullptr));
    status_->setText(cost == Cost::Touch
                         ? tr("Measure: what touching the shape costs per force tick, by its "
                              "function and by its triangles, and how far the touch is from the "
                              "true surface")
                         : tr("Measure: how far each mesh is from the true surface, and what it "
                              "costs"));
}

ChartCurves AccuracyPanel::curvesFor(const Candidate* c) const {
    if (cost_ == Cost::Touch) return ChartCurves::touch();
    return c && c->model ? ChartCurves::pdeDrawing() : ChartCurves::meshing();
}

namespace {

// A touch row as the chart draws it: the median tick's time, the mean
// contact error where the chart reads its error (ChartCurves::touch's y label).
measure::AccuracyRow touchRow(const haptics::TickCost& t) {
    measure::AccuracyRow r;
    r.method = t.resolution > 0 ? measure::Method::Polygons : measure::Method::Function;
    r.resolution = t.resolution;
    r.triangles = t.triangles;
    r.milliseconds = t.p50Us / 1000;
    r.maxError = t.meanError;
    r.meanError = t.meanError;
    return r;
}

} // namespace

void AccuracyPanel::measure() {
    dropSweep();
    const int index = shapes_->currentIndex();
    if (index < 0 || std::size_t(index) >= candidates_.size()) return;
    const Candidate& c = candidates_[std::size_t(index)];
    if (c.model && cost_ == Cost::Touch) {
        status_->setText(tr("a PDE model is touched by its triangles: touch is measured for "
                            "implicit and explicit shapes"));
        return;
    }
    Sweep sweep{generation_, cost_, c.field, c.model, resolutions_};
    // Polygons past 128 take long to build and say nothing new to a hand;
    // a PDE model's drawing is measured against one twice as fine as the
    // finest row, which past 128 outgrows what is worth the wait.
    if (cost_ == Cost::Touch || c.model)
        std::erase_if(sweep.resolutions, [](double r) { return r > 128; });
    chart_->setRows({});
    progress_->setRange(0, int(sweep.resolutions.size()) + (cost_ == Cost::Touch ? 1 : 0));
    progress_->setValue(0);
    measure_->setEnabled(false);
    cancel_->setEnabled(true);
    status_->setText(tr("measuring…"));
    running_ = true;
    worker_.request(std::move(sweep));
}

AccuracyPanel::SweepResult AccuracyPanel::runSweep(const Sweep& sweep) {
    const std::atomic<bool>* stop = worker_.cancelFlag();
    // What the worker has so far, on the interface thread (nothing once the
    // panel is gone or a newer sweep was asked for).
    auto progress = [this, alive = alive_, generation = sweep.generation](
                        std::vector<measure::AccuracyRow> rows, int done) {
        QMetaObject::invokeMethod(
            this,
            [this, rows = std::move(rows), done, alive, generation] {
                if (!*alive || generation != generation_) return;
                chart_->setRows(rows);
                progress_->setValue(done);
            },
            Qt::QueuedConnection);
    };
    SweepResult out;
    if (sweep.cost == Cost::Touch) {
        const auto path = haptics::pathUnderSurface(*sweep.field);
        haptics::touchSweep(*sweep.field, path, sweep.resolutions, 1, stop,
                            [&](const haptics::TickCost& t) {
                                out.rows.push_back(touchRow(t));
                                progress(out.rows, int(out.rows.size()));
                            });
        out.summary = *stop          ? tr("cancelled")
                      : path.empty() ? tr("no surface to touch was found in the box")
                                     : touchSummary(out.rows);
        return out;
    }
    if (sweep.model) {
        measure::pdeDrawingSweep(*sweep.model, sweep.resolutions, stop,
                                 [&](const measure::AccuracyRow& row) {
                                     out.rows.push_back(row);
                                     progress(out.rows, int(out.rows.size()));
                                 });
        out.summary = *stop ? tr("cancelled") : pdeSummary(out.rows);
        return out;
    }
    measure::SweepOptions o;
    o.threads = 1; // the interface keeps a core
    int done = 0;
    for (double r : sweep.resolutions) {
        if (*stop) break;
        const auto more = measure::runAccuracySweep(*sweep.field, {r}, o);
        out.rows.insert(out.rows.end(), more.begin(), more.end());
        progress(out.rows, ++done);
    }
    out.summary =
        *stop ? tr("cancelled") : QString::fromStdString(measure::accuracySummary(out.rows));
    return out;
}

void AccuracyPanel::sweepFinished(const Sweep& sweep, SweepResult result) {
    if (sweep.generation != generation_) return; // dropped: a newer sweep or scene
    running_ = false;
    measure_->setEnabled(true);
    cancel_->setEnabled(false);
    chart_->setRows(result.rows);
    status_->setText(result.summary);
    Q_EMIT measured();
}

QString AccuracyPanel::pdeSummary(const std::vector<measure::AccuracyRow>& rows) {
    if (rows.empty()) return {};
    const measure::AccuracyRow &coarse = rows.front(), &fine = rows.back();
    return tr("the PDE model at resolution %1: %2 triangles in %3 ms, max error %4; at %5: %6 "
              "triangles in %7 ms, max error %8 (of the diagonal, against its drawing at %9)")
        .arg(coarse.resolution)
        .arg(coarse.triangles)
        .arg(coarse.milliseconds, 0, 'g', 3)
        .arg(coarse.maxError, 0, 'e', 1)
        .arg(fine.resolution)
        .arg(fine.triangles)
        .arg(fine.milliseconds, 0, 'g', 3)
        .arg(fine.maxError, 0, 'e', 1)
        .arg(2 * fine.resolution);
}

QString AccuracyPanel::touchSummary(const std::vector<measure::AccuracyRow>& rows) {
    const measure::AccuracyRow* function = nullptr;
    for (const measure::AccuracyRow& r : rows)
        if (r.method == measure::Method::Function) function = &r;
    if (!function) return {};
    QString out = tr("touching the function: %1 µs a tick, mean error %2")
                      .arg(function->milliseconds * 1000, 0, 'g', 3)
                      .arg(function->maxError, 0, 'e', 1);
    for (const measure::AccuracyRow& r : rows)
        if (r.method == measure::Method::Polygons)
            out += tr("\nits %1 triangles (resolution %2): %3 µs, mean error %4")
                       .arg(r.triangles)
                       .arg(r.resolution)
                       .arg(r.milliseconds * 1000, 0, 'g', 3)
                       .arg(r.maxError, 0, 'e', 1);
    return out;
}

bool AccuracyPanel::chooseTargetError(double target) {
    double best = 0;
    const measure::Method method = chart_->curves().operatingMethod;
    for (const measure::AccuracyRow& r : chart_->rows())
        if (r.method == method && r.maxError <= target && (best == 0 || r.resolution < best))
            best = r.resolution;
    if (best == 0) return false;
    choose(best);
    return true;
}

void AccuracyPanel::choose(double resolution) {
    const int index = shapes_->currentIndex();
    if (index < 0 || std::size_t(index) >= candidates_.size()) return;
    Candidate& c = candidates_[std::size_t(index)];
    c.resolution = resolution;
    chart_->setOperatingResolution(resolution);
    status_->setText(tr("%1 is meshed at resolution %2 now").arg(c.name).arg(resolution));
    write_->setEnabled(c.written);
    Q_EMIT resolutionChosen(c.geometry, resolution);
}

void AccuracyPanel::writeChoice() {
    const int index = shapes_->currentIndex();
    if (index < 0 || std::size_t(index) >= candidates_.size()) return;
    const Candidate& c = candidates_[std::size_t(index)];
    if (c.written) Q_EMIT writeRequested(c.geometry, c.resolution);
}

void AccuracyPanel::attach(PanelContext& context) {
    context_ = &context;
    connect(this, &AccuracyPanel::resolutionChosen, this,
            [&context](const scene::Node* geometry, double resolution) {
                context.chooseResolution(geometry, resolution);
            });
    connect(this, &AccuracyPanel::writeRequested, this, &AccuracyPanel::writeResolution);
}

bool AccuracyPanel::writeResolution(const scene::Node* geometry, double resolution) {
    PanelContext& c = *context_;
    // The edits are offsets into the text the scene was read from: only when
    // that is still the editor's text.
    const std::string text = c.editor->toPlainText().toStdString();
    const auto scene = c.scene();
    if (!scene || scene->files.empty() || scene->files[0].text != text || !geometry) {
        c.problem(tr("The text changed since it was last read: wait for it to parse, then write "
                     "the resolution again."));
        return false;
    }
    std::string why;
    const auto edit = scene::resolutionEdit(*scene, *geometry, resolution, &why);
    if (!edit) {
        c.problem(tr("The resolution cannot be written into the text: %1")
                      .arg(QString::fromStdString(why)));
        return false;
    }
    // One undoable step in the editor; offsets in bytes become characters.
    QTextCursor cursor(c.editor->document());
    cursor.beginEditBlock();
    for (const scene::TextEdit& e : edit->edits()) {
        const auto at = QString::fromUtf8(text.data(), qsizetype(e.offset)).size();
        const auto end = QString::fromUtf8(text.data(), qsizetype(e.offset + e.length)).size();
        cursor.setPosition(int(at));
        cursor.setPosition(int(end), QTextCursor::KeepAnchor);
        cursor.insertText(QString::fromStdString(e.text));
    }
    cursor.endEditBlock();
    c.status->showMessage(tr("resolution %1 written into the scene").arg(resolution), 5000);
    return true;
}

} // namespace fl::suite
