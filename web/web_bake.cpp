#include "web_bake.h"

#include "animation/animator.h"
#include "mesh/level_of_detail.h"
#include "mesh/mesh_cache.h"
#include "mesh/scene_meshing.h"
#include "mesh/scene_preview.h"
#include "scene/components.h"
#include "scene/effects_plan.h"
#include "scene/node_building.h"
#include "scene/scene_references.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <unordered_map>
#include <unordered_set>

namespace fl::web {
namespace {

using scene::Node;
using scene::NodeKind;

constexpr int kMaxDepth = 256; // the builder refuses loops; this bounds deep trees

bool isRootKind(NodeKind kind) {
    return kind == NodeKind::FShape || kind == NodeKind::Shape || kind == NodeKind::FTransform;
}

bool isFunctionNode(const Node& n) {
    return n.spec && n.spec->component == "FunctionLab";
}

// Every node a node holds in its fields, through PROTO instances to what they
// stand for; `skip` names a field not to follow.
template <class F>
void forEachChild(const Node& n, F&& f) {
    for (const scene::Field& field : n.fields)
        for (const Node* child : field.value.nodes)
            if (const Node* c = scene::effectiveNode(child)) f(field.name, *c);
    if (n.inlined)
        for (const Node* root : n.inlined->roots)
            if (const Node* c = scene::effectiveNode(root)) f("children", *c);
}

bool isUrlField(const scene::Field& f) {
    return f.value.type == scene::FieldType::MFString &&
           (f.name == "url" || (f.name.size() > 3 && f.name.ends_with("Url")));
}

bool isRemote(std::string_view url) {
    const auto colon = url.find(':');
    const auto slash = url.find('/');
    // A scheme (http:, data:, javascript: ...) or a network path (//host).
    return url.starts_with("//") || (colon != std::string_view::npos && colon > 1 &&
                                     (slash == std::string_view::npos || colon < slash));
}

// A number to four significant digits (LOD ranges, sequencer keys).
double fourDigits(double v) {
    if (v == 0 || !std::isfinite(v)) return v;
    const double scale = std::pow(10.0, 3 - std::floor(std::log10(std::abs(v))));
    return std::round(v * scale) / scale;
}

// Digits a page does not need, left out of its text (a third of its size):
// positions to 1e-4 of the mesh's longest side (a cell at resolution 512 is
// 20 times that), normals and colours to 1e-3.
void roundForText(mesh::Mesh& m) {
    const field::Box3 box = mesh::pointBounds(m.positions);
    const double side = box.valid() ? box.longestSide() : 1.0;
    const double step = std::pow(10.0, std::floor(std::log10(std::max(side, 1e-30) * 1e-4)));
    const auto round = [](float v, double q) { return float(std::round(double(v) / q) * q); };
    for (auto& p : m.positions)
        for (float& v : p)
            v = round(v, step);
    for (auto& n : m.normals)
        for (float& v : n)
            v = round(v, 1e-3);
    for (auto& c : m.colours)
        for (float& v : c)
            v = round(v, 1e-3);
}

// The topmost FShape, Shape or FTransform on a way down the scene, as the
// mesher's walk (SceneMeshOptions::meshInRootFrame) names it.
struct Root {
    const Node* node = nullptr;
    bool function = false; // its look comes from functions: replaced by meshes
    int group = -1;        // its moment group; -1: static
};

// Roots that vary with time on the same cycle and clock share their moments.
struct MomentGroup {
    BakedClock clock;
    std::vector<double> moments; // scene seconds
};

// One shape of a root at one moment: a Shape per resolution, finest first.
struct ShapeLevels {
    std::vector<scene::Node*> levels;
    field::Box3 box{{1e300, 1e300, 1e300}, {-1e300, -1e300, -1e300}};
};

class Baker {
  public:
    Baker(const scene::Scene& source, const BakeOptions& options, BakeResult& out)
        : src_(source), options_(options), out_(out), animator_(source) {
        for (double r : options.resolutions)
            if (std::isfinite(r) && r >= 1) resolutions_.push_back(r);
        if (resolutions_.empty()) resolutions_.push_back(32);
        std::sort(resolutions_.begin(), resolutions_.end(), std::greater<>());
        resolutions_.erase(std::unique(resolutions_.begin(), resolutions_.end()),
                           resolutions_.end());
        frames_ = std::clamp(options.frames, 2, 1000);
        src_.forEachNode([&](const Node& n) {
            if (!n.defName.empty()) names_.insert(n.defName);
        });
        // Urls resolve inside the scene's folder, found once.
        if (const std::string& path = src_.pathOf(0); !path.empty()) {
            std::error_code ec;
            urlContext_.emplace();
            urlContext_->root = std::filesystem::weakly_canonical(
                std::filesystem::absolute(path).parent_path(), ec);
            urlContext_->displayRoot = urlContext_->root;
        }
    }

