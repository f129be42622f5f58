#include "node_graph.h"

#include <algorithm>
#include <unordered_map>

namespace fl::scene {
namespace {

enum class Mark : std::uint8_t { Open, Done };

struct Visit {
    Mark mark = Mark::Open;
    std::size_t unfolded = 0; // this node and everything under it, unfolded
    std::size_t depth = 0;    // nodes on the longest path down from here
};

struct Frame {
    const Node* node;
    std::vector<const Node*> children;
    std::size_t next = 0;
    std::size_t unfolded = 0; // of the children done so far
    std::size_t depth = 0;
};

// Sums that stop one past the cap: a DEF used twice at each of 64 levels
// unfolds to 2^64 nodes, which no size_t holds.
std::size_t saturatingAdd(std::size_t a, std::size_t b, std::size_t cap) {
    const std::size_t ceiling = cap + 1;
    return (a >= ceiling || b >= ceiling || a + b >= ceiling) ? ceiling : a + b;
}

class GraphExaminer {
  public:
    GraphExaminer(Edges edges, std::size_t nodeCap, std::size_t depthCap)
        : edges_(edges), nodeCap_(nodeCap), depthCap_(depthCap) {}

    // Walks from `start`; returns false when a loop was found.
    bool walk(const Node& start, NodeGraphShape& shape) {
        auto [it, fresh] = visits_.try_emplace(&start);
        if (!fresh) return true; // done from an earlier start (an open one cannot be met here)
        push(start);
        while (!stack_.empty()) {
            Frame& top = stack_.back();
            if (top.next < top.children.size()) {
                const Node* child = top.children[top.next++];
                auto [cv, childFresh] = visits_.try_emplace(child);
                if (childFresh) {
                    push(*child); // invalidates `top`
                    continue;
                }
                if (cv->second.mark == Mark::Open) {
                    shape.loop = loopClosedBy(*top.node, *child);
                    return false;
                }
                top.unfolded = saturatingAdd(top.unfolded, cv->second.unfolded, nodeCap_);
                top.depth = std::max(top.depth, cv->second.depth);
                continue;
            }
            Visit& v = visits_[top.node];
            v.mark = Mark::Done;
            v.unfolded = saturatingAdd(top.unfolded, 1, nodeCap_);
            v.depth = std::min(top.depth, depthCap_) + 1;
            if (v.unfolded > nodeCap_ && !shape.overCap) shape.overCap = top.node;
            if (v.depth > depthCap_ && !shape.tooDeep) shape.tooDeep = top.node;
            stack_.pop_back();
        }
        return true;
    }

    const Visit& visitOf(const Node& node) const { return visits_.at(&node); }

  private:
    void push(const Node& node) {
        Frame f{&node, {}};
        forEachChild(node, edges_, [&](const Node& c) { f.children.push_back(&c); });
        stack_.push_back(std::move(f));
    }

    NodeLoop loopClosedBy(const Node& holder, const Node& ancestor) const {
        NodeLoop loop{&holder, &ancestor, {}};
        auto from = std::find_if(stack_.begin(), stack_.end(),
                                 [&](const Frame& f) { return f.node == &ancestor; });
        for (; from != stack_.end(); ++from)
            loop.path.push_back(from->node);
        return loop;
    }

    Edges edges_;
    std::size_t nodeCap_;
    std::size_t depthCap_;
    std::unordered_map<const Node*, Visit> visits_;
    std::vector<Frame> stack_;
};

} // namespace

NodeGraphShape examineNodeGraph(const std::vector<const Node*>& roots,
                                const std::vector<const Node*>& extraStarts, Edges edges,
                                std::size_t nodeCap, std::size_t depthCap) {
    NodeGraphShape shape;
    GraphExaminer examiner(edges, nodeCap, depthCap);
    for (const Node* root : roots) {
        if (!root) continue;
        if (!examiner.walk(*root, shape)) return shape;
        const Visit& v = examiner.visitOf(*root);
        shape.unfoldedNodes = saturatingAdd(shape.unfoldedNodes, v.unfolded, nodeCap);
        shape.depth = std::max(shape.depth, v.depth);
    }
    for (const Node* start : extraStarts)
        if (start && !examiner.walk(*start, shape)) return shape;
    return shape;
}

void checkUnfoldedScene(const Scene& scene, std::size_t maxNodes, std::size_t maxDepth,
                        std::vector<SceneDiagnostic>& out) {
    std::vector<const Node*> roots(scene.roots.begin(), scene.roots.end());
    const NodeGraphShape shape = examineNodeGraph(roots, {}, Edges::Shown, maxNodes, maxDepth);
    auto refuse = [&](const Node& at, std::string message, std::string suggestion) {
        out.push_back({Severity::Error, scene.pathOf(at.file), at.where, std::move(message),
                       std::move(suggestion), true});
    };
    if (shape.loop) // the builder refuses loops; met here only for a scene changed by code
        refuse(*shape.loop->holder, "this node contains itself", "a scene is a tree");
    else if (shape.overCap)
        refuse(*shape.overCap,
               "this node holds more than " + std::to_string(maxNodes) +
                   " nodes once every USE, PROTO instance and Inline in it is unfolded",
               "each USE repeats the whole node it names: USE smaller parts, or fewer times");
    else if (shape.tooDeep)
        refuse(*shape.tooDeep,
               "nodes nest more than " + std::to_string(maxDepth) +
                   " deep below this one once USEs, PROTO instances and Inlines are followed",
               "flatten the chain of USEs or PROTOs");
}

std::vector<const Node*> protoNodes(const Scene& scene) {
    std::vector<const Node*> nodes;
    std::vector<const ProtoDeclaration*> stack(scene.protos.begin(), scene.protos.end());
    while (!stack.empty()) {
        const ProtoDeclaration* p = stack.back();
        stack.pop_back();
        nodes.insert(nodes.end(), p->body.begin(), p->body.end());
        for (const FieldDeclaration& d : p->interface)
            nodes.insert(nodes.end(), d.value.nodes.begin(), d.value.nodes.end());
        stack.insert(stack.end(), p->protos.begin(), p->protos.end());
    }
    return nodes;
}

} // namespace fl::scene
