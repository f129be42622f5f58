// bench mesh's libfive peer (issue 31 §3): a formula meshed by libfive's dual
// contouring, built from source as a benchmark-only program (bench/CMakeLists.txt,
// FUNCTIONLAB_LIBFIVE_SOURCE). functionlab runs it as a separate process and
// measures the triangles it writes with the same error code as its own.
//
// usage: functionlab-libfive-peer FORMULA X0 Y0 Z0 X1 Y1 Z1 RESOLUTION THREADS REPEATS OUT.stl
//                                 [M ALPHA]
// (M ALPHA: & | \ are the R-functions of continuity M and parameter ALPHA,
// as a scene's setOperations="rfunction" makes them; else min and max.)
//
// The formula is compiled by FunctionLab's compiler and its tape rebuilt as a
// libfive tree, operation by operation (libfive has no select, comparison,
// rounding or noise: such a formula is refused, naming the operation).
// libfive's octree halves its box along every axis at once, so its cells
// are the box over a power of two along each axis: the least power of two
// at or above RESOLUTION (cells along the longest side, as FunctionLab
// counts them; the cells are cubes only in a cube box), printed. Timed: the least
// of REPEATS calls of Mesh::render with evaluators made beforehand (as
// functionlab's meshers are timed from a compiled tape). Prints one line of
// JSON; exit 0 meshed, 1 the formula cannot be meshed here, 2 usage error.
#include "formula/compiler.h"
#include "formula/diagnostic.h"
#include "mesh/mesh_export.h"

#include <libfive/eval/evaluator.hpp>
#include <libfive/render/brep/mesh.hpp>
#include <libfive/render/brep/region.hpp>
#include <libfive/render/brep/settings.hpp>
#include <libfive/tree/tree.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

