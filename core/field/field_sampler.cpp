#include "field_sampler.h"

#include "domain_mapping.h"

#include <algorithm>
#include <cmath>

namespace fl::field {

namespace {

template <class Evaluator>
void setParameters(Evaluator& e, const ImplicitField& field) {
    for (const auto& [name, v] : field.parameters)
        e.parameters().set(name, v);
}

} // namespace

struct FieldSampler::DisplacementEvaluators {
    explicit DisplacementEvaluators(const formula::Tape& tape)
        : batch(tape), scalar(tape), gradientXyz(tape),
          gradientUvw(tape, {formula::Input::U, formula::Input::V, formula::Input::W}),
          interval(tape), readsUvw(tape.usesInput[std::size_t(formula::Input::U)] ||
                                   tape.usesInput[std::size_t(formula::Input::V)] ||
                                   tape.usesInput[std::size_t(formula::Input::W)]) {}
    formula::BatchEvaluator batch;
    formula::ScalarEvaluator scalar;
    formula::GradientEvaluator gradientXyz, gradientUvw;
    formula::IntervalEvaluator interval;
    bool readsUvw;
};

// The evaluators of one tape: the interval evaluator at once (an octree's
// nodes need only it), the others when first asked for.
struct FieldSampler::Evaluators {
    Evaluators(std::shared_ptr<const NarrowedTape> n, const ImplicitField& f)
        : narrowed(std::move(n)), tape(narrowed ? narrowed->tape : f.tape), field(f),
          mayNarrow(formula::hasChoices(tape)), interval(tape) {
        setParameters(interval, field);
    }
    std::shared_ptr<const NarrowedTape> narrowed; // null: the field's own tape
    const formula::Tape& tape;
    const ImplicitField& field;
    bool mayNarrow; // the tape has a min, max or select left
    formula::IntervalEvaluator interval;

    // (A simplified tape is interpreted: a mesher block evaluates it a few
    // times, and compiling each of a union's many patterns cost more.)
    formula::BatchEvaluator& batch() { return made(batch_, narrowed == nullptr); }
    formula::ScalarEvaluator& scalar() { return made(scalar_); }
    formula::GradientEvaluator& gradient() { return made(gradient_); }

  private:
    template <class E, class... Options>
    E& made(std::optional<E>& e, Options... options) {
        if (!e) {
            e.emplace(tape, options...);
            setParameters(*e, field);
        }
        return *e;
    }
    std::optional<formula::BatchEvaluator> batch_;
    std::optional<formula::ScalarEvaluator> scalar_;
    std::optional<formula::GradientEvaluator> gradient_;
};

// A simplified tape's evaluators, found again by what was decided.
struct FieldSampler::Simplified {
    std::uint64_t hash = 0;
    std::shared_ptr<Evaluators> evaluators;
    std::uint64_t lastUse = 0;
};

FieldSampler::~FieldSampler() = default;

std::array<double, 6> FieldSampler::mapped(const Vec3& p) const {
    return componentView(p, field_.box, field_.displacement->componentBox);
}

FieldSampler::FieldSampler(const ImplicitField& field)
    : field_(field),
      clip_(field.boundary == BoxBoundary::Closed), stack_{std::make_shared<Evaluators>(nullptr,
                                                                                        field)},
      now_(stack_.back().get()) {
    if (field.displacement)
        displacement_ = std::make_unique<DisplacementEvaluators>(field.displacement->tape);
}

void FieldSampler::values(const double* x, const double* y, const double* z, std::size_t n,
                          double* out) {
    formula::BatchInputs in;
    in.set(formula::Input::X, x);
    in.set(formula::Input::Y, y);
    in.set(formula::Input::Z, z);
    in.set(formula::Input::T, field_.t);
    now_->batch().evaluate(in, n, out);
    counts_.points += n;
    if (!displacement_) return;
    for (auto& v : mappedInputs_)
        v.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const auto m = mapped({x[i], y[i], z[i]});
        for (std::size_t k = 0; k < 6; ++k)
            mappedInputs_[k][i] = m[k];
    }
    formula::BatchInputs d;
    d.set(formula::Input::X, mappedInputs_[0].data());
    d.set(formula::Input::Y, mappedInputs_[1].data());
    d.set(formula::Input::Z, mappedInputs_[2].data());
    d.set(formula::Input::U, mappedInputs_[3].data());
    d.set(formula::Input::V, mappedInputs_[4].data());
    d.set(formula::Input::W, mappedInputs_[5].data());
    d.set(formula::Input::T, field_.t);
    displacementValues_.resize(n);
    displacement_->batch.evaluate(d, n, displacementValues_.data());
    for (std::size_t i = 0; i < n; ++i)
        out[i] += displacementValues_[i];
}