    void run() {
        discover();
        meshAll();
        if (out_.cancelled) return;
        transcribe();
    }

  private:
    // ---- which roots there are, and how each varies with time

    void discover() {
        lenders_ = scene::lendingShapes(src_);
        for (const scene::Scene* s : scene::scenesShownBy(src_))
            for (const scene::CompiledDefinition& d : s->definitions)
                if (d.tape && d.tape->usesInput[std::size_t(formula::Input::T)])
                    timeReaders_.insert(d.node);
        animator_.tick(animation::Instant{});
        std::unordered_set<const Node*> seen;
        for (const Node* root : src_.roots)
            find(root, 0, seen);
    }

    void find(const Node* raw, int depth, std::unordered_set<const Node*>& seen) {
        const Node* n = scene::effectiveNode(raw);
        if (!n || depth > kMaxDepth || !seen.insert(n).second) return;
        if (isRootKind(n->kind())) {
            addRoot(*n);
            return;
        }
        forEachChild(*n, [&](const std::string&, const Node& c) { find(&c, depth + 1, seen); });
    }

    // The nodes below a root that shape its look (its physics left out).
    void subtree(const Node& n, int depth, std::vector<const Node*>& nodes,
                 std::unordered_set<const Node*>& seen) const {
        if (depth > kMaxDepth || !seen.insert(&n).second) return;
        nodes.push_back(&n);
        forEachChild(n, [&](const std::string& field, const Node& c) {
            if (field != "physics") subtree(c, depth + 1, nodes, seen);
        });
    }

    void addRoot(const Node& n) {
        Root r{&n};
        std::vector<const Node*> nodes;
        std::unordered_set<const Node*> seen;
        subtree(n, 0, nodes, seen);
        r.function =
            lenders_.count(&n) > 0 || std::any_of(nodes.begin(), nodes.end(),
                                                  [](const Node* m) { return isFunctionNode(*m); });
        if (r.function) r.group = groupOf(nodes);
        index_.emplace(&n, roots_.size());
        roots_.push_back(r);
    }

    // The cycle a root's time-reading nodes repeat on: the longest of theirs.
    int groupOf(const std::vector<const Node*>& nodes) {
        std::optional<animation::FunctionTiming> longest;
        bool loop = false;
        animation::TimeBase base = animation::TimeBase::Scene;
        for (const Node* n : nodes) {
            if (!timeReaders_.count(n)) continue;
            const animation::FunctionTiming t = animator_.timing(*n);
            if (!longest || t.window.cycleSeconds > longest->window.cycleSeconds) longest = t;
            loop = loop || t.window.loop;
            if (t.base != animation::TimeBase::Scene) base = t.base;
        }
        if (!longest) return -1;
        // A cycle no page can play (a student's cycleInterval of 1e300):
        // the shape is shown as it is at moment 0, and said.
        if (!(longest->window.cycleSeconds > 1e-3 && longest->window.cycleSeconds <= 1e7)) {
            warnOnce("a cycleInterval of " + std::to_string(longest->window.cycleSeconds) +
                     " s cannot be played as frames: shown as at moment 0");
            return -1;
        }
        BakedClock clock;
        clock.cycleSeconds = longest->window.cycleSeconds;
        clock.loop = loop;
        clock.base = base == animation::TimeBase::Utc     ? ClockBase::Utc
                     : base == animation::TimeBase::Local ? ClockBase::Local
                                                          : ClockBase::Scene;
        // Wall clocks: scene second s is the wall-clock second s after 1970
        // (mesh::momentOf), which a TimeSensor started in 1970 reaches too.
        clock.startSeconds =
            clock.base == ClockBase::Scene ? double(longest->window.startNs) / 1e9 : 0.0;
        for (std::size_t g = 0; g < groups_.size(); ++g) {
            const BakedClock& c = groups_[g].clock;
            if (c.cycleSeconds == clock.cycleSeconds && c.loop == clock.loop &&
                c.base == clock.base && c.startSeconds == clock.startSeconds)
                return int(g);
        }
        MomentGroup group;
        group.clock = clock;
        // Looping: N moments of [0, cycle); once: N moments of [0, cycle], the end included.
        const int steps = loop ? frames_ : frames_ - 1;
        for (int k = 0; k < frames_; ++k)
            group.moments.push_back(clock.startSeconds + clock.cycleSeconds * k / steps);
        groups_.push_back(std::move(group));
        return int(groups_.size() - 1);
    }

