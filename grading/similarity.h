#pragma once
// Are two submissions the same model? Each shown function shape's field is
// reduced to the set of its sub-expressions as shapes — constants, names and
// placement forgotten (a number is just "a constant"; x, y and z are "a
// coordinate", so moving, scaling or turning a part changes nothing), the
// operands of commutative operations (+ * min max and the R-functions) taken
// in any order. What the starter scene already has is subtracted; what is
// left is compared (Jaccard: shared over all).
#include "scene/scene.h"

#include <cstdint>
#include <set>
#include <string>
#include <vector>

namespace fl::grading {

using ModelFingerprint = std::set<std::uint64_t>;

ModelFingerprint modelFingerprint(const scene::Scene& scene);

// |a ∩ b| / |a ∪ b| (1 for two empty sets: nothing to tell them apart).
double similarity(const ModelFingerprint& a, const ModelFingerprint& b);

ModelFingerprint without(const ModelFingerprint& a, const ModelFingerprint& b);

struct SimilarPair {
    std::string first, second; // student ids
    double similarity = 0;
    std::size_t shared = 0; // sub-expressions they share beyond the starter
};

struct Fingerprinted {
    std::string student;
    ModelFingerprint fingerprint; // the starter already subtracted
};

// Pairs at or above `threshold` whose shared part has at least `minimumShared`
// sub-expressions (tiny models alike by chance are not reported), most
// similar first.
std::vector<SimilarPair> similarPairs(const std::vector<Fingerprinted>& models, double threshold,
                                      std::size_t minimumShared = 8);

} // namespace fl::grading