namespace {

using fl::formula::Op;
using libfive::Tree;

struct Args {
    std::string formula;
    double lo[3], hi[3];
    double resolution;
    unsigned threads;
    int repeats;
    std::string out;
    std::optional<fl::formula::SetOperationMode> rfunctions;
};

std::optional<double> number(const char* s) {
    char* end = nullptr;
    const double v = std::strtod(s, &end);
    if (end == s || *end != '\0' || !std::isfinite(v)) return std::nullopt;
    return v;
}

std::optional<Args> parse(int argc, char** argv) {
    if (argc != 12 && argc != 14) return std::nullopt;
    Args a;
    a.formula = argv[1];
    double v[9];
    for (int i = 0; i < 9; ++i) {
        const auto n = number(argv[2 + i]);
        if (!n) return std::nullopt;
        v[i] = *n;
    }
    for (int k = 0; k < 3; ++k) {
        a.lo[k] = v[k];
        a.hi[k] = v[3 + k];
        if (!(a.hi[k] > a.lo[k])) return std::nullopt;
    }
    const auto whole = [](double x, double lo, double hi) {
        return x == std::floor(x) && x >= lo && x <= hi;
    };
    if (!(v[6] >= 1 && v[6] <= 4096) || !whole(v[7], 1, 1024) || !whole(v[8], 1, 100))
        return std::nullopt;
    a.resolution = v[6];
    a.threads = unsigned(v[7]);
    a.repeats = int(v[8]);
    a.out = argv[11];
    if (argc == 14) {
        const auto m = number(argv[12]), alpha = number(argv[13]);
        if (!m || !alpha || *m < 0 || !(*alpha > -1 && *alpha <= 1)) return std::nullopt;
        a.rfunctions = fl::formula::SetOperationMode{fl::formula::SetOperationMode::Kind::RFunction,
                                                     *m, *alpha};
    }
    return a;
}

std::optional<int> integerValue(double v) {
    if (v == std::round(v) && std::abs(v) <= 64) return int(v);
    return std::nullopt;
}

// The R-functions in their textbook form (formula/rfunctions.h keeps ours
// exact at extremes; a benchmark shape does not reach them):
// (a + b - sqrt(a² + b² - 2αab)) / (1 + α) · (a² + b²)^(m/2), the radicand
// held at 0 or above (rounding takes it below where a ≈ b and α = 1); α = 1
// is min, as ours is.
std::optional<Tree> rIntersect(const Tree& a, const Tree& b, double m, double alpha) {
    const auto mi = integerValue(m);
    if (!mi || *mi < 0) return std::nullopt;
    Tree r = alpha >= 1 ? min(a, b)
                        : (a + b - sqrt(max(square(a) + square(b) - 2.0 * alpha * a * b, 0.0))) /
                              (1.0 + alpha);
    if (*mi > 0) r = r * pow(sqrt(square(a) + square(b)), Tree(double(*mi)));
    return r;
}

// The tape rebuilt as a libfive tree; none with `why` for what libfive lacks.
std::optional<Tree> treeOf(const fl::formula::Tape& tape, std::string& why) {
    using fl::formula::Input;
    std::vector<std::optional<Tree>> regs(std::size_t(tape.registerCount));
    regs[std::size_t(Input::X)] = Tree::X();
    regs[std::size_t(Input::Y)] = Tree::Y();
    regs[std::size_t(Input::Z)] = Tree::Z();
    regs[std::size_t(Input::T)] = Tree(0.0); // the shape at t = 0
    for (const fl::formula::ParameterInfo& p : tape.params)
        regs[std::size_t(p.reg)] = Tree(p.defaultValue);
    auto operand = [&](const fl::formula::Operand& o) -> std::optional<Tree> {
        if (o.isConst()) return Tree(o.value);
        if (o.reg < 0 || std::size_t(o.reg) >= regs.size()) return std::nullopt;
        return regs[std::size_t(o.reg)];
    };
    for (const fl::formula::Instruction& in : tape.code) {
        const auto a = operand(in.a);
        const auto b = fl::formula::opArity(in.op) >= 2 ? operand(in.b) : a;
        if (!a || !b) {
            why = "the formula reads u, v or w, which an implicit shape has not";
            return std::nullopt;
        }
        std::optional<Tree> r;
        switch (in.op) {
        case Op::Neg:
            r = -*a;
            break;
        case Op::Abs:
            r = abs(*a);
            break;
        case Op::Square:
            r = square(*a);
            break;
        case Op::Sqrt:
            r = sqrt(*a);
            break;
        case Op::Cbrt:
            r = nth_root(*a, Tree(3.0));
            break;
        case Op::Exp:
            r = exp(*a);
            break;
        case Op::Log:
            r = log(*a);
            break;
        case Op::Log2:
            r = log(*a) * (1.0 / std::numbers::ln2);
            break;
        case Op::Log10:
            r = log(*a) * (1.0 / std::numbers::ln10);
            break;
        case Op::Sin:
        case Op::SinOfPair:
            r = sin(*a);
            break;
        case Op::Cos:
        case Op::CosOfPair:
            r = cos(*a);
            break;
        case Op::Tan:
            r = tan(*a);
            break;
        case Op::Asin:
            r = asin(*a);
            break;
        case Op::Acos:
            r = acos(*a);
            break;
        case Op::Atan:
            r = atan(*a);
            break;
        case Op::Sinh:
            r = (exp(*a) - exp(-*a)) * 0.5;
            break;
        case Op::Cosh:
            r = (exp(*a) + exp(-*a)) * 0.5;
            break;
        case Op::Tanh:
            r = 1.0 - 2.0 / (exp(2.0 * *a) + 1.0);
            break;
        case Op::PowI:
            if (const auto n = integerValue(in.imm0)) r = pow(*a, Tree(double(*n)));
            break;
        case Op::Add:
            r = *a + *b;
            break;
        case Op::Sub:
            r = *a - *b;
            break;
        case Op::Mul:
            r = *a * *b;
            break;
        case Op::Div:
            r = *a / *b;
            break;
        case Op::Pow:
            if (in.b.isConst() && integerValue(in.b.value))
                r = pow(*a, *b);
            else if (in.b.isConst() && in.b.value == 0.5)
                r = sqrt(*a);
            else if (const auto n = in.b.isConst() && in.b.value > 0
                                        ? integerValue(1.0 / in.b.value)
                                        : std::nullopt;
                     n && *n > 0 && *n % 2 == 0)
                r = nth_root(*a, Tree(double(*n))); // even roots: NaN below 0 on both sides
            break;
        case Op::Min:
            r = min(*a, *b);
            break;
        case Op::Max:
            r = max(*a, *b);
            break;
        case Op::Atan2:
            r = atan2(*a, *b);
            break;
        case Op::Hypot:
            r = sqrt(square(*a) + square(*b));
            break;
        case Op::Mod: // libfive's loops forever for b < 0; its intervals assume b > 0
            if (in.b.isConst() && in.b.value > 0) r = mod(*a, *b);
            break;
        case Op::RIntersect:
            r = rIntersect(*a, *b, in.imm0, in.imm1);
            break;
        case Op::RUnion:
            if (auto i = rIntersect(-*a, -*b, in.imm0, in.imm1)) r = -*i;
            break;
        case Op::Floor:
        case Op::Ceil:
        case Op::Round:
        case Op::Sign:
        case Op::Not:
        case Op::Less:
        case Op::LessEq:
        case Op::Greater:
        case Op::GreaterEq:
        case Op::Equal:
        case Op::NotEqual:
        case Op::And:
        case Op::Or:
        case Op::Select:
        case Op::Noise:
            break;
        }
        if (!r) {
            const bool power = in.op == Op::Pow || in.op == Op::PowI;
            const bool rfunction = in.op == Op::RIntersect || in.op == Op::RUnion;
            why = power       ? "libfive raises to whole constant powers (or their even roots) only"
                  : rfunction ? "libfive has no R-function of non-whole continuity"
                  : in.op == Op::Mod ? "libfive's mod takes a positive constant divisor only"
                                     : std::string("libfive has no ") + fl::formula::opName(in.op);
            return std::nullopt;
        }
        if (in.out < 0 || std::size_t(in.out) >= regs.size()) {
            why = "the tape writes past its registers";
            return std::nullopt;
        }
        regs[std::size_t(in.out)] = std::move(r);
    }
    if (tape.outputs.empty()) {
        why = "the formula has no value";
        return std::nullopt;
    }
    const auto f = operand(tape.outputs.front().value);
    if (!f) {
        why = "the formula's value reads u, v or w";
        return std::nullopt;
    }
    return -*f; // FunctionLab's inside is f >= 0, libfive's f < 0
}

// libfive's triangles as FunctionLab's mesh, for its STL writer.
fl::mesh::Mesh meshOf(const libfive::Mesh& m) {
    fl::mesh::Mesh out;
    out.positions.reserve(m.verts.size());
    for (const auto& v : m.verts)
        out.positions.push_back({v[0], v[1], v[2]});
    out.triangles.reserve(m.branes.size());
    for (const auto& t : m.branes)
        out.triangles.push_back({t[0], t[1], t[2]});
    return out;
}

} // namespace