    // ---- meshing every root at every resolution and moment

    void meshAll() {
        levels_.resize(roots_.size());
        for (std::size_t i = 0; i < roots_.size(); ++i)
            levels_[i].resize(
                roots_[i].group < 0 ? 1 : groups_[std::size_t(roots_[i].group)].moments.size());
        std::size_t steps = 1;
        for (const MomentGroup& g : groups_)
            steps += g.moments.size();
        steps *= resolutions_.size();
        std::size_t done = 0;
        for (std::size_t ri = 0; ri < resolutions_.size(); ++ri) {
            meshAt(0, ri, -1, 0);
            report(++done, steps);
            for (std::size_t g = 0; g < groups_.size() && !out_.cancelled; ++g)
                for (std::size_t k = 0; k < groups_[g].moments.size() && !out_.cancelled; ++k) {
                    meshAt(groups_[g].moments[k], ri, int(g), k);
                    report(++done, steps);
                }
            if (out_.cancelled) return;
        }
    }

    void report(std::size_t done, std::size_t steps) {
        if (options_.cancel && options_.cancel->load()) out_.cancelled = true;
        if (options_.progress) options_.progress(double(done) / double(steps));
    }

    void meshAt(double seconds, std::size_t ri, int group, std::size_t frame) {
        mesh::SceneMeshOptions so;
        so.mesh.resolution = resolutions_[ri];
        so.mesh.threads = options_.threads;
        so.mesh.cancel = options_.cancel;
        so.useFileResolution = false;
        so.placeInScene = true;
        so.meshInRootFrame = true;
        so.everyChoice = true;
        so.sceneSeconds = seconds;
        so.cache = &cache_;
        mesh::SceneMeshes meshes = mesh::meshScene(src_, so);
        // A root USEd again is meshed once (meshInRootFrame).
        std::unordered_map<const Node*, std::size_t> count;
        for (mesh::ShapeMesh& s : meshes.shapes) {
            const auto it = index_.find(s.root);
            if (it == index_.end()) continue;
            const Root& root = roots_[it->second];
            if (!root.function || root.group != group) continue;
            if (!s.error.empty()) warnOnce(s.name + ": " + s.error);
            auto& shapes = levels_[it->second][frame];
            const std::size_t i = count[s.root]++;
            if (shapes.size() <= i) shapes.resize(i + 1);
            ShapeLevels& l = shapes[i];
            l.levels.resize(resolutions_.size(), nullptr);
            if (s.mesh.empty()) continue;
            roundForText(s.mesh);
            l.levels[ri] = mesh::standardShapeNode(out_.scene, s);
            l.box = mesh::pointBounds(s.mesh.positions, l.box);
            out_.triangles += s.mesh.triangleCount();
            if (out_.triangles > options_.maxTriangles && out_.error.empty()) {
                out_.cancelled = true;
                out_.error = "the page would hold more than " +
                             std::to_string(options_.maxTriangles) +
                             " triangles (every level of every frame): use fewer --frames or "
                             "lower --resolutions";
            }
        }
    }

    // ---- the replacements

    std::string uniqueName(const std::string& wanted) {
        std::string name = wanted;
        for (int k = 2; names_.count(name); ++k)
            name = wanted + "_" + std::to_string(k);
        names_.insert(name);
        return name;
    }

    scene::Node* group(std::vector<scene::Node*> children) {
        scene::Node* g = scene::newCatalogueNode(out_.scene, "Group");
        if (!children.empty())
            scene::addNodesField(*g, "children", scene::FieldType::MFNode, std::move(children));
        return g;
    }

