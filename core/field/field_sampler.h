#pragma once
// A function shape as every module samples it — the mesher, picking, haptic
// contact, the grader: an implicit / explicit (FRep) definition, f >= 0
// inside, at a fixed time t with chosen parameter values, over a domain box,
// optionally closed by the box (the solid is cut by the box, so its mesh is
// closed where the shape meets the box). One `FieldSampler` per thread holds
// the formula engine's evaluators and counts what it evaluated.
#include "formula/eval_batch.h"
#include "formula/eval_gradient.h"
#include "formula/eval_interval.h"
#include "formula/eval_scalar.h"
#include "formula/tape.h"
#include "formula/tape_simplify.h"

#include "box3.h"

#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace fl::field {

enum class BoxBoundary : std::uint8_t {
    Closed, // the box cuts the solid: faces on the box close the mesh (default)
    Open,   // the mesh simply stops at the box: open where the shape leaves it
};

// A displacement texture (FTexture3D): d is added to f (positive d adds
// material), read in its own box mapped onto the geometry's: x, y, z in the
// component's box, u, v, w the point's place in the geometry's box in [0, 1].
struct Displacement {
    formula::Tape tape; // one value d
    Box3 componentBox;
};

struct ImplicitField {
    formula::Tape tape; // first output is f
    Box3 box;
    std::optional<Displacement> displacement;
    double t = 0;
    std::vector<std::pair<std::string, double>> parameters; // values other than the defaults
    BoxBoundary boundary = BoxBoundary::Closed;
};

struct EvaluationCounts {
    std::size_t points = 0;    // point evaluations (batch and scalar)
    std::size_t gradients = 0; // value-and-gradient evaluations
    std::size_t intervals = 0; // box evaluations
    EvaluationCounts& operator+=(const EvaluationCounts& o) {
        points += o.points;
        gradients += o.gradients;
        intervals += o.intervals;
        return *this;
    }
};

// A formula narrowed to a region: the field's tape with what the region's
// interval decided dropped (formula/tape_simplify.h). Immutable, so the
// samplers of one field share it (FieldSampler::adopt).
struct NarrowedTape {
    formula::Tape tape;
    std::vector<formula::Keep> decided; // per instruction of the field's tape
    std::vector<std::int32_t> source;   // per instruction of `tape`: its index in the field's
    std::uint64_t hash = 0;             // of `decided`
};

class FieldSampler {
  public:
    explicit FieldSampler(const ImplicitField& field);

    // f at n points (x, y, z arrays); the box does not enter (see interval).
    void values(const double* x, const double* y, const double* z, std::size_t n, double* out);
    double value(const Vec3& p);
    // f and its gradient.
    formula::Dual gradient(const Vec3& p);
    // The same at n points at once (much cheaper per point).
    void gradients(const Vec3* points, std::size_t n, formula::Dual* out);
    // An interval containing f over the box [lo, hi] — for a closed boundary,
    // of min(f, distance to the domain box's faces): only its sign is used
    // (can the solid's boundary pass through here?), so the two units may mix.
    formula::Interval interval(const Vec3& lo, const Vec3& hi);

    // Narrows the sampler to the box [lo, hi] (issue 31 §1): the min, max
    // and select operations whose interval over the box decides them drop
    // their dead operand (formula/tape_simplify.h), and values, gradients and
    // intervals run that shorter tape until widen(). Every point evaluated
    // meanwhile must lie in the box; the results are the full tape's, bit
    // for bit. Narrowings nest (an octree's boxes): each simplifies the
    // tape the sampler runs at the time, and widen() undoes the last one.
    // The shorter tapes' evaluators are kept for the next boxes that decide
    // the same (the last kCachedTapes).
    void narrow(const Vec3& lo, const Vec3& hi);
    void widen();
    // The tape the sampler runs now (null while it runs the field's own), to
    // hand to another sampler of the same field: adopt() makes that one run
    // it, as a narrowing that widen() undoes (null: the field's own again).
    // A tape is known by what was decided, not by the boxes: two boxes that
    // decide the same share one tape and one set of evaluators.
    std::shared_ptr<const NarrowedTape> tapeNow() const;
    void adopt(const std::shared_ptr<const NarrowedTape>& tape);
    // Instructions the evaluators run now (the full tape's when wide).
    std::size_t instructions() const;

    const EvaluationCounts& counts() const { return counts_; }
    const ImplicitField& field() const { return field_; }

  private:
    // The displacement's view of a point: (x', y', z', u, v, w).
    std::array<double, 6> mapped(const Vec3& p) const;

    // The evaluators of one tape (the field's, or a simplified one).
    struct Evaluators;
    struct Simplified;
    static constexpr std::size_t kCachedTapes = 256;

    // The cached evaluators of the tape that decides decided_ (made if new,
    // from `parent`'s tape and keep_), or of `adopted` when given.
    std::shared_ptr<Evaluators> evaluatorsFor(std::uint64_t hash,
                                              const std::shared_ptr<const NarrowedTape>& adopted,
                                              const Evaluators* parent);
    void push(std::shared_ptr<Evaluators> e);

    const ImplicitField& field_;
    bool clip_;
    // The narrowings in force, the field's own tape at the bottom; now_ is
    // the top's (evaluators stay alive while on it, even once evicted).
    std::vector<std::shared_ptr<Evaluators>> stack_;
    Evaluators* now_;
    std::vector<Simplified> simplified_;
    std::vector<formula::Keep> keep_, decided_;
    std::uint64_t uses_ = 0; // a clock for evicting the least recently used
    // The displacement's evaluators (when there is one).
    struct DisplacementEvaluators;
    std::unique_ptr<DisplacementEvaluators> displacement_;
    std::array<std::vector<double>, 6> mappedInputs_;
    std::vector<double> displacementValues_;
    std::vector<formula::Point> gradientPoints_;
    EvaluationCounts counts_;

  public:
    ~FieldSampler();
};

// A sampler narrowed to a box (or running an adopted tape) while this lives.
class Narrowing {
  public:
    Narrowing(FieldSampler& sampler, const Vec3& lo, const Vec3& hi) : sampler_(sampler) {
        sampler_.narrow(lo, hi);
    }
    // Running a tape another sampler narrowed to (FieldSampler::adopt).
    Narrowing(FieldSampler& sampler, const std::shared_ptr<const NarrowedTape>& tape)
        : sampler_(sampler) {
        sampler_.adopt(tape);
    }
    ~Narrowing() { sampler_.widen(); }
    Narrowing(const Narrowing&) = delete;
    Narrowing& operator=(const Narrowing&) = delete;

  private:
    FieldSampler& sampler_;
};

} // namespace fl::field
