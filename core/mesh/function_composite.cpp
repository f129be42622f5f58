#include "function_composite.h"

#include "formula/eval_scalar.h"
#include "formula/tape_builder.h"
#include "formula/tape_compose.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>

namespace fl::mesh {

namespace {

using scene::GeometryType;
using scene::Node;
using scene::NodeKind;
using scene::SetOperation;
using Inputs = std::array<formula::Val, formula::kInputCount>;

// Coordinate k of `map` applied to the local coordinates, written with no
// term that is zero and no factor that is one: an identity or axis-aligned
// placement gives exactly `x`, as in one formula. (0 * x and t + 0 are not
// folded by the tape builder, rightly for arbitrary values; here the
// coordinates are finite. Each such step would widen an interval by an ulp,
// and a face lying on a cell boundary — box(0.5, …) in [-1, 1] — would never
// be proven on one side.)
formula::Val affineCoordinate(formula::TapeBuilder& b, const Affine& map, int k,
                              const Inputs& local) {
    std::optional<formula::Val> sum;
    if (map.t[k] != 0) sum = formula::Val::constant(map.t[k]);
    for (int j = 0; j < 3; ++j) {
        const double m = map.m[k][j];
        if (m == 0) continue;
        const formula::Val term = m == 1 ? local[std::size_t(j)]
                                         : b.mul(formula::Val::constant(m), local[std::size_t(j)]);
        sum = sum ? b.add(*sum, term) : term;
    }
    return sum ? *sum : formula::Val::constant(0.0);
}

// One function for a subtree of the FTransform.
struct Piece {
    formula::Val f;
    Box3 box;                         // in the FTransform's local coordinates
    const Node* appearance = nullptr; // of the first FShape in it
    double resolution = 0;
    const Node* levelOfDetail = nullptr;
};

class Composer {
  public:
    Composer(const SceneWalkContext& context, WalkGuard& guard, std::vector<std::string>& notes)
        : context_(context), guard_(guard), notes_(notes) {
        for (int i = 0; i < formula::kInputCount; ++i)
            local_[std::size_t(i)] = b_.input(formula::Input(i));
    }

    std::optional<ComposedShape> compose(const Node& ft) {
        std::vector<Piece> pieces;
        for (const Node* child : context_.moment.nodes(ft, "children"))
            collect(child, Affine{}, pieces);
        if (pieces.empty()) {
            notes_.push_back(context_.nameOf(ft) + ": no implicit or explicit child to combine");
            return std::nullopt;
        }
        const Piece whole = combine(ft, pieces);
        ComposedShape out;
        out.field.tape = b_.finish({{"value", whole.f}}, {});
        out.field.box = whole.box;
        out.appearance = whole.appearance;
        out.resolution = whole.resolution;
        out.levelOfDetail = whole.levelOfDetail;
        out.texts = std::move(texts_);
        return out;
    }

  private:
    // The pieces under `raw`, whose coordinates are `toLocal` of the
    // combining FTransform's.
    void collect(const Node* raw, const Affine& toLocal, std::vector<Piece>& out) {
        const Node* n = scene::effectiveNode(raw);
        const scene::WalkPath::Step step(guard_.path(), n);
        if (!n || guard_.refused(step)) return;
        const animation::Animator& moment = context_.moment;
        const NodeKind kind = n->kind();
        if (kind == NodeKind::FShape) return functionShape(*n, toLocal, out);
        if (kind == NodeKind::Transform || kind == NodeKind::FTransform) {
            const Affine inner =
                toLocal * (kind == NodeKind::Transform ? context_.transformOf(*n)
                                                       : context_.functionTransform(*n));
            std::vector<Piece> pieces;
            for (const Node* child : moment.nodes(*n, "children"))
                collect(child, inner, pieces);
            if (kind == NodeKind::FTransform && context_.operationOf(*n) != SetOperation::Group &&
                !pieces.empty()) {
                out.push_back(combine(*n, pieces));
                return;
            }
            out.insert(out.end(), pieces.begin(), pieces.end());
            return;
        }
        if (n->spec && scene::findFieldSpec(*n->spec, "children"))
            for (const Node* child : moment.nodes(*n, "children"))
                collect(child, toLocal, out);
    }

