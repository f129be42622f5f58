#include "effects_plan.h"

#include "field_access.h"
#include "node_graph.h"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <map>
#include <set>
#include <unordered_set>

namespace fl::scene {
namespace {

constexpr int kInputT = 3; // x y z t u v w

bool definitionReadsT(const Scene& scene, const Node* node, std::string_view field) {
    if (!node) return false;
    const formula::Tape* tape = scene.definition(*node, field);
    return tape && tape->usesInput[kInputT];
}

bool anyDefinitionReadsT(const Scene& scene, const Node* node) {
    if (!node) return false;
    for (const CompiledDefinition& d : scene.definitions)
        if (d.node == node && d.tape->usesInput[kInputT]) return true;
    return false;
}

bool wallClock(const Node* node) {
    return node && node->spec && findFieldSpec(*node->spec, "timeBase") &&
           stringField(*node, "timeBase") != "scene";
}

std::string nameOf(const Node& n) {
    return n.defName.empty() ? n.type : n.type + " " + n.defName;
}

class Planner {
  public:
    explicit Planner(const Scene& scene) : scene_(scene) {}

    EffectsPlan run() {
        collectRouteTargets();
        for (const Node* root : scene_.roots)
            visit(root);
        for (const PlanEntry& e : plan_.entries) {
            plan_.timeVarying |= e.timeVarying;
            plan_.usesWallClock |= e.usesWallClock;
            plan_.needsHaptics |= !e.tangible.empty();
        }
        return std::move(plan_);
    }

  private:
    void collectRouteTargets() {
        auto add = [&](const Route& r) {
            const Node* to = r.toNode;
            std::string f = r.toField;
            if (f.starts_with("set_")) f = f.substr(4);
            unsigned bits = kStatic;
            if (to->kind() == scene::NodeKind::Transform &&
                (f == "translation" || f == "rotation" || f == "scale" || f == "center" ||
                 f == "scaleOrientation"))
                bits = kTransform;
            else if (to->kind() == scene::NodeKind::Material ||
                     to->kind() == scene::NodeKind::Color ||
                     to->kind() == scene::NodeKind::ColorRGBA ||
                     to->kind() == scene::NodeKind::TwoSidedMaterial)
                bits = kColour;
            else if (to->kind() == scene::NodeKind::Coordinate ||
                     to->kind() == scene::NodeKind::Normal ||
                     to->kind() == scene::NodeKind::Sphere || to->kind() == scene::NodeKind::Box ||
                     to->kind() == scene::NodeKind::Cone ||
                     to->kind() == scene::NodeKind::Cylinder ||
                     to->kind() == scene::NodeKind::FGeometry)
                bits = kGeometry;
            else if (to->kind() == scene::NodeKind::Switch ||
                     to->kind() == scene::NodeKind::FTransform)
                bits = kTransform;
            if (bits) {
                routed_[to] |= bits;
                routeNotes_[to].push_back("driven by ROUTE " + nameOf(*r.fromNode) + "." +
                                          r.fromField + " TO " + r.toField);
            }
        };
        for (const Scene* s : scenesShownBy(scene_)) {
            for (const Route& r : s->routes)
                add(r);
            s->forEachNode([&](const Node& n) {
                for (const Route& r : n.expansionRoutes)
                    add(r);
            });
        }
    }

    void visit(const Node* raw) {
        const Node* n = effectiveNode(raw);
        const WalkPath::Step step(path_, n);
        if (!step.entered() || !visited_.insert(n).second) return;
        if (n->kind() == scene::NodeKind::FShape)
            shape(*n);
        else if (n->kind() == scene::NodeKind::FTransform)
            transform(*n);
        else if (auto it = routed_.find(n); it != routed_.end())
            standard(*n, it->second);
        for (const Field& f : n->fields)
            for (const Node* child : f.value.nodes)
                visit(child);
        if (n->inlined)
            for (const Node* root : n->inlined->roots)
                visit(root);
    }

    PlanEntry entryFor(const Node& n) {
        PlanEntry e;
        e.node = &n;
        e.name = nameOf(n);
        e.location = scene_.locationOf(n);
        if (auto it = routeNotes_.find(&n); it != routeNotes_.end()) e.notes = it->second;
        if (auto it = routed_.find(&n); it != routed_.end()) e.timeVarying |= it->second;
        return e;
    }

