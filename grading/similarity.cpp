#include "similarity.h"

#include "submission_view.h"

#include <algorithm>
#include <vector>

namespace fl::grading {
namespace {

using formula::Op;

std::uint64_t mix(std::uint64_t h, std::uint64_t v) {
    // splitmix64 of the combination: order-dependent, well spread.
    h ^= v + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
    h += 0x9e3779b97f4a7c15ull;
    h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ull;
    h = (h ^ (h >> 27)) * 0x94d049bb133111ebull;
    return h ^ (h >> 31);
}

bool commutes(Op op) {
    return formula::opIsCommutative(op) || op == Op::Min || op == Op::Max || op == Op::RUnion ||
           op == Op::RIntersect;
}

// The shape of every value a field's tape computes, added to `out`.
void addShapes(const formula::Tape& tape, ModelFingerprint& out) {
    constexpr std::uint64_t kConstant = 0x1111, kCoordinate = 0x2222, kOther = 0x3333;
    std::vector<std::uint64_t> reg(std::size_t(tape.registerCount), kOther);
    for (int i = 0; i < 3 && i < tape.registerCount; ++i) // x y z: a coordinate
        reg[std::size_t(i)] = kCoordinate;
    auto shapeOf = [&](const formula::Operand& o) {
        return o.isConst() || o.reg < 0 || std::size_t(o.reg) >= reg.size()
                   ? kConstant
                   : reg[std::size_t(o.reg)];
    };
    for (const formula::Instruction& in : tape.code) {
        std::uint64_t a = shapeOf(in.a), b = shapeOf(in.b), c = shapeOf(in.c);
        const int arity = formula::opArity(in.op);
        if (commutes(in.op) && b < a) std::swap(a, b);
        std::uint64_t h = mix(0x5eed, std::uint64_t(in.op));
        h = mix(h, a);
        if (arity > 1) h = mix(h, b);
        if (arity > 2) h = mix(h, c);
        // A value made of constants alone is a constant.
        if (a == kConstant && (arity < 2 || b == kConstant) && (arity < 3 || c == kConstant))
            h = kConstant;
        if (in.out >= 0 && std::size_t(in.out) < reg.size()) reg[std::size_t(in.out)] = h;
        if (h != kConstant) out.insert(h);
    }
}

} // namespace

ModelFingerprint modelFingerprint(const scene::Scene& scene) {
    ModelFingerprint out;
    const SubmissionView view(scene, 1);
    for (const mesh::ShapeMesh& s : view.frames().front().shapes)
        if (s.field && SubmissionView::shown(s)) addShapes(s.field->tape, out);
    return out;
}

double similarity(const ModelFingerprint& a, const ModelFingerprint& b) {
    if (a.empty() && b.empty()) return 1;
    std::size_t shared = 0;
    for (std::uint64_t h : a)
        shared += b.count(h);
    return double(shared) / double(a.size() + b.size() - shared);
}

ModelFingerprint without(const ModelFingerprint& a, const ModelFingerprint& b) {
    ModelFingerprint out;
    std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::inserter(out, out.end()));
    return out;
}

std::vector<SimilarPair> similarPairs(const std::vector<Fingerprinted>& models, double threshold,
                                      std::size_t minimumShared) {
    std::vector<SimilarPair> out;
    for (std::size_t i = 0; i < models.size(); ++i)
        for (std::size_t j = i + 1; j < models.size(); ++j) {
            const auto& a = models[i].fingerprint;
            const auto& b = models[j].fingerprint;
            std::size_t shared = 0;
            for (std::uint64_t h : a)
                shared += b.count(h);
            const double s = similarity(a, b);
            if (s >= threshold && shared >= minimumShared)
                out.push_back({models[i].student, models[j].student, s, shared});
        }
    std::sort(out.begin(), out.end(), [](const SimilarPair& p, const SimilarPair& q) {
        return p.similarity != q.similarity
                   ? p.similarity > q.similarity
                   : std::tie(p.first, p.second) < std::tie(q.first, q.second);
    });
    return out;
}

} // namespace fl::grading