    scene::Node* lod(const ShapeLevels& shape) {
        std::vector<scene::Node*> levels;
        for (scene::Node* level : shape.levels)
            levels.push_back(level ? level : group({}));
        if (levels.size() == 1) return levels.front();
        const auto& b = shape.box;
        // A flat shape (the clock's face) has a box of no depth: still a box.
        if (!(b.lo[0] <= b.hi[0] && b.lo[1] <= b.hi[1] && b.lo[2] <= b.hi[2])) return group({});
        scene::Node* n = scene::newCatalogueNode(out_.scene, "LOD");
        scene::addNumbersField(
            *n, "center", scene::FieldType::SFVec3f,
            {(b.lo[0] + b.hi[0]) / 2, (b.lo[1] + b.hi[1]) / 2, (b.lo[2] + b.hi[2]) / 2});
        std::vector<double> ranges = lodRanges(resolutions_, b);
        for (double& r : ranges)
            r = fourDigits(r);
        scene::addNumbersField(*n, "range", scene::FieldType::MFFloat, std::move(ranges));
        scene::addNodesField(*n, "children", scene::FieldType::MFNode, std::move(levels));
        return n;
    }

    scene::Node* frameGroup(const std::vector<ShapeLevels>& shapes) {
        std::vector<scene::Node*> children;
        for (const ShapeLevels& s : shapes)
            children.push_back(lod(s));
        return group(std::move(children));
    }

    void route(scene::Node* from, std::string fromField, scene::Node* to, std::string toField) {
        scene::Route r;
        r.fromNode = from;
        r.fromField = std::move(fromField);
        r.toNode = to;
        r.toField = std::move(toField);
        out_.scene.routes.push_back(std::move(r));
    }

    scene::Node* replacement(std::size_t i) {
        const Root& root = roots_[i];
        ++out_.roots;
        const auto& frames = levels_[i];
        if (root.group < 0) {
            scene::Node* g = frameGroup(frames.front());
            g->defName = root.node->defName;
            return g;
        }
        ++out_.animated;
        const MomentGroup& moments = groups_[std::size_t(root.group)];
        const std::size_t n = frames.size();
        scene::Node* sensor = scene::newCatalogueNode(out_.scene, "TimeSensor");
        sensor->defName = uniqueName("FunctionLab_Clock");
        scene::addNumbersField(*sensor, "cycleInterval", scene::FieldType::SFTime,
                               {moments.clock.cycleSeconds});
        scene::addNumbersField(*sensor, "loop", scene::FieldType::SFBool,
                               {moments.clock.loop ? 1.0 : 0.0});
        scene::Node* sequencer = scene::newCatalogueNode(out_.scene, "IntegerSequencer");
        sequencer->defName = uniqueName("FunctionLab_Frame");
        std::vector<double> keys, values;
        const double steps = moments.clock.loop ? double(n) : double(n - 1);
        for (std::size_t k = 0; k < n; ++k) {
            keys.push_back(fourDigits(double(k) / steps));
            values.push_back(double(k));
        }
        scene::addNumbersField(*sequencer, "key", scene::FieldType::MFFloat, std::move(keys));
        scene::addNumbersField(*sequencer, "keyValue", scene::FieldType::MFInt32,
                               std::move(values));
        scene::Node* choice = scene::newCatalogueNode(out_.scene, "Switch");
        choice->defName = uniqueName("FunctionLab_Frames");
        scene::addNumbersField(*choice, "whichChoice", scene::FieldType::SFInt32, {0});
        std::vector<scene::Node*> children;
        for (const auto& shapes : frames)
            children.push_back(frameGroup(shapes));
        scene::addNodesField(*choice, "children", scene::FieldType::MFNode, std::move(children));
        route(sensor, "fraction_changed", sequencer, "set_fraction");
        route(sequencer, "value_changed", choice, "set_whichChoice");
        BakedClock clock = moments.clock;
        clock.timeSensor = sensor->defName;
        out_.clocks.push_back(std::move(clock));
        scene::Node* g = group({sensor, sequencer, choice});
        g->defName = root.node->defName;
        return g;
    }

    // ---- the standard scene around them

