#pragma once
// Do two fields show the same solid in a box? The sign of f (f > 0 inside)
// compared cell by cell: the interval evaluator proves cells where both
// have one sign (or where an `activity` field shows they are equal), sample
// points look for a witness where they differ, and undecided cells are
// halved down to a depth, breadth first (every cell of a depth before the
// next: a difference anywhere is found at the coarsest depth that shows it,
// not after a corner is searched to the bottom). Before giving up, the
// centres of the cells still queued and a fixed spread of points are tried as
// witnesses. Deterministic (a fixed order) and bounded (an evaluation budget
// shared by a whole submission).
#include "field/field_sampler.h"

#include <cstddef>
#include <optional>

namespace fl::grading {

// Work a check may still spend, in instructions evaluated: a point costs
// its tape's length, an interval four times that (cost() below), so a
// submission with huge formulas gets fewer evaluations, not more time.
struct Budget {
    std::size_t left = 400'000'000;
    bool exceeded = false;
    // Verdicts cut short by a comparison's cap (CompareOptions::cap) or by
    // the budget: a submission's JSON says budget_exceeded when any was.
    std::size_t cutShort = 0;
    bool spend(std::size_t n) {
        if (left < n) {
            exceeded = true;
            left = 0;
            return false;
        }
        left -= n;
        return true;
    }
};

// What one point evaluation of a field costs (its tape and displacement).
std::size_t cost(const field::ImplicitField& f);

enum class Sameness : std::uint8_t {
    Same,      // proven: the sign agrees everywhere in the box (to the depth)
    Different, // a witness point where one is inside and the other not
    Unknown,   // the budget ran out first
};

struct SolidComparison {
    Sameness result = Sameness::Unknown;
    field::Vec3 witness{};             // with Different
    double witnessA = 0, witnessB = 0; // the two values there
    std::size_t unresolvedCells = 0;   // at the finest depth, neither proven nor witnessed
    bool cutShort = false;             // Unknown: the cap or the budget ended it
};

struct CompareOptions {
    int maxDepth = 9; // cells down to 1/512 of the box's sides
    // Work one comparison may spend of the budget: a change that is
    // not found by then is not claimed (Unknown), and the next question is
    // asked. Two equal fields whose equality the intervals cannot see (a
    // term multiplied by zero) would otherwise take the whole budget.
    std::size_t cap = 20'000'000;
};

// The same field, instruction for instruction (then the same solid).
bool identicalFields(const field::ImplicitField& a, const field::ImplicitField& b);

// `a` and `b` share the box (a's); `activity`, when given, is > 0 only where
// a and b may differ at all (elsewhere they are equal): cells where its
// interval stays <= 0 are the same without looking further.
SolidComparison compareSolids(const field::ImplicitField& a, const field::ImplicitField& b,
                              const field::ImplicitField* activity, Budget& budget,
                              const CompareOptions& options = {});

} // namespace fl::grading
