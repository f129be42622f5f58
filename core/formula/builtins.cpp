#include "builtins.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace fl::formula {

namespace {

constexpr std::array kBuiltins = {
    // maths
    BuiltinInfo{"abs", 1, 1, "abs(a)", "absolute value", false},
    BuiltinInfo{"sqrt", 1, 1, "sqrt(a)", "square root (NaN below 0)", false},
    BuiltinInfo{"cbrt", 1, 1, "cbrt(a)", "cube root, defined for negatives", false},
    BuiltinInfo{"exp", 1, 1, "exp(a)", "e to the power a", false},
    BuiltinInfo{"log", 1, 1, "log(a)", "natural logarithm (-inf at 0, NaN below)", false},
    BuiltinInfo{"log2", 1, 1, "log2(a)", "base-2 logarithm", false},
    BuiltinInfo{"log10", 1, 1, "log10(a)", "base-10 logarithm", false},
    BuiltinInfo{"sin", 1, 1, "sin(a)", "sine (radians)", false},
    BuiltinInfo{"cos", 1, 1, "cos(a)", "cosine (radians)", false},
    BuiltinInfo{"tan", 1, 1, "tan(a)", "tangent (radians)", false},
    BuiltinInfo{"asin", 1, 1, "asin(a)", "arc sine", false},
    BuiltinInfo{"acos", 1, 1, "acos(a)", "arc cosine", false},
    BuiltinInfo{"atan", 1, 2, "atan(a) | atan(y, x)", "arc tangent; with two arguments atan2",
                false},
    BuiltinInfo{"atan2", 2, 2, "atan2(y, x)", "angle of (x, y) in (-pi, pi]", false},
    BuiltinInfo{"sinh", 1, 1, "sinh(a)", "hyperbolic sine", false},
    BuiltinInfo{"cosh", 1, 1, "cosh(a)", "hyperbolic cosine", false},
    BuiltinInfo{"tanh", 1, 1, "tanh(a)", "hyperbolic tangent", false},
    BuiltinInfo{"floor", 1, 1, "floor(a)", "largest integer <= a", false},
    BuiltinInfo{"ceil", 1, 1, "ceil(a)", "smallest integer >= a", false},
    BuiltinInfo{"round", 1, 1, "round(a)", "nearest integer, halves away from 0", false},
    BuiltinInfo{"fract", 1, 1, "fract(a)", "a - floor(a)", false},
    BuiltinInfo{"sign", 1, 1, "sign(a)", "-1, 0 or 1", false},
    BuiltinInfo{"pow", 2, 2, "pow(a, b)", "a to the power b (same as a^b)", false},
    BuiltinInfo{"hypot", 2, 3, "hypot(a, b[, c])", "sqrt(a^2 + b^2 [+ c^2]) without overflow",
                false},
    BuiltinInfo{"mod", 2, 2, "mod(a, b)", "remainder with the sign of b", false},
    BuiltinInfo{"min", 2, -1, "min(a, b, ...)", "smallest argument", false},
    BuiltinInfo{"max", 2, -1, "max(a, b, ...)", "largest argument", false},
    BuiltinInfo{"clamp", 3, 3, "clamp(a, lo, hi)", "a limited to [lo, hi]", false},
    BuiltinInfo{"mix", 3, 3, "mix(a, b, s)", "(1 - s) a + s b", false},
    BuiltinInfo{"step", 2, 2, "step(edge, a)", "0 below edge, 1 from edge on", false},
    BuiltinInfo{"smoothstep", 3, 3, "smoothstep(e0, e1, a)", "smooth 0..1 ramp between e0 and e1",
                false},
    BuiltinInfo{"noise", 3, 3, "noise(x, y, z)", "deterministic 3D gradient noise, |noise| <= 2",
                false},
    // FRep set operations and blends
    BuiltinInfo{"rintersect", 2, 3, "rintersect(a, b[, m])",
                "R-function intersection a + b - sqrt(a^2+b^2), times (a^2+b^2)^(m/2)", false},
    BuiltinInfo{"runion", 2, 3, "runion(a, b[, m])",
                "R-function union a + b + sqrt(a^2+b^2), times (a^2+b^2)^(m/2)", false},
    BuiltinInfo{"blend_union", 5, 5, "blend_union(a, b, a0, a1, a2)",
                "runion(a, b) + a0 / (1 + (a/a1)^2 + (b/a2)^2)", false},
    BuiltinInfo{"blend_intersect", 5, 5, "blend_intersect(a, b, a0, a1, a2)",
                "rintersect(a, b) + a0 / (1 + (a/a1)^2 + (b/a2)^2)", false},
    BuiltinInfo{"morph", 3, 3, "morph(a, b, s)", "shape a at s = 0 to shape b at s = 1", false},
    // primitives (FRep: >= 0 inside), all reading x, y, z
    BuiltinInfo{"sphere", 1, 4, "sphere(r) | sphere(cx, cy, cz, r)", "r^2 - |p - c|^2", true},
    BuiltinInfo{"ellipsoid", 6, 6, "ellipsoid(cx, cy, cz, a, b, c)",
                "1 - ((x-cx)/a)^2 - ((y-cy)/b)^2 - ((z-cz)/c)^2", true},
    BuiltinInfo{"box", 3, 6, "box(hx, hy, hz) | box(cx, cy, cz, hx, hy, hz)",
                "axis-aligned box with half-sizes h: min(h - |p - c|) per axis", true},
    BuiltinInfo{"cylinder", 2, 5, "cylinder(r, h) | cylinder(cx, cy, cz, r, h)",
                "cylinder along y, radius r, height h, centred at c", true},
    BuiltinInfo{"cone", 2, 5, "cone(r, h) | cone(cx, cy, cz, r, h)",
                "cone along y: base radius r at y = cy - h/2, apex at cy + h/2", true},
    BuiltinInfo{"torus", 2, 5, "torus(R, r) | torus(cx, cy, cz, R, r)",
                "torus around the y axis: r^2 - (hypot(x,z) - R)^2 - y^2", true},
    BuiltinInfo{"halfspace", 4, 4, "halfspace(a, b, c, d)", "a x + b y + c z + d", true},
    BuiltinInfo{"superellipsoid", 8, 8, "superellipsoid(cx, cy, cz, a, b, c, e1, e2)",
                "1 - ((|x'/a|^(2/e2) + |y'/b|^(2/e2))^(e2/e1) + |z'/c|^(2/e1))", true},
    BuiltinInfo{"blob", 5, 5, "blob(cx, cy, cz, a, b)",
                "a exp(-b |p - c|^2); sum blobs, subtract a threshold", true},
};

bool requireConstant(const Val& v, int index, const char* what, BuiltinError& error) {
    if (v.isConst()) return true;
    error.argument = index;
    error.message = std::string(what) + " must be a constant number";
    error.suggestion =
        "use a number (a parameter can change while the shape is shown, so it cannot set this)";
    return false;
}

// Centre offsets: (x - cx, y - cy, z - cz), or the raw coordinates when the
// call has no centre arguments.
struct Local {
    Val x, y, z;
};
Local centred(BuiltinContext& ctx, std::span<const Val> args, bool hasCentre) {
    TapeBuilder& tb = ctx.tb;
    if (!hasCentre) return {ctx.x, ctx.y, ctx.z};
    return {tb.sub(ctx.x, args[0]), tb.sub(ctx.y, args[1]), tb.sub(ctx.z, args[2])};
}

Val blendTerm(TapeBuilder& tb, Val a, Val b, Val a0, Val a1, Val a2) {
    Val ra = tb.square(tb.div(a, a1));
    Val rb = tb.square(tb.div(b, a2));
    return tb.div(a0, tb.add(tb.add(Val::constant(1.0), ra), rb));
}

} // namespace