    void transcribe() {
        scene::Scene& out = out_.scene;
        out.encoding = scene::Encoding::Xml;
        out.version = "4.0";
        out.profile = "Interchange";
        out.meta = src_.meta;
        out.meta.emplace_back("generator", "FunctionLab export-web");
        for (const Node* root : src_.roots)
            if (scene::Node* c = copy(root, 0)) out.roots.push_back(c);
        copyRoutes(src_.routes);
        for (const Node* instance : instances_)
            copyRoutes(instance->expansionRoutes);
        for (const scene::Scene* inlined : inlined_)
            copyRoutes(inlined->routes);
        if (droppedRoutes_ > 0)
            warnOnce(std::to_string(droppedRoutes_) +
                     " ROUTE(s) into or out of function nodes or left-out nodes are not "
                     "exported: the frames play what they did");
        addComponents();
    }

    scene::Node* copy(const Node* raw, int depth) {
        const Node* n = scene::effectiveNode(raw);
        if (!n) {
            warnOnce("a PROTO instance whose EXTERNPROTO was not loaded is left out");
            return nullptr;
        }
        if (raw != n && raw->proto) instances_.push_back(raw);
        if (const auto it = copies_.find(n); it != copies_.end()) return it->second;
        if (depth > kMaxDepth) {
            warnOnce("the scene is nested deeper than " + std::to_string(kMaxDepth) +
                     " nodes: what is deeper is left out");
            return nullptr;
        }
        scene::Node*& slot = copies_[n];
        if (const auto it = index_.find(n); it != index_.end() && roots_[it->second].function) {
            slot = replacement(it->second);
            replaced_.insert(slot);
            return slot;
        }
        const NodeKind kind = n->kind();
        if (kind == NodeKind::Script) {
            warnOnce(src_.locationOf(*n) +
                     ": a Script node is left out: a page never runs a scene's scripts");
            return slot = nullptr;
        }
        if (kind == NodeKind::Inline) {
            if (!n->inlined) return slot = nullptr;
            inlined_.push_back(n->inlined);
            std::vector<scene::Node*> children;
            for (const Node* r : n->inlined->roots)
                if (scene::Node* c = copy(r, depth + 1)) children.push_back(c);
            slot = group(std::move(children));
            slot->defName = n->defName;
            return slot;
        }
        if (!n->spec || isFunctionNode(*n)) {
            warnOnce(src_.locationOf(*n) + ": " + n->type +
                     " is not a node X3D browsers know: left out");
            return slot = nullptr;
        }
        scene::Node* c = out_.scene.newNode();
        slot = c;
        c->type = n->type;
        c->spec = n->spec;
        c->defName = n->defName;
        for (const scene::Field& f : n->fields) {
            scene::Field g;
            g.name = f.name;
            // VRML97's names for X3D's children (X3D 4 knows only the latter).
            if ((kind == NodeKind::Switch && f.name == "choice") ||
                (kind == NodeKind::LOD && f.name == "level"))
                g.name = "children";
            g.value.type = f.value.type;
            g.value.numbers = f.value.numbers;
            g.value.strings = f.value.strings;
            for (const Node* child : f.value.nodes)
                if (scene::Node* cc = copy(child, depth + 1)) g.value.nodes.push_back(cc);
            if (isUrlField(f)) keepLocalUrls(g, *n);
            c->fields.push_back(std::move(g));
        }
        return c;
    }

    void copyRoutes(const std::vector<scene::Route>& routes) {
        for (const scene::Route& r : routes) {
            const auto from = copies_.find(scene::effectiveNode(r.fromNode));
            const auto to = copies_.find(scene::effectiveNode(r.toNode));
            if (from == copies_.end() || to == copies_.end() || !from->second || !to->second ||
                replaced_.count(from->second) || replaced_.count(to->second)) {
                ++droppedRoutes_;
                continue;
            }
            route(from->second, r.fromField, to->second, r.toField);
        }
    }

    // Urls the page can follow without a network: files inside the scene's
    // folder (copied beside it), and an Anchor's #Viewpoint.
    void keepLocalUrls(scene::Field& f, const Node& n) {
        std::vector<std::string> kept;
        for (const std::string& url : f.value.strings) {
            if (n.kind() == NodeKind::Anchor && url.starts_with('#')) {
                kept.push_back(url);
                continue;
            }
            std::string why;
            std::optional<std::string> target;
            if (isRemote(url))
                why = "it is not a file of the scene's folder (the page needs no network)";
            else
                target = localFile(n, url, why);
            if (target)
                kept.push_back(*target);
            else
                warnOnce(src_.locationOf(n) + ": url \"" + url + "\" is left out: " + why);
        }
        f.value.strings = std::move(kept);
    }

