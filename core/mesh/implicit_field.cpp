#include "implicit_field.h"

#include <algorithm>
#include <cmath>

namespace fl::mesh {

double Box3::longestSide() const {
    return std::max({size(0), size(1), size(2)});
}

double Box3::diagonal() const {
    return std::hypot(size(0), size(1), size(2));
}

bool Box3::valid() const {
    for (int a = 0; a < 3; ++a)
        if (!(std::isfinite(lo[std::size_t(a)]) && std::isfinite(hi[std::size_t(a)]) &&
              size(a) > 0))
            return false;
    return true;
}

namespace {

template <class Evaluator>
void setParameters(Evaluator& e, const ImplicitField& field) {
    for (const auto& [name, v] : field.parameters)
        e.parameters().set(name, v);
}

} // namespace

FieldSampler::FieldSampler(const ImplicitField& field)
    : field_(field), clip_(field.boundary == BoxBoundary::Closed), batch_(field.tape),
      scalar_(field.tape), gradient_(field.tape), interval_(field.tape) {
    setParameters(batch_, field);
    setParameters(scalar_, field);
    setParameters(gradient_, field);
    setParameters(interval_, field);
}

void FieldSampler::values(const double* x, const double* y, const double* z, std::size_t n,
                          double* out) {
    formula::BatchInputs in;
    in.set(formula::Input::X, x);
    in.set(formula::Input::Y, y);
    in.set(formula::Input::Z, z);
    in.set(formula::Input::T, field_.t);
    batch_.evaluate(in, n, out);
    counts_.points += n;
}

double FieldSampler::value(const std::array<double, 3>& p) {
    ++counts_.points;
    return scalar_.evaluate(formula::pointXYZ(p[0], p[1], p[2], field_.t));
}

formula::Dual FieldSampler::gradient(const std::array<double, 3>& p) {
    ++counts_.gradients;
    return gradient_.evaluate(formula::pointXYZ(p[0], p[1], p[2], field_.t));
}

formula::Interval FieldSampler::interval(const std::array<double, 3>& lo,
                                         const std::array<double, 3>& hi) {
    ++counts_.intervals;
    formula::Interval r =
        interval_.evaluate(formula::boxXYZ(lo[0], hi[0], lo[1], hi[1], lo[2], hi[2], field_.t));
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

} // namespace fl::mesh
