#pragma once
// A scene is a tree with shared leaves, never a loop (DESIGN §3). This is the
// one place that looks at the node graph as a graph: it finds a node that
// holds one of its own ancestors, and measures what the scene becomes once
// every USE is unfolded — the work every walker that goes down the tree does.
// The scene builder refuses what it finds; walkers keep a depth guard of
// their own (WalkPath) as a second line.
#include "scene.h"

#include <algorithm>
#include <cstddef>
#include <optional>
#include <vector>

namespace fl::scene {

// How deep any recursive walk over a scene may go. The reader refuses a scene
// deeper than this once USEs, PROTO expansions and Inlines are followed
// (ReadLimits::maxUnfoldedDepth), so a walker that meets the guard is looking
// at a scene that was not read, or was changed, and stops there.
inline constexpr std::size_t kMaxWalkDepth = 512;

// The nodes a recursive walk is inside, outermost first: the second line
// behind the reader's refusal, for scenes built or changed by code. A walker
// takes a Step into each node it enters and goes no further when the step is
// refused: the node is already on the path (a loop) or the path is
// kMaxWalkDepth long.
class WalkPath {
  public:
    class Step {
      public:
        Step(WalkPath& path, const Node* node) : path_(path) {
            auto& nodes = path_.nodes_;
            entered_ = node && nodes.size() < kMaxWalkDepth &&
                       std::find(nodes.begin(), nodes.end(), node) == nodes.end();
            if (entered_) nodes.push_back(node);
        }
        ~Step() {
            if (entered_) path_.nodes_.pop_back();
        }
        Step(const Step&) = delete;
        Step& operator=(const Step&) = delete;
        bool entered() const { return entered_; }

      private:
        WalkPath& path_;
        bool entered_ = false;
    };

  private:
    std::vector<const Node*> nodes_;
};

// Which edges of the tree to follow. The fields a Script or shader declares
// are not among them: they hold references, not children (VRML97 §6.40 lets a
// Script name itself in its own SFNode field), and no walk draws them.
enum class Edges : std::uint8_t {
    AsWritten,      // node-valued fields
    WithExpansions, // ... and each PROTO instance's expansion
    Shown,          // ... and each loaded Inline's scene (its roots)
};

// Calls f(child) for each node `node` holds, in field order: node-valued
// fields, then (by `edges`) the expansion and the inlined roots.
template <class F>
void forEachChild(const Node& node, Edges edges, F&& f) {
    for (const Field& field : node.fields)
        for (const Node* child : field.value.nodes)
            if (child) f(*child);
    if (edges == Edges::AsWritten) return;
    for (const Node* child : node.expansion)
        if (child) f(*child);
    if (edges == Edges::Shown && node.inlined)
        for (const Node* child : node.inlined->roots)
            if (child) f(*child);
}

// An edge that closes a loop: `holder` holds `ancestor`, which holds `holder`
// again through `path` (ancestor first, holder last).
struct NodeLoop {
    const Node* holder = nullptr;
    const Node* ancestor = nullptr;
    std::vector<const Node*> path;
};

struct NodeGraphShape {
    std::optional<NodeLoop> loop; // the first loop met; the measures below are then partial
    // Nodes a walk from the roots visits, a shared node once per path that
    // reaches it (saturates at the cap given).
    std::size_t unfoldedNodes = 0;
    std::size_t depth = 0; // nodes on the longest path from a root
    // The first node whose own unfolded size passed the cap: the place where
    // USEs multiply (all its children are under the cap). Null when none did.
    const Node* overCap = nullptr;
    // The first node whose depth passed the depth cap (null when none did).
    const Node* tooDeep = nullptr;
};

// Examines the graph reachable from `roots` and from `extraStarts` (PROTO
// bodies, interface defaults: loops there matter even if never instanced;
// they do not count toward the measures). Iterative: any depth, any size.
NodeGraphShape examineNodeGraph(const std::vector<const Node*>& roots,
                                const std::vector<const Node*>& extraStarts, Edges edges,
                                std::size_t nodeCap, std::size_t depthCap);

// Refuses (an error in `out`, at the node where it happens) a scene that,
// with its PROTO instances expanded and its Inlines shown, unfolds to more
// nodes or nests deeper than `limits` allow. Call after Inlines are loaded.
void checkUnfoldedScene(const Scene& scene, std::size_t maxNodes, std::size_t maxDepth,
                        std::vector<SceneDiagnostic>& out);

// Every node a scene's PROTO declarations hold (bodies and interface default
// values, nested declarations too), for `extraStarts`.
std::vector<const Node*> protoNodes(const Scene& scene);

} // namespace fl::scene