    void shape(const Node& n) {
        ++plan_.functionShapes;
        PlanEntry e = entryFor(n);
        const Node* geometry = effectiveNode(nodeField(n, "geometry"));
        const Node* appearance = effectiveNode(nodeField(n, "appearance"));
        const Node* physics = effectiveNode(nodeField(n, "physics"));
        if (!geometry) {
            e.geometry = "none";
            e.appliesToSiblings = true;
        } else if (geometry->kind() == scene::NodeKind::FGeometry) {
            e.geometry = stringField(*geometry, "type");
            if (definitionReadsT(scene_, geometry, "definition")) e.timeVarying |= kGeometry;
            e.usesWallClock |= wallClock(geometry);
        } else {
            e.geometry = geometry->type;
            if (auto it = routed_.find(geometry); it != routed_.end()) e.timeVarying |= it->second;
        }
        if (appearance) {
            const Node* material = effectiveNode(nodeField(*appearance, "material"));
            const Node* texture = effectiveNode(nodeField(*appearance, "texture"));
            if (material && material->kind() == scene::NodeKind::FMaterial &&
                anyDefinitionReadsT(scene_, material))
                e.timeVarying |= kColour;
            if (material && routed_.count(material)) e.timeVarying |= kColour;
            if (texture && texture->kind() == scene::NodeKind::FTexture3D &&
                definitionReadsT(scene_, texture, "definition"))
                e.timeVarying |= kDisplacement;
            e.usesWallClock |= wallClock(material) || wallClock(texture);
        }
        if (physics) {
            const Node* surface = effectiveNode(nodeField(*physics, "surface"));
            if (surface) {
                tangible(e, TangibleKind::Friction, effectiveNode(nodeField(*surface, "friction")));
                tangible(e, TangibleKind::Tension, effectiveNode(nodeField(*surface, "tension")));
            }
            tangible(e, TangibleKind::Density, effectiveNode(nodeField(*physics, "density")));
            tangible(e, TangibleKind::Force, effectiveNode(nodeField(*physics, "force")));
        }
        plan_.entries.push_back(std::move(e));
    }

    void tangible(PlanEntry& e, TangibleKind kind, const Node* node) {
        if (!node) return;
        TangibleEffect t;
        t.kind = kind;
        t.node = node;
        const auto lo = numbersField(*node, "domainMin"), hi = numbersField(*node, "domainMax");
        for (int i = 0; i < 3 && lo.size() == 3 && hi.size() == 3; ++i) {
            t.domainMin[i] = lo[i];
            t.domainMax[i] = hi[i];
        }
        t.timeVarying = definitionReadsT(scene_, node, "definition");
        if (t.timeVarying) e.timeVarying |= kPhysics;
        e.usesWallClock |= wallClock(node);
        e.tangible.push_back(std::move(t));
    }

    void transform(const Node& n) {
        PlanEntry e = entryFor(n);
        e.geometry = "operation " + stringField(n, "operation");
        for (std::string_view f : {"translation", "rotationAngle", "scale"})
            if (definitionReadsT(scene_, &n, f)) e.timeVarying |= kTransform;
        for (std::string_view f : {"morphFactor", "operationDefinition"})
            if (definitionReadsT(scene_, &n, f)) e.timeVarying |= kGeometry;
        e.usesWallClock = wallClock(&n);
        plan_.entries.push_back(std::move(e));
    }

    void standard(const Node& n, unsigned bits) {
        PlanEntry e = entryFor(n);
        e.geometry = n.type;
        e.timeVarying = bits;
        plan_.entries.push_back(std::move(e));
    }

    const Scene& scene_;
    EffectsPlan plan_;
    std::set<const Node*> visited_;
    WalkPath path_;
    std::map<const Node*, unsigned> routed_;
    std::map<const Node*, std::vector<std::string>> routeNotes_;
};

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    return buf;
}

} // namespace

