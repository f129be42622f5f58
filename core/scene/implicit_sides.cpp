#include "implicit_sides.h"

#include "field_access.h"
#include "formula/compiler.h"
#include "formula/eval_scalar.h"
#include "formula/parser.h"
#include "function_kinds.h"
#include "node_graph.h"

#include <array>
#include <cmath>
#include <map>
#include <string>

namespace fl::scene {
namespace {

// Samples per box edge: 9 x 9 on each face, 9^3 inside. Enough to see a
// closed surface inside the box; a shape thinner than a ninth of its box is
// not judged (no warning is better than a wrong one).
constexpr int kSamples = 9;

// The shapes that need an inside, in the order the scene holds them (so the
// warnings come out in a fixed order), each with why.
struct Uses {
    std::vector<std::pair<const Node*, std::string>> list;
    std::map<const Node*, std::size_t> index;

    void add(const Node* shape, const std::string& why) {
        auto [it, fresh] = index.emplace(shape, list.size());
        if (fresh) list.emplace_back(shape, std::string());
        std::string& all = list[it->second].second;
        if (all.find(why) == std::string::npos) all += (all.empty() ? "" : " and ") + why;
    }
};

// The FShapes below `node` (through grouping nodes' children).
void shapesBelow(const Node* raw, const std::string& why, Uses& uses, int depth = 0) {
    const Node* n = effectiveNode(raw);
    if (!n || depth > int(kMaxWalkDepth)) return;
    if (n->kind() == scene::NodeKind::FShape) {
        uses.add(n, why);
        return;
    }
    if (n->spec && findFieldSpec(*n->spec, "children"))
        for (const Node* child : nodesField(*n, "children"))
            shapesBelow(child, why, uses, depth + 1);
}

// True when f > 0 on the whole boundary of the box and f < 0 somewhere inside.
bool looksNegativeInside(const formula::Tape& tape, const std::vector<double>& lo,
                         const std::vector<double>& hi, double t) {
    formula::ScalarEvaluator f(tape);
    auto at = [&](int i, int j, int k) {
        const std::array<int, 3> g{i, j, k};
        std::array<double, 3> p{};
        for (std::size_t a = 0; a < 3; ++a)
            p[a] = lo[a] + (hi[a] - lo[a]) * double(g[a]) / double(kSamples - 1);
        return f.evaluate(formula::pointXYZ(p[0], p[1], p[2], t));
    };
    bool negativeInside = false;
    for (int i = 0; i < kSamples; ++i)
        for (int j = 0; j < kSamples; ++j)
            for (int k = 0; k < kSamples; ++k) {
                const bool onBoundary = i == 0 || j == 0 || k == 0 || i == kSamples - 1 ||
                                        j == kSamples - 1 || k == kSamples - 1;
                const double v = at(i, j, k);
                if (onBoundary && !(v > 0)) return false; // NaN too: not judged
                if (!onBoundary && v < 0) negativeInside = true;
            }
    return negativeInside;
}

// The operands of the set operations (& | \\) in a plain formula, as text:
// each is read with the FRep sign too, whatever the surface as a whole.
void setOperands(const formula::Expr& e, std::string_view source,
                 std::vector<std::pair<std::string, const char*>>& out, std::size_t most) {
    if (out.size() >= most) return;
    if (e.kind == formula::ExprKind::Binary &&
        (e.binaryOp == formula::BinaryOp::Intersect || e.binaryOp == formula::BinaryOp::Union ||
         e.binaryOp == formula::BinaryOp::Difference)) {
        const char* op = e.binaryOp == formula::BinaryOp::Intersect ? "&"
                         : e.binaryOp == formula::BinaryOp::Union   ? "|"
                                                                    : "\\";
        for (const formula::ExprPtr& a : e.args) {
            const std::size_t b = a->range.begin.offset, end = a->range.end.offset;
            if (b < end && end <= source.size() && out.size() < most)
                out.emplace_back(std::string(source.substr(b, end - b)), op);
        }
    }
    for (const formula::ExprPtr& a : e.args)
        if (a) setOperands(*a, source, out, most);
}

// Issue 29 §7: `(x^2 + y^2 + z^2 - 1) & (y + 0.5)` in one implicit formula
// intersects the sphere's *outside*: its & reads f >= 0 as inside, as an
// FTransform's intersection does. One warning per operand that looks
// negative inside (at most a few per formula, each sampled as the surface).
void checkOperands(const Scene& scene, const Node& geometry, const std::vector<double>& lo,
                   const std::vector<double>& hi, double t, std::vector<SceneDiagnostic>& out) {
    const std::vector<std::string> source = stringsField(geometry, "definition");
    if (source.size() != 1) return;
    std::vector<formula::Diagnostic> ignored; // the definition was checked when read
    const formula::Program program = formula::parse(source[0], ignored);
    if (!program.isExpression || program.statements.size() != 1 || !program.statements[0]->value)
        return;
    constexpr std::size_t kMostOperands = 8;
    std::vector<std::pair<std::string, const char*>> operands;
    setOperands(*program.statements[0]->value, source[0], operands, kMostOperands);
    formula::CompileOptions options;
    options.kind = formula::DefinitionKind::Implicit;
    // Each scene read does this, on every implicit formula with a set
    // operation: a costly operand is not judged (no warning is better than
    // work a hostile scene could multiply), the formula itself was bounded.
    options.limits.maxExpansionSteps = 20'000;
    options.limits.maxTapeSize = 4096;
    for (const auto& [text, op] : operands) {
        const formula::CompileResult operand = formula::compile(text, options);
        if (!operand.ok() || !looksNegativeInside(*operand.tape, lo, hi, t)) continue;
        out.push_back({Severity::Warning, scene.pathOf(geometry.file), geometry.where,
                       "the operand " + text + " of " + op +
                           " is negative inside (f > 0 on the whole box boundary, f < 0 "
                           "within), but " +
                           op + " reads f >= 0 as the inside, so its outside is used",
                       "write it the FRep way, inside positive: -(" + text + ")"});
    }
}

} // namespace

std::vector<SceneDiagnostic> checkImplicitSides(const Scene& scene) {
    Uses uses;
    scene.forEachNode([&](const Node& n) {
        if (n.inProtoBody) return;
        if (n.kind() == scene::NodeKind::FTransform) {
            const std::string op = stringField(n, "operation");
            if (setOperationNamed(op) != SetOperation::Group)
                for (const Node* child : nodesField(n, "children"))
                    shapesBelow(child, "an FTransform's " + op, uses);
        }
        if (n.kind() != scene::NodeKind::FShape) return;
        if (const Node* a = effectiveNode(nodeField(n, "appearance")))
            if (const Node* texture = effectiveNode(nodeField(*a, "texture"));
                texture && texture->kind() == scene::NodeKind::FTexture3D)
                uses.add(&n, "its FTexture3D displacement");
        if (const Node* p = effectiveNode(nodeField(n, "physics"));
            p && p->kind() == scene::NodeKind::FPhysics) {
            if (nodeField(*p, "density")) uses.add(&n, "its FDensity");
            if (nodeField(*p, "force")) uses.add(&n, "its FForce (the field's container)");
        }
    });
    std::vector<SceneDiagnostic> out;
    // The set operations inside each implicit formula of the scene.
    scene.forEachNode([&](const Node& g) {
        if (g.inProtoBody || g.kind() != scene::NodeKind::FGeometry ||
            geometryTypeNamed(stringField(g, "type")) != GeometryType::Implicit)
            return;
        const std::vector<double> lo = numbersField(g, "domainMin"),
                                  hi = numbersField(g, "domainMax");
        if (lo.size() != 3 || hi.size() != 3) return;
        const std::vector<double> span = numbersField(g, "timeSpan");
        checkOperands(scene, g, lo, hi, span.empty() ? 0.0 : span[0], out);
    });
    for (const auto& [shape, why] : uses.list) {
        const Node* geometry = effectiveNode(nodeField(*shape, "geometry"));
        if (!geometry || geometry->kind() != scene::NodeKind::FGeometry ||
            geometryTypeNamed(stringField(*geometry, "type")) != GeometryType::Implicit)
            continue;
        const formula::Tape* tape = scene.definition(*geometry, "definition");
        const std::vector<double> lo = numbersField(*geometry, "domainMin"),
                                  hi = numbersField(*geometry, "domainMax");
        if (!tape || lo.size() != 3 || hi.size() != 3) continue;
        const std::vector<double> span = numbersField(*geometry, "timeSpan");
        if (!looksNegativeInside(*tape, lo, hi, span.empty() ? 0.0 : span[0])) continue;
        const std::vector<std::string> source = stringsField(*geometry, "definition");
        const std::string fix =
            source.size() == 1
                ? "for the inside, write type 'explicit' with the formula negated: -(" + source[0] +
                      ")"
                : "for the inside, write type 'explicit' and negate what the script returns";
        out.push_back({Severity::Warning, scene.pathOf(geometry->file), geometry->where,
                       "this implicit surface is negative inside (f > 0 on its whole box "
                       "boundary, f < 0 within), but " +
                           why + " reads f >= 0 as the inside, so its outside would be used there",
                       fix});
    }
    return out;
}

} // namespace fl::scene
