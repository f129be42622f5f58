#pragma once
// The Accuracy panel: what accuracy costs in time, for one function shape of
// the scene. A sweep of resolutions — the adaptive mesher and dense marching
// cubes, the same rows `functionlab bench accuracy` prints, from the same
// code (bench/accuracy_sweep.h) — runs on a worker thread, cancellable, with
// progress, and is drawn as error against time (AccuracyChart). The shape's
// resolution now is ringed; clicking a point, or typing a target error,
// chooses the resolution the view meshes the shape at; "Write into the
// scene" makes that choice part of the scene text (resolution, and the
// level of detail's coarsest resolution). For a PDE model (FPdeSurface) the
// sweep is its drawing: the time to mesh it at each resolution against how
// far that mesh is from the model's finest drawing (ChartCurves::pdeDrawing).
#include "accuracy_chart.h"
#include "panel.h"

#include "field/field_sampler.h"
#include "measure/accuracy_sweep.h"
#include "platform/newest_only_worker.h"
#include "scene/scene.h"

#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

class QComboBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;

namespace fl::scene {
struct Node;
}
namespace fl::pde {
struct Model;
}

namespace fl::suite {

class AccuracyPanel : public Panel {
    Q_OBJECT
  public:
    explicit AccuracyPanel(QWidget* parent = nullptr);
    ~AccuracyPanel() override;

    // The resolutions a sweep measures (by default 8 to 256).
    static std::vector<double> sweepResolutions();
    // The touch sweep's rows in words (the status line after a touch sweep).
    static QString touchSummary(const std::vector<measure::AccuracyRow>& rows);
    // A PDE model's drawing sweep in words.
    static QString pdeSummary(const std::vector<measure::AccuracyRow>& rows);
    void setResolutions(std::vector<double> resolutions);
    const std::vector<double>& resolutions() const { return resolutions_; }

    // What is measured: meshing (the adaptive mesher against dense marching
    // cubes) or touch (function contact against polygon contact, per tick).
    enum class Cost { Meshing, Touch };
    void setCost(Cost cost);
    Cost cost() const { return cost_; }

    void measure(); // starts a sweep of the chosen shape (cancels one running)
    void cancel();
    bool measuring() const;
    // Sets the resolution whose error is at most `target` (a fraction of the
    // box diagonal), as measured; false when no measured resolution reaches it.
    bool chooseTargetError(double target);

    void writeChoice(); // asks the window to write the current choice

    // Its place in the window: a chosen resolution is meshed from then on;
    // Write into the scene edits the editor's text.
    void attach(PanelContext& context) override;
    // Writes the choice of resolution for `geometry` into the editor's text
    // (one undoable edit). False, said through the window, if not.
    bool writeResolution(const scene::Node* geometry, double resolution);

    AccuracyChart* chart() const { return chart_; }
    QPushButton* writeButton() const { return write_; }
    QComboBox* shapes() const { return shapes_; }
    QLabel* status() const { return status_; }

  public Q_SLOTS:
    void sceneChanged(std::shared_ptr<const fl::scene::Scene> scene) override;

  Q_SIGNALS:
    // Mesh this FGeometry at this resolution (the window tells the player).
    void resolutionChosen(const fl::scene::Node* geometry, double resolution);
    void measured(); // a sweep finished (or was cancelled)
    // Write this FGeometry's chosen resolution into the scene text.
    void writeRequested(const fl::scene::Node* geometry, double resolution);

  private:
    PanelContext* context_ = nullptr;
    struct Candidate {
        const scene::Node* geometry; // the FGeometry (its FShape's), or the FTransform
        QString name;
        std::shared_ptr<const field::ImplicitField> field;
        double resolution;
        bool written;                            // a FGeometry of the scene file: it can be edited
        std::pair<double, double> lodRange;      // {0, 0}: no level of detail
        std::shared_ptr<const pde::Model> model; // an FPdeSurface's (then no field)
    };
    // The chart's curves for the shape chosen and the cost.
    ChartCurves curvesFor(const Candidate* c) const;
    void choose(double resolution);

    std::shared_ptr<const scene::Scene> scene_;
    std::vector<double> resolutions_ = sweepResolutions();
    std::vector<Candidate> candidates_;
    QComboBox* shapes_;
    QComboBox* costs_;
    Cost cost_ = Cost::Meshing;
    AccuracyChart* chart_;
    QProgressBar* progress_;
    QPushButton *measure_, *cancel_, *write_;
    QLineEdit* target_;
    QLabel* status_;

    // One sweep at a time; a newer one waits for the running one to stop.
    struct Sweep {
        int generation = 0; // results of an older one are not shown
        Cost cost = Cost::Meshing;
        std::shared_ptr<const field::ImplicitField> field;
        std::shared_ptr<const pde::Model> model; // a PDE model's drawing, instead
        std::vector<double> resolutions;
    };
    struct SweepResult {
        std::vector<measure::AccuracyRow> rows;
        QString summary;
    };
    SweepResult runSweep(const Sweep& sweep); // on the worker
    void sweepFinished(const Sweep& sweep, SweepResult result);
    // Stops the running sweep and forgets it: its rows are not shown.
    void dropSweep();

    int generation_ = 0;
    bool running_ = false;
    std::shared_ptr<bool> alive_ = std::make_shared<bool>(true); // for progress from the worker
    // Last: it stops and joins the sweep before the rest goes.
    platform::NewestOnlyWorker<Sweep, SweepResult> worker_;
};

} // namespace fl::suite
