#include "solid_difference.h"

#include <array>
#include <cmath>
#include <cstring>
#include <deque>
#include <vector>

namespace fl::grading {
namespace {

bool inside(double f) {
    return f > 0;
}

// Where a comparison cut short still looks: this many queued cells' centres
// and this many points of a Halton spread over the box.
constexpr std::size_t kLastLookCells = 4096;
constexpr int kLastLookSpread = 1024;

double radicalInverse(int i, int base) {
    double result = 0, f = 1.0 / base;
    for (; i > 0; i /= base, f /= base)
        result += f * (i % base);
    return result;
}

// Both intervals one side of zero, the same side.
bool sameSide(const formula::Interval& p, const formula::Interval& q) {
    if (p.empty() || q.empty() || p.nan || q.nan) return false;
    return (p.lo > 0 && q.lo > 0) || (p.hi <= 0 && q.hi <= 0);
}

bool sameOperand(const formula::Operand& a, const formula::Operand& b) {
    return a.reg == b.reg && (a.reg >= 0 || std::memcmp(&a.value, &b.value, sizeof a.value) == 0);
}

bool sameTape(const formula::Tape& a, const formula::Tape& b) {
    if (a.code.size() != b.code.size() || a.outputs.size() != b.outputs.size()) return false;
    for (std::size_t i = 0; i < a.code.size(); ++i) {
        const formula::Instruction &p = a.code[i], &q = b.code[i];
        if (p.op != q.op || p.out != q.out || !sameOperand(p.a, q.a) || !sameOperand(p.b, q.b) ||
            !sameOperand(p.c, q.c) || p.imm0 != q.imm0 || p.imm1 != q.imm1)
            return false;
    }
    for (std::size_t i = 0; i < a.outputs.size(); ++i)
        if (!sameOperand(a.outputs[i].value, b.outputs[i].value)) return false;
    return true;
}

} // namespace

std::size_t cost(const field::ImplicitField& f) {
    return f.tape.code.size() + 1 + (f.displacement ? f.displacement->tape.code.size() + 1 : 0);
}

bool identicalFields(const field::ImplicitField& a, const field::ImplicitField& b) {
    if (a.t != b.t || a.parameters != b.parameters || a.box.lo != b.box.lo ||
        a.box.hi != b.box.hi || a.boundary != b.boundary ||
        a.displacement.has_value() != b.displacement.has_value() || !sameTape(a.tape, b.tape))
        return false;
    return !a.displacement || (sameTape(a.displacement->tape, b.displacement->tape) &&
                               a.displacement->componentBox.lo == b.displacement->componentBox.lo &&
                               a.displacement->componentBox.hi == b.displacement->componentBox.hi);
}

SolidComparison compareSolids(const field::ImplicitField& a, const field::ImplicitField& b,
                              const field::ImplicitField* activity, Budget& budget,
                              const CompareOptions& options) {
    // Compared inside the box, without the box's own faces: both would carry
    // them, and every cell on a face would look undecided.
    field::ImplicitField openA = a, openB = b;
    openA.boundary = openB.boundary = field::BoxBoundary::Open;
    openB.box = openA.box;
    field::FieldSampler fa(openA), fb(openB);
    std::optional<field::FieldSampler> active;
    std::optional<field::ImplicitField> openActivity;
    if (activity) {
        openActivity = *activity;
        openActivity->boundary = field::BoxBoundary::Open;
        openActivity->box = openA.box;
        active.emplace(*openActivity);
    }
    SolidComparison out;
    struct Cell {
        field::Box3 box;
        int depth;
    };
    const std::size_t costAB = cost(openA) + cost(openB);
    const std::size_t costActivity = openActivity ? cost(*openActivity) : 0;
    std::deque<Cell> queue{{openA.box, 0}};
    const std::size_t stopAt = budget.left > options.cap ? budget.left - options.cap : 0;
    // A point where one is inside and the other not ends the comparison.
    auto witnessAt = [&](const field::Vec3& p) {
        const double va = fa.value(p), vb = fb.value(p);
        if (!std::isfinite(va) || !std::isfinite(vb) || inside(va) == inside(vb)) return false;
        out.result = Sameness::Different;
        out.witness = p;
        out.witnessA = va;
        out.witnessB = vb;
        return true;
    };
    // Cut short: the queued cells' centres and a fixed spread of the box are
    // the last places looked at (paid from the budget beyond the cap).
    auto lastLook = [&] {
        std::size_t tried = 0;
        for (const Cell& c : queue) {
            if (tried++ >= kLastLookCells || !budget.spend(costAB)) break;
            if (witnessAt(field::scaled(field::plus(c.box.lo, c.box.hi), 0.5))) break;
        }
        for (int i = 1; out.result == Sameness::Unknown && i <= kLastLookSpread; ++i) {
            if (!budget.spend(costAB)) break;
            const field::Vec3 u{radicalInverse(i, 2), radicalInverse(i, 3), radicalInverse(i, 5)};
            field::Vec3 p;
            for (std::size_t k = 0; k < 3; ++k)
                p[k] = openA.box.lo[k] + u[k] * (openA.box.hi[k] - openA.box.lo[k]);
            witnessAt(p);
        }
        // Found after all: a verdict. Else the comparison was cut short.
        out.cutShort = out.result != Sameness::Different;
        if (out.cutShort) ++budget.cutShort;
        return out;
    };
    while (!queue.empty()) {
        const Cell cell = queue.front();
        queue.pop_front();
        // Two or three intervals, at four times a point's cost.
        if (budget.left <= stopAt || !budget.spend(4 * (costAB + costActivity))) {
            queue.push_front(cell);
            return lastLook(); // Unknown, unless a last look finds a witness
        }
        if (active) {
            const formula::Interval g = active->interval(cell.box.lo, cell.box.hi);
            if (g.empty() || (!g.nan && g.hi <= 0)) continue; // equal here
        }
        const formula::Interval ia = fa.interval(cell.box.lo, cell.box.hi);
        const formula::Interval ib = fb.interval(cell.box.lo, cell.box.hi);
        if (sameSide(ia, ib)) continue;
        // Look for a witness at the centre (and, at the top, the corners).
        std::vector<field::Vec3> points;
        const field::Vec3 mid = field::scaled(field::plus(cell.box.lo, cell.box.hi), 0.5);
        points.push_back(mid);
        if (cell.depth == 0)
            for (int c = 0; c < 8; ++c)
                points.push_back({c & 1 ? cell.box.hi[0] : cell.box.lo[0],
                                  c & 2 ? cell.box.hi[1] : cell.box.lo[1],
                                  c & 4 ? cell.box.hi[2] : cell.box.lo[2]});
        for (const field::Vec3& p : points) {
            if (!budget.spend(costAB)) {
                queue.push_front(cell);
                return lastLook();
            }
            if (witnessAt(p)) return out;
        }
        if (cell.depth >= options.maxDepth) {
            ++out.unresolvedCells;
            continue;
        }
        // Halve every side; the children are visited in a fixed order,
        // after every cell of this depth.
        for (int c = 0; c < 8; ++c) {
            Cell child{cell.box, cell.depth + 1};
            for (std::size_t k = 0; k < 3; ++k) {
                const double m = 0.5 * (cell.box.lo[k] + cell.box.hi[k]);
                (c >> k & 1 ? child.box.lo[k] : child.box.hi[k]) = m;
            }
            queue.push_back(child);
        }
    }
    out.result = Sameness::Same;
    return out;
}

} // namespace fl::grading
