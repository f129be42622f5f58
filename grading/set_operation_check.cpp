// The set-operations requirement: count the operations that change the
// shown solid, at any judged moment; explain the ones that do not.
#include "checks.h"

#include "formula/builtins.h"
#include "operation_liveness.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <map>
#include <memory>
#include <set>
#include <tuple>

namespace fl::grading {
namespace {

// Whether `text` is one call of a library primitive, `box(0.5, 0.4, 0.5)`:
// an operation whose source is that call is the library's, not the student's.
bool isPrimitiveCall(std::string_view text) {
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front())))
        text.remove_prefix(1);
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())))
        text.remove_suffix(1);
    std::size_t name = 0;
    while (name < text.size() &&
           (std::isalnum(static_cast<unsigned char>(text[name])) || text[name] == '_'))
        ++name;
    if (name == 0 || name >= text.size() || text[name] != '(' || text.back() != ')') return false;
    // The parenthesis opened after the name closes at the very end.
    int depth = 0;
    for (std::size_t i = name; i < text.size(); ++i) {
        depth += text[i] == '(' ? 1 : text[i] == ')' ? -1 : 0;
        if (depth == 0 && i + 1 < text.size()) return false;
    }
    const formula::BuiltinInfo* b = formula::findBuiltin(text.substr(0, name));
    return b && b->readsCoordinates;
}

// One operation as written: its text, and the place in it.
using OperationKey = std::tuple<const scene::Node*, std::string, std::size_t, std::size_t>;

struct Found {
    SetOperationKind kind;
    Location where;
    std::string text;
    bool live = false;
    std::string why; // dead: the reason
    // The fields it was judged in: a moment showing one of them again
    // (a shape that does not change) is not judged twice.
    std::vector<std::shared_ptr<const field::ImplicitField>> judgedIn;
};

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

std::string boxText(const field::Box3& b) {
    const bool cube =
        b.lo[0] == b.lo[1] && b.lo[1] == b.lo[2] && b.hi[0] == b.hi[1] && b.hi[1] == b.hi[2];
    if (cube) return "[" + number(b.lo[0]) + "," + number(b.hi[0]) + "]³";
    std::string s;
    for (std::size_t k = 0; k < 3; ++k)
        s += (k ? " x [" : "[") + number(b.lo[k]) + "," + number(b.hi[k]) + "]";
    return s;
}

// How many pairs of parentheses wrap the whole of `text` ("((a) & b)": 1).
std::size_t wrappingParentheses(const std::string& text) {
    std::size_t n = 0;
    while (text.size() >= 2 * n + 2 && text[n] == '(' && text[text.size() - 1 - n] == ')') {
        int depth = 0;
        bool wraps = true;
        for (std::size_t i = n; i + 1 + n < text.size() && wraps; ++i) {
            depth += text[i] == '(' ? 1 : text[i] == ')' ? -1 : 0;
            wraps = depth > 0;
        }
        if (!wraps) break;
        ++n;
    }
    return n;
}

// Where the operator of a set operation written as an expression is: the
// last & | \ outside parentheses, | first (it binds loosest). 0 (the
// expression's start) for min(...), max(...) and the R-functions.
std::size_t operatorOffset(const std::string& written) {
    // Parentheses round the whole expression are not its structure.
    const std::size_t from = wrappingParentheses(written);
    const std::string text = written.substr(from, written.size() - 2 * from);
    std::size_t best = 0;
    int depth = 0, rank = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        depth += c == '(' ? 1 : c == ')' ? -1 : 0;
        if (depth != 0) continue;
        const int r = c == '|' ? 2 : (c == '&' || c == '\\') ? 1 : 0;
        if (r > 0 && r >= rank) {
            rank = r;
            best = from + i;
        }
    }
    return best;
}

// "(5 - x*x)" reads as "5 - x*x" in a sentence; "(a) + (b)" keeps its own.
std::string withoutOuterParentheses(const std::string& text) {
    const std::size_t n = wrappingParentheses(text);
    return text.substr(n, text.size() - 2 * n);
}

std::string operandText(const SubmissionView& view, const mesh::ShapeMesh& s,
                        std::size_t instruction, int operand) {
    const auto writer = operandWriter(s.field->tape, instruction, operand);
    if (!writer) return {};
    std::string text = withoutOuterParentheses(view.textOf(s, s.field->tape.code[*writer].origin));
    return text.empty() ? std::string{} : "`" + shortened(text, 40) + "`";
}

