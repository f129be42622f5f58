#pragma once
// The Accuracy panel: what accuracy costs in time, for one function shape of
// the scene. A sweep of resolutions — the adaptive mesher and dense marching
// cubes, the same rows `functionlab bench accuracy` prints, from the same
// code (bench/accuracy_sweep.h) — runs on a worker thread, cancellable, with
// progress, and is drawn as error against time (AccuracyChart). The shape's
// resolution now is ringed; clicking a point, or typing a target error,
// chooses the resolution the view meshes the shape at.
#include "accuracy_chart.h"
#include "panel.h"

#include "field/field_sampler.h"

#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

class QComboBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;

namespace fl::scene {
struct Node;
}

namespace fl::suite {

class AccuracyPanel : public Panel {
    Q_OBJECT
  public:
    explicit AccuracyPanel(QWidget* parent = nullptr);
    ~AccuracyPanel() override;

    // The resolutions a sweep measures.
    static std::vector<double> sweepResolutions();

    void measure(); // starts a sweep of the chosen shape (cancels one running)
    void cancel();
    bool measuring() const;
    // Sets the resolution whose error is at most `target` (a fraction of the
    // box diagonal), as measured; false when no measured resolution reaches it.
    bool chooseTargetError(double target);

    AccuracyChart* chart() const { return chart_; }
    QComboBox* shapes() const { return shapes_; }
    QLabel* status() const { return status_; }

  public Q_SLOTS:
    void sceneChanged(std::shared_ptr<const fl::scene::Scene> scene) override;

  Q_SIGNALS:
    // Mesh this FGeometry at this resolution (the window tells the player).
    void resolutionChosen(const fl::scene::Node* geometry, double resolution);
    void measured(); // a sweep finished (or was cancelled)

  private:
    struct Candidate {
        const scene::Node* geometry; // the FGeometry (its FShape's), or the FTransform
        QString name;
        std::shared_ptr<const field::ImplicitField> field;
        double resolution;
    };
    void choose(double resolution);

    std::shared_ptr<const scene::Scene> scene_;
    std::vector<Candidate> candidates_;
    QComboBox* shapes_;
    AccuracyChart* chart_;
    QProgressBar* progress_;
    QPushButton *measure_, *cancel_;
    QLineEdit* target_;
    QLabel* status_;

    std::thread worker_;
    std::atomic<bool> stop_{false};
    std::atomic<bool> running_{false};
    std::shared_ptr<bool> alive_ = std::make_shared<bool>(true);
};

} // namespace fl::suite