std::unordered_map<const Node*, std::vector<const Node*>> lendingShapes(const Scene& scene) {
    // The grouping nodes that hold a lender, found in one pass.
    std::vector<std::pair<const Node*, const Node*>> groups; // (group, lender)
    scene.forEachNode([&](const Node& n) {
        for (const Field& f : n.fields)
            for (const Node* c : f.value.nodes) {
                const Node* child = effectiveNode(c);
                if (child && child->kind() == scene::NodeKind::FShape &&
                    !effectiveNode(nodeField(*child, "geometry")))
                    groups.emplace_back(&n, child);
            }
    });
    std::unordered_map<const Node*, std::vector<const Node*>> out;
    for (const auto& [group, lender] : groups) {
        // Each node once per lender (a USE'd subtree too): the walk is
        // bounded by the scene's size.
        std::vector<const Node*> todo{group};
        std::unordered_set<const Node*> seen{group};
        while (!todo.empty()) {
            const Node* n = todo.back();
            todo.pop_back();
            for (const Field& f : n->fields)
                for (const Node* c : f.value.nodes) {
                    const Node* child = effectiveNode(c);
                    if (!child) continue;
                    if (child->kind() == scene::NodeKind::Shape) {
                        auto& lenders = out[child];
                        if (std::find(lenders.begin(), lenders.end(), lender) == lenders.end())
                            lenders.push_back(lender);
                    } else if (child->kind() != scene::NodeKind::FShape &&
                               seen.insert(child).second) {
                        todo.push_back(child);
                    }
                }
        }
    }
    return out;
}

std::unordered_map<const Node*, const PlanEntry*> lentPhysics(const Scene& scene,
                                                              const EffectsPlan& plan) {
    std::unordered_map<const Node*, const PlanEntry*> tangible;
    for (const PlanEntry& e : plan.entries)
        if (e.node && e.appliesToSiblings && !e.tangible.empty()) tangible.emplace(e.node, &e);
    std::unordered_map<const Node*, const PlanEntry*> out;
    if (tangible.empty()) return out;
    for (const auto& [shape, lenders] : lendingShapes(scene))
        for (const Node* lender : lenders)
            if (auto it = tangible.find(lender); it != tangible.end()) {
                out.emplace(shape, it->second);
                break;
            }
    return out;
}

std::string_view tangibleKindName(TangibleKind kind) {
    switch (kind) {
    case TangibleKind::Friction:
        return "friction";
    case TangibleKind::Tension:
        return "tension";
    case TangibleKind::Density:
        return "density";
    case TangibleKind::Force:
        return "force";
    }
    return "?";
}

EffectsPlan makeEffectsPlan(const Scene& scene) {
    return Planner(scene).run();
}

std::vector<std::string_view> timeVaryingNames(unsigned bits) {
    static constexpr std::string_view kNames[] = {"geometry", "displacement", "colour", "transform",
                                                  "physics"}; // in bit order
    std::vector<std::string_view> names;
    for (unsigned i = 0; i < std::size(kNames); ++i)
        if (bits & (1u << i)) names.push_back(kNames[i]);
    return names;
}

std::string timeVaryingText(unsigned bits) {
    if (bits == kStatic) return "static";
    std::string out;
    for (std::string_view name : timeVaryingNames(bits))
        out += std::string(out.empty() ? "" : ", ") + std::string(name);
    return out;
}

std::string planText(const EffectsPlan& plan) {
    std::string out = "effects plan: " + std::to_string(plan.functionShapes) +
                      " function shape(s); varies with time: " + timeVaryingText(plan.timeVarying) +
                      "; haptics: " + (plan.needsHaptics ? "needed" : "not needed") +
                      "; wall clock: " + (plan.usesWallClock ? "yes" : "no") + "\n";
    for (const PlanEntry& e : plan.entries) {
        out += "  " + e.name + " (" + e.location + ")\n";
        out +=
            "    geometry: " + e.geometry +
            (e.appliesToSiblings ? " (lends its properties to the shapes grouped with it)" : "") +
            "\n";
        out += "    varies with time: " + timeVaryingText(e.timeVarying) +
               (e.usesWallClock ? " (wall clock)" : "") + "\n";
        for (const TangibleEffect& t : e.tangible)
            out += "    tangible: " + std::string(tangibleKindName(t.kind)) + " in [" +
                   num(t.domainMin[0]) + " " + num(t.domainMin[1]) + " " + num(t.domainMin[2]) +
                   " .. " + num(t.domainMax[0]) + " " + num(t.domainMax[1]) + " " +
                   num(t.domainMax[2]) + "]" + (t.timeVarying ? ", varies with time" : "") + "\n";
        for (const std::string& note : e.notes)
            out += "    " + note + "\n";
    }
    return out;
}

} // namespace fl::scene