    void functionShape(const Node& n, const Affine& toLocal, std::vector<Piece>& out) {
        const animation::Animator& moment = context_.moment;
        const Node* geometry = scene::effectiveNode(moment.node(n, "geometry"));
        if (!geometry || geometry->kind() != NodeKind::FGeometry ||
            context_.geometryTypeOf(*geometry) == GeometryType::Parametric) {
            notes_.push_back(context_.nameOf(n) +
                             ": only implicit and explicit geometry takes part in "
                             "an FTransform's set operation; left out");
            return;
        }
        const formula::Tape* tape = context_.scene.definition(*geometry, "definition");
        if (!tape) return;
        // The child's own coordinates, from the local ones.
        // A singular map (a zero scale) flattens the child to nothing.
        const std::optional<Affine> inverse = toLocal.inverse();
        if (!inverse) return;
        Inputs in = local_;
        for (int k = 0; k < 3; ++k)
            in[std::size_t(k)] = affineCoordinate(b_, *inverse, k, local_);
        in[std::size_t(formula::Input::T)] = formula::Val::constant(context_.timeOf(*geometry));
        formula::Val f = formula::inlineTape(b_, *tape, in, std::vector<double>{},
                                             textTag(*geometry, "definition"))[0];
        // Nothing of the child exists outside its box.
        formula::SourceRange boxText;
        boxText.source = textTag(*geometry, "domainMin");
        b_.setOrigin(boxText);
        const Box3 box = domainOf(*geometry);
        for (std::size_t k = 0; k < 3; ++k) {
            f = b_.min(f, b_.sub(in[k], formula::Val::constant(box.lo[k])));
            f = b_.min(f, b_.sub(formula::Val::constant(box.hi[k]), in[k]));
        }
        out.push_back({f, field::boundsOf(box, toLocal), context_.appearanceOf(n),
                       moment.number(*geometry, "resolution", 0, 32),
                       moment.flag(*geometry, "lod") ? geometry : nullptr});
    }

    Piece combine(const Node& ft, const std::vector<Piece>& pieces) {
        const std::optional<SetOperation> op = context_.operationOf(ft);
        // The combining instructions are the FTransform's `operation`.
        formula::SourceRange here;
        here.source = textTag(ft, "operation");
        b_.setOrigin(here);
        Piece r = pieces.front();
        for (const Piece& p : pieces) {
            r.resolution = std::max(r.resolution, p.resolution);
            if (!r.levelOfDetail) r.levelOfDetail = p.levelOfDetail;
            if (op != SetOperation::Intersection && op != SetOperation::Difference)
                for (std::size_t k = 0; k < 3; ++k) {
                    r.box.lo[k] = std::min(r.box.lo[k], p.box.lo[k]);
                    r.box.hi[k] = std::max(r.box.hi[k], p.box.hi[k]);
                }
            if (op == SetOperation::Intersection)
                for (std::size_t k = 0; k < 3; ++k) {
                    r.box.lo[k] = std::max(r.box.lo[k], p.box.lo[k]);
                    r.box.hi[k] = std::min(r.box.hi[k], p.box.hi[k]);
                }
        }
        const double t = context_.timeOf(ft);
        if (op == SetOperation::Union) {
            for (std::size_t i = 1; i < pieces.size(); ++i)
                r.f = b_.max(r.f, pieces[i].f);
        } else if (op == SetOperation::Intersection) {
            for (std::size_t i = 1; i < pieces.size(); ++i)
                r.f = b_.min(r.f, pieces[i].f);
        } else if (op == SetOperation::Difference) { // the first child minus the others
            for (std::size_t i = 1; i < pieces.size(); ++i)
                r.f = b_.min(r.f, b_.neg(pieces[i].f));
        } else if (op == SetOperation::Morph) {
            double s = 0;
            if (const formula::Tape* tape = context_.scene.definition(ft, "morphFactor")) {
                formula::ScalarEvaluator e(*tape);
                s = e.evaluate({0, 0, 0, t, 0, 0, 0});
            }
            if (pieces.size() >= 2 && std::isfinite(s))
                r.f = b_.add(b_.mul(formula::Val::constant(1 - s), pieces[0].f),
                             b_.mul(formula::Val::constant(s), pieces[1].f));
        } else if (op == SetOperation::Formula) {
            if (const formula::Tape* tape = context_.scene.definition(ft, "operationDefinition")) {
                std::vector<formula::Val> values;
                for (const formula::ParameterInfo& p : tape->params) {
                    // f1, f2, ... are the children in order; a missing one reads 0.
                    const std::size_t i = std::size_t(std::atoi(p.name.c_str() + 1)) - 1;
                    values.push_back(i < pieces.size() ? pieces[i].f : formula::Val::constant(0));
                }
                auto in = local_;
                in[std::size_t(formula::Input::T)] = formula::Val::constant(t);
                r.f = formula::inlineTape(b_, *tape, in, values,
                                          textTag(ft, "operationDefinition"))[0];
            }
        }
        return r;
    }

    // The number of a text the composed tape's instructions come from
    // (SourceRange::source, ShapeMesh::texts).
    int textTag(const Node& node, const char* field) {
        for (std::size_t i = 0; i < texts_.size(); ++i)
            if (texts_[i].node == &node && texts_[i].field == field) return int(i);
        texts_.push_back({&node, field});
        return int(texts_.size()) - 1;
    }

    const SceneWalkContext& context_;
    WalkGuard& guard_;
    std::vector<std::string>& notes_;
    formula::TapeBuilder b_;
    Inputs local_{};
    std::vector<DefinitionText> texts_;
};

} // namespace

std::optional<ComposedShape> composeFunctionTransform(const SceneWalkContext& context,
                                                      WalkGuard& guard, const Node& ft,
                                                      std::vector<std::string>& notes) {
    return Composer(context, guard, notes).compose(ft);
}

} // namespace fl::mesh
