#pragma once
// Random well-formed formulas over x, y, z for property tests.
#include <random>
#include <string>

namespace fl::formula::testing {

// A random expression of at most `depth` levels using every operator family.
std::string randomFormula(std::mt19937_64& rng, int depth);

} // namespace fl::formula::testing