int main(int argc, char** argv) {
    const auto args = parse(argc, argv);
    if (!args) {
        std::cerr << "usage: functionlab-libfive-peer FORMULA X0 Y0 Z0 X1 Y1 Z1 RESOLUTION "
                     "THREADS REPEATS OUT.stl [M ALPHA]\n";
        return 2;
    }
    fl::formula::CompileOptions options;
    options.kind = fl::formula::DefinitionKind::Implicit;
    if (args->rfunctions) options.setOperations = *args->rfunctions;
    const fl::formula::CompileResult compiled = fl::formula::compile(args->formula, options);
    for (const fl::formula::Diagnostic& d : compiled.diagnostics)
        std::cerr << fl::formula::formatDiagnostic(d, args->formula, "formula");
    if (!compiled.ok()) return 1;
    std::string why;
    const auto tree = treeOf(*compiled.tape, why);
    if (!tree) {
        std::cerr << "functionlab-libfive-peer: " << why << "\n";
        return 1;
    }

    double shortest = 1e300;
    for (int k = 0; k < 3; ++k)
        shortest = std::min(shortest, args->hi[k] - args->lo[k]);
    const int level = std::max(0, int(std::ceil(std::log2(args->resolution) - 1e-9)));
    libfive::BRepSettings settings;
    settings.workers = args->threads;
    // libfive takes the depth as ceil(log2(shortest side / min_feature)): a
    // hair above the cell along the shortest side lands on `level` exactly.
    settings.min_feature = shortest / std::ldexp(1.0, level) * (1 + 1e-3);
    const libfive::Region<3> region({args->lo[0], args->lo[1], args->lo[2]},
                                    {args->hi[0], args->hi[1], args->hi[2]});

    const Tree optimized = tree->optimized();
    std::vector<libfive::Evaluator, Eigen::aligned_allocator<libfive::Evaluator>> evaluators;
    evaluators.reserve(settings.workers);
    for (unsigned i = 0; i < settings.workers; ++i)
        evaluators.emplace_back(libfive::Evaluator(optimized));

    double best = 1e300;
    std::unique_ptr<libfive::Mesh> mesh;
    for (int r = 0; r < args->repeats; ++r) {
        const auto started = std::chrono::steady_clock::now();
        mesh = libfive::Mesh::render(evaluators.data(), region, settings);
        best = std::min(best, std::chrono::duration<double, std::milli>(
                                  std::chrono::steady_clock::now() - started)
                                  .count());
        if (!mesh) {
            std::cerr << "functionlab-libfive-peer: libfive made no mesh\n";
            return 1;
        }
    }
    if (std::string error; !fl::mesh::writeMesh(meshOf(*mesh), args->out, error)) {
        std::cerr << "functionlab-libfive-peer: " << error << "\n";
        return 1;
    }
    std::printf("{\"ms\": %.6g, \"triangles\": %zu, \"resolution\": %.6g, \"threads\": %u}\n", best,
                mesh->branes.size(), std::ldexp(1.0, level), settings.workers);
    return 0;
}