    std::optional<std::string> localFile(const Node& n, const std::string& url, std::string& why) {
        if (!urlContext_) {
            why = "the scene was not read from a file";
            return std::nullopt;
        }
        const scene::ReferenceContext& context = *urlContext_;
        std::error_code ec;
        const std::string& nodePath = src_.pathOf(n.file);
        const std::filesystem::path base =
            nodePath.empty() ? context.root : std::filesystem::absolute(nodePath, ec).parent_path();
        const auto target = scene::resolveUrl(context, base, url, why);
        if (!target) return std::nullopt;
        const std::string relative =
            "files/" + std::filesystem::relative(target->file, context.root, ec).generic_string();
        if (ec) {
            why = ec.message();
            return std::nullopt;
        }
        if (std::none_of(out_.files.begin(), out_.files.end(),
                         [&](const BakedFile& f) { return f.target == relative; }))
            out_.files.push_back({target->file, relative});
        return relative;
    }

    // Interchange and the components beyond it that the nodes written need.
    void addComponents() {
        std::map<std::string, int> levels;
        out_.scene.forEachNode([&](const Node& n) {
            if (!n.spec) return;
            const std::string component(n.spec->component);
            const int inProfile =
                scene::profileComponentLevel(out_.scene.profile, component).value_or(0);
            if (n.spec->level > inProfile)
                levels[component] = std::max(levels[component], n.spec->level);
        });
        for (const auto& [name, level] : levels)
            out_.scene.components.push_back({name, level});
    }

    void warnOnce(const std::string& warning) {
        if (std::find(out_.warnings.begin(), out_.warnings.end(), warning) == out_.warnings.end())
            out_.warnings.push_back(warning);
    }

    const scene::Scene& src_;
    const BakeOptions& options_;
    BakeResult& out_;
    animation::Animator animator_;
    mesh::MeshCache cache_;
    std::vector<double> resolutions_; // finest first
    int frames_ = 24;
    std::unordered_map<const Node*, std::vector<const Node*>> lenders_;
    std::unordered_set<const Node*> timeReaders_;
    std::vector<Root> roots_;
    std::unordered_map<const Node*, std::size_t> index_;
    std::vector<MomentGroup> groups_;
    // Per root, per frame, per shape: its levels.
    std::vector<std::vector<std::vector<ShapeLevels>>> levels_;
    std::unordered_map<const Node*, scene::Node*> copies_;
    std::unordered_set<const scene::Node*> replaced_;
    std::vector<const Node*> instances_;
    std::vector<const scene::Scene*> inlined_;
    std::set<std::string> names_;
    std::optional<scene::ReferenceContext> urlContext_; // none: the scene came from memory
    std::size_t droppedRoutes_ = 0;
};

} // namespace

std::string_view clockBaseName(ClockBase base) {
    switch (base) {
    case ClockBase::Scene:
        return "scene";
    case ClockBase::Utc:
        return "utc";
    case ClockBase::Local:
        return "local";
    }
    return "scene";
}

std::vector<double> lodRanges(const std::vector<double>& resolutionsFinestFirst,
                              const field::Box3& box) {
    // resolutionForView is inversely proportional to the distance: find
    // the resolution at distance 1, unclamped, and divide.
    mesh::ViewForLod view;
    view.distance = 1;
    const double atOne = mesh::resolutionForView(box, view, 0, 1e300);
    std::vector<double> ranges;
    for (std::size_t i = 0; i + 1 < resolutionsFinestFirst.size(); ++i) {
        const double mean = std::sqrt(resolutionsFinestFirst[i] * resolutionsFinestFirst[i + 1]);
        ranges.push_back(atOne / std::max(mean, 1e-9));
    }
    return ranges;
}

BakeResult bakeForWeb(const scene::Scene& source, const BakeOptions& options) {
    BakeResult result;
    Baker(source, options, result).run();
    return result;
}

} // namespace fl::web
