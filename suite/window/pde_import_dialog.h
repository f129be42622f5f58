#pragma once
// File → Import Mesh as PDE… (issue 30 §3): a polygon mesh fitted as PDE
// patches while the student watches. A slider sets the error to reach or
// the number of patches; each setting is fitted on a worker thread (a newer
// one cancels the running fit) exactly as `functionlab pde fit` fits it,
// and shown beside the original with its distance to the original as colour
// on the surface, with the file's size, the RMS and Hausdorff distance and
// the fit's time. Every fit made is a point of the chart of error against
// patches ("Measure the curve" fits a sweep of counts). Save writes the
// .pde and a scene beside it that names it, and the window opens the scene.
#include "mesh/mesh.h"
#include "pde/fit_measure.h"
#include "platform/newest_only_worker.h"

#include <QDialog>
#include <QTimer>

#include <memory>
#include <optional>
#include <vector>

class QComboBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QSlider;

namespace fl::viewer {
class SceneWidget;
}

namespace fl::suite {

class AccuracyChart;

class PdeImportDialog : public QDialog {
    Q_OBJECT
  public:
    explicit PdeImportDialog(QWidget* parent = nullptr);
    ~PdeImportDialog() override;

    // Reads the mesh on a worker thread (the dialog says it is reading: a
    // large file must not freeze the window), then fits it. A file that is
    // not a mesh one can fit is said by loadFailed, with a located message.
    void load(const QString& objPath);

    enum class Goal { Error, Patches };
    // What the slider sets: the RMS miss to reach (a fraction of the box
    // diagonal), or the number of patches. Fits at once.
    void setGoal(Goal goal, double value);
    Goal goal() const { return goal_; }
    double goalValue() const;

    // The last fit shown (none before the first ends, or when it failed).
    struct Figures {
        std::size_t patches = 0, maxRadii = 0, bytes = 0, objBytes = 0;
        double rms = 0, hausdorff = 0; // of the box diagonal
        double fitMs = 0;
    };
    const std::optional<Figures>& figures() const { return figures_; }
    bool fitting() const;

    // Fits each count of `counts` in turn, adding every fit to the chart.
    void measureCurve(std::vector<std::size_t> counts = {4, 8, 16, 32, 64, 128});

    // Writes the last fit to `pdePath` and, beside it, a scene of the same
    // name (.x3d) whose FPdeSurface names the file; the scene's path, or
    // nothing with `why`.
    std::optional<QString> save(const QString& pdePath, QString* why);

    AccuracyChart* chart() const { return chart_; }
    viewer::SceneWidget* view() const { return view_; }
    QLabel* figuresLabel() const { return figuresText_; }
    QSlider* slider() const { return slider_; }

  Q_SIGNALS:
    void fitted(); // a fit ended (shown, failed, or cancelled by a newer one)
    // The file given to load() could not be read as a mesh ("notes.obj:2:7: ...").
    void loadFailed(const QString& why);
    // Save wrote this scene: the window opens it.
    void sceneSaved(const QString& scenePath);

  private:
    // The mesh as read, with what every fit of it needs: the OBJ lines of its
    // triangles (for located messages) and its distance tree, built once
    // (each fit is measured and coloured against it).
    struct Original {
        mesh::Mesh mesh;
        std::vector<std::uint32_t> lines;
        std::unique_ptr<const mesh::TriangleTree> tree; // of `mesh`
        std::size_t fileBytes = 0;
    };
    struct Read {
        std::shared_ptr<const Original> original;
        QString why; // empty when read
    };
    static Read readOriginal(const QString& objPath); // on the reader
    void readDone(const QString& objPath, Read r);    // on the interface thread
    struct Job {
        int generation = 0;
        std::shared_ptr<const Original> original;
        Goal goal = Goal::Error;
        double value = 0;
        bool curve = false; // a count of "Measure the curve"
    };
    struct Outcome {
        std::optional<pde::FitMeasure> measured;
        double fitMs = 0;
        QString why; // empty when measured
    };
    Outcome runFit(const Job& job);          // on the worker
    void fitDone(const Job& job, Outcome r); // on the interface thread
    void requestFit();
    void showFit(const Outcome& r);
    // The goal on the combo box and the slider, without fitting (a value
    // outside the slider's range is clamped to it).
    void showGoal(Goal goal, double value);
    void showGoalText(); // the goal in words beside the slider
    void saveAsked();
    void addChartRow(const Figures& f);

    std::shared_ptr<const Original> original_;
    QString objPath_;
    Goal goal_ = Goal::Error;
    double value_ = 0.003; // the goal's error or patch count
    int generation_ = 0;
    std::vector<std::size_t> curve_; // counts still to fit for the chart
    std::optional<Figures> figures_;
    std::optional<pde::FitMeasure> last_; // what Save writes

    QComboBox* goals_;
    QSlider* slider_;
    QLabel* goalText_;
    viewer::SceneWidget* view_;
    AccuracyChart* chart_;
    QLabel* figuresText_;
    QLabel* legend_;
    QProgressBar* progress_;
    QPushButton *curveButton_, *saveButton_;
    QTimer settle_; // a slider still moving is not fitted at every step

    std::shared_ptr<bool> alive_ = std::make_shared<bool>(true);
    // Last: they stop and join the running read and fit before the rest goes.
    platform::NewestOnlyWorker<QString, Read> reader_;
    platform::NewestOnlyWorker<Job, Outcome> worker_;
};

} // namespace fl::suite