double FieldSampler::value(const Vec3& p) {
    ++counts_.points;
    const double f = now_->scalar().evaluate(formula::pointXYZ(p[0], p[1], p[2], field_.t));
    if (!displacement_) return f;
    const auto m = mapped(p);
    return f + displacement_->scalar.evaluate({m[0], m[1], m[2], field_.t, m[3], m[4], m[5]});
}

formula::Dual FieldSampler::gradient(const Vec3& p) {
    ++counts_.gradients;
    formula::Dual d = now_->gradient().evaluate(formula::pointXYZ(p[0], p[1], p[2], field_.t));
    if (!displacement_) return d;
    // Chain rule through the linear map: d/dp = d/dx' * (c / g) + d/du * (1 / g).
    const auto m = mapped(p);
    const formula::Point q{m[0], m[1], m[2], field_.t, m[3], m[4], m[5]};
    const formula::Dual dx = displacement_->gradientXyz.evaluate(q);
    formula::Dual du{};
    if (displacement_->readsUvw) du = displacement_->gradientUvw.evaluate(q);
    d.v += dx.v;
    const Box3& g = field_.box;
    const Box3& c = field_.displacement->componentBox;
    for (std::size_t a = 0; a < 3; ++a) {
        const double size = g.hi[a] - g.lo[a];
        d.d[a] += dx.d[a] * (c.hi[a] - c.lo[a]) / size + du.d[a] / size;
    }
    return d;
}

void FieldSampler::gradients(const Vec3* points, std::size_t n, formula::Dual* out) {
    if (displacement_) { // the chain rule through the mapping, point by point
        for (std::size_t i = 0; i < n; ++i)
            out[i] = gradient(points[i]);
        return;
    }
    counts_.gradients += n;
    gradientPoints_.resize(n);
    for (std::size_t i = 0; i < n; ++i)
        gradientPoints_[i] = formula::pointXYZ(points[i][0], points[i][1], points[i][2], field_.t);
    now_->gradient().evaluateMany(gradientPoints_.data(), n, out);
}

formula::Interval FieldSampler::interval(const Vec3& lo, const Vec3& hi) {
    ++counts_.intervals;
    formula::Interval r = now_->interval.evaluate(
        formula::boxXYZ(lo[0], hi[0], lo[1], hi[1], lo[2], hi[2], field_.t));
    if (displacement_) {
        const auto mlo = mapped(lo), mhi = mapped(hi);
        formula::Box b{};
        b[std::size_t(formula::Input::T)] = formula::Interval::point(field_.t);
        for (std::size_t k = 0; k < 6; ++k) {
            const std::size_t input = k < 3 ? k : std::size_t(formula::Input::U) + (k - 3);
            b[input] = formula::Interval::of(std::min(mlo[k], mhi[k]), std::max(mlo[k], mhi[k]));
        }
        const formula::Interval d = displacement_->interval.evaluate(b);
        if (r.empty() || d.empty())
            r = formula::Interval::undefined();
        else // rounded outward, so the sum still contains every value
            r = formula::Interval::of(std::nextafter(r.lo + d.lo, -HUGE_VAL),
                                      std::nextafter(r.hi + d.hi, HUGE_VAL), r.nan || d.nan);
    }
    if (!clip_) return r;
    // The box function over [lo, hi]: from its smallest to its largest value.
    double bLo = std::numeric_limits<double>::infinity(), bHi = bLo;
    const Box3& b = field_.box;
    for (std::size_t a = 0; a < 3; ++a) {
        bLo = std::min({bLo, lo[a] - b.lo[a], b.hi[a] - hi[a]});
        bHi = std::min({bHi, hi[a] - b.lo[a], b.hi[a] - lo[a]});
    }
    if (r.empty()) return r;
    return formula::Interval::of(std::min(r.lo, bLo), std::min(r.hi, bHi), r.nan);
}

