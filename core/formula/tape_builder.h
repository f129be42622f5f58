#pragma once
// Builds a tape one operation at a time: folds constants, applies safe
// algebraic identities, shares common subexpressions (hash-consing), then
// drops dead code and assigns registers by liveness.
#include "diagnostic.h"
#include "tape.h"

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace fl::formula {

// A value during compilation: a constant or the result of node `node`.
struct Val {
    std::int32_t node = -1; // -1: constant
    double c = 0.0;

    static Val constant(double v) { return {-1, v}; }
    bool isConst() const { return node < 0; }
    bool isConst(double v) const { return node < 0 && c == v; }
};

class TapeBuilder {
  public:
    TapeBuilder();

    Val input(Input which);
    Val parameter(std::int32_t index); // index into the parameter list (registers after inputs)

    // The current source range is attached to every node emitted while it is set.
    void setOrigin(const SourceRange& range) { origin_ = range; }
    const SourceRange& origin() const { return origin_; }

    Val emit(Op op, Val a, Val b = {}, Val c = {}, double imm0 = 0.0, double imm1 = 0.0);

    // Convenience forms used by the compiler and the built-in expansions.
    Val neg(Val a) { return emit(Op::Neg, a); }
    Val add(Val a, Val b) { return emit(Op::Add, a, b); }
    Val sub(Val a, Val b) { return emit(Op::Sub, a, b); }
    Val mul(Val a, Val b) { return emit(Op::Mul, a, b); }
    Val div(Val a, Val b) { return emit(Op::Div, a, b); }
    Val square(Val a) { return emit(Op::Square, a); }
    Val min(Val a, Val b) { return emit(Op::Min, a, b); }
    Val max(Val a, Val b) { return emit(Op::Max, a, b); }
    Val select(Val cond, Val a, Val b) { return emit(Op::Select, cond, a, b); }
    Val power(Val base, Val exponent);

    std::size_t nodeCount() const { return nodes_.size(); }

    // The value as a constant where it is one — including operations kept on
    // the tape only because they are NaN for every point — else unchanged.
    // For places that need a number at compile time (loop bounds, m, …).
    Val resolveConstant(Val v);

    // Source ranges of always-NaN operations that resolveConstant evaluated
    // (they vanish from the tape when, say, a loop bound absorbs them).
    const std::vector<SourceRange>& resolvedUndefined() const { return resolvedUndefined_; }

    struct Output {
        std::string name;
        Val value;
    };
    Tape finish(const std::vector<Output>& outputs, std::vector<ParameterInfo> params) const;

  private:
    struct Node {
        Op op;
        Val a, b, c;
        double imm0, imm1;
        std::int32_t origin;
        bool isLeaf; // an input or a parameter: lives in a fixed register
        std::int32_t leafRegister;
    };
    struct Key {
        Op op;
        std::int32_t an, bn, cn;
        std::uint64_t ac, bc, cc, i0, i1;
        bool operator==(const Key&) const = default;
    };
    struct KeyHash {
        std::size_t operator()(const Key& k) const;
    };

    std::vector<Node> nodes_;
    std::vector<SourceRange> origins_;
    std::unordered_map<Key, std::int32_t, KeyHash> cse_;
    std::unordered_map<std::int32_t, std::int32_t> leaves_; // fixed register -> node
    SourceRange origin_;
    std::vector<SourceRange> resolvedUndefined_;

    Val leaf(std::int32_t reg);
    Val fold(Op op, Val a, Val b, Val c, double imm0, double imm1);
    bool isNegOf(Val v, Val& inner) const;
};

} // namespace fl::formula
