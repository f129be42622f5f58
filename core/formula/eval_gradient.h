#pragma once
// Forward-mode automatic differentiation: value and the partial derivatives
// with respect to three chosen inputs (x, y, z by default; u, v, w for
// parametric surfaces). Normals, Newton steps and haptic contact use it.
//
// Where a derivative does not exist the evaluator returns a defined one-sided
// or averaged value (documented in docs/numerics.md) and never lets a zero
// derivative times an infinite one produce NaN.
#include "eval_scalar.h"

#include <array>
#include <cstddef>
#include <memory>
#include <new>
#include <vector>

namespace fl::formula {

struct Dual {
    double v = 0.0;
    std::array<double, 3> d{};
};

class GradientJit;

class GradientEvaluator {
  public:
    // `code`: one point at a time as the scalar evaluator does — machine
    // code (gradient_jit.h, the same bits) after kScalarWarmUp points, from
    // the first, or never.
    explicit GradientEvaluator(const Tape& tape,
                               std::array<Input, 3> wrt = {Input::X, Input::Y, Input::Z},
                               ScalarCode code = ScalarCode::AfterWarmUp);
    ~GradientEvaluator();
    GradientEvaluator(const GradientEvaluator& other);
    GradientEvaluator& operator=(const GradientEvaluator&) = delete;

    ParameterValues& parameters() { return params_; }

    Dual evaluate(const Point& p);
    // Whether the last evaluate(), evaluateAll() or evaluateMany() ran as
    // machine code.
    bool compiledLast() const { return compiledLast_; }
    // The first output at n points: the same values as evaluate() point by
    // point, computed instruction by instruction over blocks of points (the
    // dispatch is paid once per instruction and block, not per point) —
    // or, for a tape whose operations mostly lack row loops (abs, powers,
    // divisions), point by point as machine code, once it has been asked
    // for kScalarWarmUp points.
    void evaluateMany(const Point* points, std::size_t n, Dual* out);
    void evaluateAll(const Point& p, Dual* outputs);

  private:
    const Tape tape_; // a copy: evaluators never dangle when a CompileResult goes away
    std::array<Input, 3> wrt_;
    ParameterValues params_;
    // Each dual on a 32-byte boundary: the machine code moves a dual with
    // one 32-byte load or store, and one split across two cache lines
    // cannot be forwarded from the store that wrote it (union50's gradient
    // ran 6x slower in a process whose malloc gave 16-byte alignment).
    template <class T>
    struct Aligned32 {
        using value_type = T;
        Aligned32() = default;
        template <class U>
        Aligned32(const Aligned32<U>&) noexcept {}
        T* allocate(std::size_t n) {
            return static_cast<T*>(::operator new (n * sizeof(T), std::align_val_t{32}));
        }
        void deallocate(T* p, std::size_t) noexcept {
            // (unsized: clang without -fsized-deallocation declares no sized form)
            ::operator delete (p, std::align_val_t{32});
        }
        template <class U>
        bool operator==(const Aligned32<U>&) const noexcept {
            return true;
        }
    };
    std::vector<Dual, Aligned32<Dual>> regs_;
    // evaluateMany's rows: per register its values and three derivatives
    // over a block of points; per instruction its constant operands'.
    std::vector<double> blockRegs_;
    std::vector<double> constRows_;
    std::vector<std::int32_t> constSlot_; // per instruction and operand: its row, or -1
    // One point as machine code: made after the warm-up (or never), and the
    // parameters' version last written to regs_ for it.
    ScalarCode code_;
    bool manyByCode_; // evaluateMany's way (manyByCode() in eval_gradient.cpp)
    unsigned calls_ = 0;
    bool compiledLast_ = false;
    bool tried_ = false;
    std::shared_ptr<const GradientJit> jit_;
    std::uint64_t paramsWritten_ = 0;
    bool paramsWrittenOnce_ = false;
    void run(const Point& p);
    bool runCompiled(const Point& p);
    // Whether there is code to run, made now if `asked` more points end the
    // warm-up (t: the first point's, for its work on t alone).
    bool haveCode(std::size_t asked, double t);
    void runCode(const Point& p);
};

namespace ad {
// (value, f' times a's slopes), each slope under the zero rule: +0 where the
// slope or f' is 0.
Dual chain(double value, double fprime, const Dual& a);
Dual unary(Op op, const Dual& a, double imm0);
Dual binary(Op op, const Dual& a, const Dual& b, double imm0, double imm1);
Dual ternary(Op op, const Dual& a, const Dual& b, const Dual& c);
} // namespace ad

} // namespace fl::formula