void FieldSampler::push(std::shared_ptr<Evaluators> e) {
    now_ = e.get();
    stack_.push_back(std::move(e));
}

void FieldSampler::narrow(const Vec3& lo, const Vec3& hi) {
    const std::shared_ptr<Evaluators> parent = stack_.back();
    if (!parent->mayNarrow) return push(parent);
    ++counts_.intervals;
    parent->interval.evaluate(formula::boxXYZ(lo[0], hi[0], lo[1], hi[1], lo[2], hi[2], field_.t),
                              keep_);
    // The decisions carried back to the field's tape, added to the parent's.
    const NarrowedTape* from = parent->narrowed.get();
    if (from)
        decided_ = from->decided;
    else
        decided_.assign(field_.tape.code.size(), formula::Keep::All);
    bool any = false;
    for (std::size_t i = 0; i < keep_.size(); ++i)
        if (keep_[i] != formula::Keep::All) {
            decided_[from ? std::size_t(from->source[i]) : i] = keep_[i];
            any = true;
        }
    if (!any) return push(parent);
    std::uint64_t hash = 1469598103934665603ull; // FNV-1a
    for (formula::Keep k : decided_)
        hash = (hash ^ std::uint64_t(k)) * 1099511628211ull;
    push(evaluatorsFor(hash, nullptr, parent.get()));
}

std::shared_ptr<FieldSampler::Evaluators>
FieldSampler::evaluatorsFor(std::uint64_t hash, const std::shared_ptr<const NarrowedTape>& adopted,
                            const Evaluators* parent) {
    const std::vector<formula::Keep>& decided = adopted ? adopted->decided : decided_;
    ++uses_;
    for (Simplified& s : simplified_)
        if (s.hash == hash && s.evaluators->narrowed->decided == decided) {
            s.lastUse = uses_;
            return s.evaluators;
        }
    if (simplified_.size() == kCachedTapes) // the least recently used makes room
        simplified_.erase(std::min_element(
            simplified_.begin(), simplified_.end(),
            [](const Simplified& a, const Simplified& b) { return a.lastUse < b.lastUse; }));
    std::shared_ptr<const NarrowedTape> narrowed = adopted;
    if (!narrowed) {
        // Simplified from the parent's tape with this box's decisions (the
        // same tape as the field's with all of decided_, made from fewer
        // instructions), its instructions traced back to the field's.
        auto made = std::make_shared<NarrowedTape>();
        made->tape = formula::simplifyTape(parent->tape, keep_, &made->source);
        if (parent->narrowed)
            for (std::int32_t& i : made->source)
                i = parent->narrowed->source[std::size_t(i)];
        made->decided = decided_;
        made->hash = hash;
        narrowed = std::move(made);
    }
    simplified_.push_back({hash, std::make_shared<Evaluators>(std::move(narrowed), field_), uses_});
    return simplified_.back().evaluators;
}

void FieldSampler::adopt(const std::shared_ptr<const NarrowedTape>& tape) {
    if (!tape) return push(stack_.front());
    push(evaluatorsFor(tape->hash, tape, nullptr));
}

void FieldSampler::widen() {
    if (stack_.size() > 1) stack_.pop_back();
    now_ = stack_.back().get();
}

std::shared_ptr<const NarrowedTape> FieldSampler::tapeNow() const {
    return now_->narrowed;
}

std::size_t FieldSampler::instructions() const {
    return now_->tape.code.size();
}

} // namespace fl::field