std::span<const BuiltinInfo> builtinTable() {
    return kBuiltins;
}

const BuiltinInfo* findBuiltin(std::string_view name) {
    for (const BuiltinInfo& b : kBuiltins)
        if (b.name == name) return &b;
    return nullptr;
}

bool lowerBuiltin(const BuiltinInfo& info, BuiltinContext& ctx, std::span<const Val> a, Val& result,
                  BuiltinError& error) {
    TapeBuilder& tb = ctx.tb;
    const std::string_view n = info.name;
    const std::size_t argc = a.size();
    auto unary = [&](Op op) { return tb.emit(op, a[0]); };

    if (n == "abs")
        result = unary(Op::Abs);
    else if (n == "sqrt")
        result = unary(Op::Sqrt);
    else if (n == "cbrt")
        result = unary(Op::Cbrt);
    else if (n == "exp")
        result = unary(Op::Exp);
    else if (n == "log")
        result = unary(Op::Log);
    else if (n == "log2")
        result = unary(Op::Log2);
    else if (n == "log10")
        result = unary(Op::Log10);
    else if (n == "sin")
        result = unary(Op::Sin);
    else if (n == "cos")
        result = unary(Op::Cos);
    else if (n == "tan")
        result = unary(Op::Tan);
    else if (n == "asin")
        result = unary(Op::Asin);
    else if (n == "acos")
        result = unary(Op::Acos);
    else if (n == "atan")
        result = argc == 2 ? tb.emit(Op::Atan2, a[0], a[1]) : unary(Op::Atan);
    else if (n == "atan2")
        result = tb.emit(Op::Atan2, a[0], a[1]);
    else if (n == "sinh")
        result = unary(Op::Sinh);
    else if (n == "cosh")
        result = unary(Op::Cosh);
    else if (n == "tanh")
        result = unary(Op::Tanh);
    else if (n == "floor")
        result = unary(Op::Floor);
    else if (n == "ceil")
        result = unary(Op::Ceil);
    else if (n == "round")
        result = unary(Op::Round);
    else if (n == "fract")
        result = tb.sub(a[0], unary(Op::Floor));
    else if (n == "sign")
        result = unary(Op::Sign);
    else if (n == "pow")
        result = tb.power(a[0], a[1]);
    else if (n == "hypot") {
        result = tb.emit(Op::Hypot, a[0], a[1]);
        if (argc == 3) result = tb.emit(Op::Hypot, result, a[2]);
    } else if (n == "mod")
        result = tb.emit(Op::Mod, a[0], a[1]);
    else if (n == "min" || n == "max") {
        Op op = n == "min" ? Op::Min : Op::Max;
        result = a[0];
        for (std::size_t i = 1; i < argc; ++i)
            result = tb.emit(op, result, a[i]);
    } else if (n == "clamp")
        result = tb.min(tb.max(a[0], a[1]), a[2]);
    else if (n == "mix" || n == "morph") {
        // (1 - s) a + s b: exact at both ends, unlike a + s (b - a)
        result = tb.add(tb.mul(tb.sub(Val::constant(1.0), a[2]), a[0]), tb.mul(a[2], a[1]));
    } else if (n == "step")
        result = tb.emit(Op::GreaterEq, a[1], a[0]);
    else if (n == "smoothstep") {
        Val s = tb.div(tb.sub(a[2], a[0]), tb.sub(a[1], a[0]));
        s = tb.min(tb.max(s, Val::constant(0.0)), Val::constant(1.0));
        result = tb.mul(tb.square(s), tb.sub(Val::constant(3.0), tb.mul(Val::constant(2.0), s)));
    } else if (n == "noise")
        result = tb.emit(Op::Noise, a[0], a[1], a[2]);
    else if (n == "rintersect" || n == "runion") {
        double m = 0.0;
        if (argc == 3) {
            Val mv = tb.resolveConstant(a[2]);
            if (!requireConstant(mv, 2, "the continuity m", error)) return false;
            m = mv.c;
            if (!(m >= 0.0) || m > 16.0) {
                error = {2, "the continuity m must be between 0 and 16", "use m = 0, 1 or 2"};
                return false;
            }
        }
        result = tb.emit(n == "rintersect" ? Op::RIntersect : Op::RUnion, a[0], a[1], {}, m, 0.0);
    } else if (n == "blend_union" || n == "blend_intersect") {
        Val base =
            tb.emit(n == "blend_union" ? Op::RUnion : Op::RIntersect, a[0], a[1], {}, 0.0, 0.0);
        result = tb.add(base, blendTerm(tb, a[0], a[1], a[2], a[3], a[4]));
    } else if (n == "sphere") {
        if (argc != 1 && argc != 4) {
            error = {-1, "sphere takes 1 argument (r) or 4 (cx, cy, cz, r)",
                     "write sphere(1) or sphere(0, 0, 0, 1)"};
            return false;
        }
        // r^2 - dx^2 - dy^2 - dz^2, the classic FRep sphere (and one fused
        // pass in the batch evaluator)
        Local p = centred(ctx, a, argc == 4);
        Val r = a[argc - 1];
        result =
            tb.sub(tb.sub(tb.sub(tb.square(r), tb.square(p.x)), tb.square(p.y)), tb.square(p.z));
    } else if (n == "ellipsoid") {
        Local p = centred(ctx, a, true);
        Val s = tb.add(tb.add(tb.square(tb.div(p.x, a[3])), tb.square(tb.div(p.y, a[4]))),
                       tb.square(tb.div(p.z, a[5])));
        result = tb.sub(Val::constant(1.0), s);
    } else if (n == "box") {
        if (argc != 3 && argc != 6) {
            error = {-1, "box takes 3 arguments (hx, hy, hz) or 6 (cx, cy, cz, hx, hy, hz)",
                     "write box(1, 1, 1)"};
            return false;
        }
        Local p = centred(ctx, a, argc == 6);
        std::size_t h = argc == 6 ? 3 : 0;
        result = tb.min(
            tb.min(tb.sub(a[h], tb.emit(Op::Abs, p.x)), tb.sub(a[h + 1], tb.emit(Op::Abs, p.y))),
            tb.sub(a[h + 2], tb.emit(Op::Abs, p.z)));
    } else if (n == "cylinder" || n == "cone" || n == "torus") {
        if (argc != 2 && argc != 5) {
            error = {-1, std::string(n) + " takes 2 arguments or 5 (cx, cy, cz and two sizes)",
                     "see " + std::string(info.signature)};
            return false;
        }
        Local p = centred(ctx, a, argc == 5);
        Val s1 = a[argc - 2], s2 = a[argc - 1];
        Val radial = tb.emit(Op::Hypot, p.x, p.z);
        if (n == "cylinder") {
            Val half = tb.mul(s2, Val::constant(0.5));
            result = tb.min(tb.sub(s1, radial), tb.sub(half, tb.emit(Op::Abs, p.y)));
        } else if (n == "cone") {
            // radius shrinks linearly from s1 at the base to 0 at the apex
            Val half = tb.mul(s2, Val::constant(0.5));
            Val fromApex = tb.sub(half, p.y); // 0 at apex, h at base
            Val side = tb.sub(tb.mul(tb.div(s1, s2), fromApex), radial);
            result = tb.min(side, tb.add(p.y, half));
        } else {
            result = tb.sub(tb.sub(tb.square(s2), tb.square(tb.sub(radial, s1))), tb.square(p.y));
        }
    } else if (n == "halfspace") {
        // a x + b y + c z + d without the terms a zero coefficient makes
        // (0 * x is not folded in general; coordinates are finite) and with
        // no factor of one: halfspace(0, 1, 0, -0.2) is y - 0.2, whose
        // intervals are as tight as the plane written by hand.
        std::optional<Val> sum;
        const Val coordinates[3] = {ctx.x, ctx.y, ctx.z};
        for (int i = 0; i < 3; ++i) {
            if (a[i].isConst(0.0)) continue;
            const Val term = a[i].isConst(1.0) ? coordinates[i] : tb.mul(a[i], coordinates[i]);
            sum = sum ? tb.add(*sum, term) : term;
        }
        result = !sum ? a[3] : a[3].isConst(0.0) ? *sum : tb.add(*sum, a[3]);
    } else if (n == "superellipsoid") {
        Local p = centred(ctx, a, true);
        Val e1 = a[6], e2 = a[7];
        Val two = Val::constant(2.0);
        auto term = [&](Val c, Val size, Val e) {
            return tb.power(tb.emit(Op::Abs, tb.div(c, size)), tb.div(two, e));
        };
        Val xy = tb.power(tb.add(term(p.x, a[3], e2), term(p.y, a[4], e2)), tb.div(e2, e1));
        result = tb.sub(Val::constant(1.0), tb.add(xy, term(p.z, a[5], e1)));
    } else if (n == "blob") {
        Local p = centred(ctx, a, true);
        Val d2 = tb.add(tb.add(tb.square(p.x), tb.square(p.y)), tb.square(p.z));
        result = tb.mul(a[3], tb.emit(Op::Exp, tb.neg(tb.mul(a[4], d2))));
    } else {
        error = {-1, "internal: built-in '" + std::string(n) + "' has no lowering", ""};
        return false;
    }
    return true;
}

} // namespace fl::formula
