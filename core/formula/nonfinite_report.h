#pragma once
// Finds where in the formula a NaN or infinity first appears, so it can be
// reported once with the formula location instead of silently spreading.
#include "diagnostic.h"
#include "eval_scalar.h"

#include <atomic>
#include <optional>

namespace fl::formula {

// Re-evaluates `p` and returns a warning located at the first operation whose
// operands were finite but whose result was not; nullopt when the outputs are
// finite (or a non-finite input was passed in).
std::optional<Diagnostic> explainNonFinite(const Tape& tape, const std::vector<double>& params,
                                           const Point& p);

// Reports at most once per definition, from any thread: hot loops call
// `shouldReport()` only after they have seen a non-finite value.
class NonFiniteOnce {
  public:
    bool shouldReport() { return !reported_.exchange(true); }

  private:
    std::atomic<bool> reported_{false};
};

} // namespace fl::formula