std::string deadReason(const SubmissionView& view, const mesh::ShapeMesh& s,
                       const OperationVerdict& v) {
    const std::string kind(setOperationKindName(v.operation.kind));
    if (v.undecided) return "the " + kind + " could not be judged within the checker's budget";
    const std::string idle = operandText(view, s, v.operation.instruction, v.idleOperand);
    std::string reason = "the " + kind + (idle.empty() ? "" : " with " + idle) +
                         " changes nothing in the box " + boxText(s.field->box);
    switch (v.idleSign) {
    case OperandSign::Positive:
        return reason + ": that operand is positive everywhere there";
    case OperandSign::Negative:
        return reason + ": that operand is negative everywhere there";
    case OperandSign::Mixed:
        break;
    }
    return reason + ": the other operand alone gives the same solid";
}

} // namespace

RequirementResult checkSetOperations(const SubmissionView& view, const Requirement& r,
                                     Budget& budget, const CompareOptions& compare) {
    RequirementResult out{r.id, r.kind, false, 0, r.points, {}, {}};
    std::map<OperationKey, Found> found;
    std::vector<OperationKey> order; // as first met, for stable messages
    for (const mesh::SceneMeshes& frame : view.frames())
        for (const mesh::ShapeMesh& s : frame.shapes) {
            if (!s.field || !SubmissionView::shown(s)) continue;
            for (const TapeSetOperation& op : setOperationsIn(s.field->tape)) {
                const std::int32_t origin = s.field->tape.code[op.instruction].origin;
                const mesh::DefinitionText* text = view.textSource(s, origin);
                // The box a child of an FTransform is cut by is not the student's,
                // and neither are the operations inside a library primitive
                // (box() is one shape, not the intersections that make it).
                if (!text || text->field == "domainMin") continue;
                if (isPrimitiveCall(view.textOf(s, origin))) continue;
                const formula::SourceRange& range = s.field->tape.origins[std::size_t(origin)];
                // An FTransform's operation over n children is n - 1 operations,
                // all from one word: told apart by their place in the tape.
                const bool combined = text->field == "operation";
                const OperationKey key{text->node, text->field,
                                       combined ? op.instruction : range.begin.offset,
                                       combined ? op.instruction : range.end.offset};
                auto [it, fresh] = found.try_emplace(key);
                Found& f = it->second;
                if (fresh) {
                    order.push_back(key);
                    f.kind = op.kind;
                    f.where =
                        text->field == "operation"
                            ? view.locationOf(*text->node, "operation")
                            : view.locationOf(s, origin, operatorOffset(view.textOf(s, origin)));
                    // "union of FTransform U's children at line 22" (with
                    // describe's kind and line): never "the the", never
                    // the line twice.
                    f.text =
                        text->field == "operation"
                            ? "of " +
                                  (text->node->defName.empty()
                                       ? std::string("an FTransform's")
                                       : text->node->type + " " + text->node->defName + "'s") +
                                  " children"
                            : "`" + shortened(withoutOuterParentheses(view.textOf(s, origin)), 50) +
                                  "`";
                }
                if (f.live || std::any_of(f.judgedIn.begin(), f.judgedIn.end(), [&](const auto& j) {
                        return identicalFields(*j, *s.field);
                    }))
                    continue;
                f.judgedIn.push_back(s.field);
                const OperationVerdict v = judgeOperation(*s.field, op, budget, compare);
                if (v.counts)
                    f.live = true;
                else if (f.why.empty())
                    f.why = deadReason(view, s, v);
            }
        }
    std::set<SetOperationKind> kinds;
    std::vector<const Found*> live, dead;
    for (const OperationKey& k : order) {
        const Found& f = found.at(k);
        (f.live ? live : dead).push_back(&f);
        if (f.live) kinds.insert(f.kind);
    }
    out.met = int(live.size()) >= r.minimum && int(kinds.size()) >= r.minimumKinds;
    out.points = out.met ? r.points : 0;
    auto describe = [&](const Found& f) {
        return std::string(setOperationKindName(f.kind)) + " " + f.text + " at line " +
               std::to_string(f.where.line);
    };
    std::string text = std::to_string(live.size()) + " set operation" +
                       (live.size() == 1 ? "" : "s") + " of " + std::to_string(kinds.size()) +
                       " kind" + (kinds.size() == 1 ? "" : "s") + " change the shown solid";
    for (std::size_t i = 0; i < live.size(); ++i) {
        text += (i ? "; " : ": ") + describe(*live[i]);
        out.locations.push_back(live[i]->where);
    }
    if (!out.met) {
        text += " (" + std::to_string(r.minimum) + " operations of at least " +
                std::to_string(r.minimumKinds) + " kinds are needed)";
        // The first few dead ones, explained; the rest counted.
        constexpr std::size_t kExplained = 5;
        for (std::size_t i = 0; i < dead.size() && i < kExplained; ++i) {
            text += ". Not counted: " + dead[i]->why + " (line " +
                    std::to_string(dead[i]->where.line) + ")";
            out.locations.push_back(dead[i]->where);
        }
        if (dead.size() > kExplained)
            text += ". " + std::to_string(dead.size() - kExplained) + " more not counted";
    }
    out.evidence = text;
    return out;
}

} // namespace fl::grading
