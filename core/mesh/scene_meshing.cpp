#include "scene_meshing.h"

#include "pde/pde_mesh.h"
#include "pde_surface_shape.h"

#include "animation/clock.h"
#include "error_driven.h"
#include "function_composite.h"
#include "lent_appearance.h"
#include "mesh_topology.h"
#include "parametric.h"
#include "pde/pde_mesh.h"
#include "pde_surface_shape.h"
#include "point_cloud.h"
#include "scene/field_access.h"
#include "scene_standard_geometry.h"
#include "scene_view_nodes.h"
#include "scene_walk.h"
#include "shape_appearance.h"
#include "surface_displacement.h"
#include "touch_sensor_scope.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <unordered_set>
#include <utility>

namespace fl::mesh {
namespace {

using scene::GeometryType;
using scene::Node;
using scene::NodeKind;
using scene::SetOperation;

// The traversal: it goes down the scene at one moment, carrying the
// placement, and hands each node to the part that owns its concern — view
// nodes (scene_view_nodes), TouchSensors (touch_sensor_scope), function and
// standard shapes (here), FTransform set operations (function_composite),
// appearance (shape_appearance); lent appearances come after the walk.
class Walker {
  public:
    Walker(const SceneWalkContext& context, SceneMeshes& out)
        : context_(context), options_(context.options), scene_(context.scene),
          moment_(context.moment), out_(out), guard_(out.notes) {}

    void walk(const Node* raw, const Affine& m) {
        const Node* n = scene::effectiveNode(raw);
        const scene::WalkPath::Step step(guard_.path(), n);
        if (!n || guard_.refused(step)) return;
        // USE makes a DAG; a few dozen lines can make it exponentially large
        // when walked as a tree. Each visit counts; past the budget the rest
        // is left out, with one note.
        if (++visits_ > kMaxVisits) {
            if (!overBudget_)
                out_.notes.push_back(
                    "the scene reuses (USE) nodes so often that walking it passes " +
                    std::to_string(kMaxVisits) + " nodes; the rest is not meshed");
            overBudget_ = true;
            return;
        }
        const NodeKind kind = n->kind();
        const ShapeRootScope rootScope(*this, *n, kind);
        // Meshed in its parent's frame, a root USEd again gives the same
        // meshes: once is enough (a USE DAG can reach one root 10^5 times).
        if (rootScope.entered() && options_.meshInRootFrame && !meshedRoots_.insert(n).second)
            return;
        const Affine& entered = rootScope.entered() && options_.meshInRootFrame ? kIdentity : m;
        if (kind == NodeKind::FShape || kind == NodeKind::Shape) {
            const std::size_t first = out_.shapes.size();
            shape(*n, entered);
            senseTouches(first);
            return;
        }
        const TouchSensorScope sensors(touchSensors_, *n, moment_);
        if (collectViewNode(*n, m, moment_, out_.view)) return;
        Affine here = entered;
        if (kind == NodeKind::Transform) here = m * context_.transformOf(*n);
        if (kind == NodeKind::FTransform) {
            here = entered * context_.functionTransform(*n);
            if (context_.operationOf(*n) != SetOperation::Group) {
                const std::size_t first = out_.shapes.size();
                composite(*n, here);
                senseTouches(first);
                return;
            }
        }
        if (kind == NodeKind::Switch) {
            const auto choice = moment_.number(*n, "whichChoice", 0, -1);
            const auto children = moment_.nodes(*n, "children");
            for (std::size_t i = 0; i < children.size(); ++i)
                if (options_.everyChoice || double(i) == choice) walk(children[i], here);
            return;
        }
        if (kind == NodeKind::LOD) { // the most detailed level
            const auto levels = moment_.nodes(*n, "level");
            const auto children = moment_.nodes(*n, "children");
            const auto& shown = children.empty() ? levels : children;
            for (std::size_t i = 0; i < shown.size() && (i == 0 || options_.everyChoice); ++i)
                walk(shown[i], here);
            return;
        }
        if (n->spec && scene::findFieldSpec(*n->spec, "children"))
            for (const Node* child : moment_.nodes(*n, "children"))
                walk(child, here);
        if (n->inlined)
            for (const Node* root : n->inlined->roots)
                walk(root, here);
    }

  private:
    static inline const Affine kIdentity{};

    // The topmost shape-making node the walk is inside (SceneMeshOptions::
    // meshInRootFrame): entered by the first FShape, Shape or FTransform met
    // on the way down, left when the walk comes back up from it.
    class ShapeRootScope {
      public:
        ShapeRootScope(Walker& w, const Node& n, NodeKind kind) : w_(w) {
            if (w.root_ || (kind != NodeKind::FShape && kind != NodeKind::Shape &&
                            kind != NodeKind::FTransform))
                return;
            w.root_ = &n;
            entered_ = true;
        }
        ~ShapeRootScope() {
            if (entered_) w_.root_ = nullptr;
        }
        ShapeRootScope(const ShapeRootScope&) = delete;
        ShapeRootScope& operator=(const ShapeRootScope&) = delete;
        bool entered() const { return entered_; }

      private:
        Walker& w_;
        bool entered_ = false;
    };

    void senseTouches(std::size_t firstShape) {
        for (std::size_t i = firstShape; i < out_.shapes.size(); ++i) {
            out_.shapes[i].touchSensors = touchSensors_;
            out_.shapes[i].root = root_;
        }
    }

    std::string nameOf(const Node& n) const { return context_.nameOf(n); }
    double timeOf(const Node& n) const { return context_.timeOf(n); }
    MeshResult cached(const std::string& key, const std::function<MeshResult()>& make) const {
        return context_.cached(key, make);
    }
    void place(ShapeMesh& sm, const Affine& m) const { mesh::place(sm, m, options_); }

    void shape(const Node& n, const Affine& m) {
        const Node* geometry = scene::effectiveNode(moment_.node(n, "geometry"));
        if (!geometry) { // lends its properties to the shapes grouped with it
            if (n.kind() == scene::NodeKind::FShape) out_.lenders.push_back({&n, m.matrix()});
            return;
        }
        if (geometry->kind() == scene::NodeKind::FPdeSurface) {
            pdeShape(n, *geometry, m);
            return;
        }
        if (geometry->kind() != scene::NodeKind::FGeometry) {
            standardShape(n, *geometry, m);
            return;
        }
        const GeometryType type = context_.geometryTypeOf(*geometry);
        const formula::Tape* tape = scene_.definition(*geometry, "definition");
        ShapeMesh sm;
        sm.shape = &n;
        sm.name = nameOf(n);
        if (!tape) {
            sm.error = "the geometry has no compiled definition";
            out_.shapes.push_back(std::move(sm));
            return;
        }
        sm.geometry = geometry;
        if (moment_.flag(*geometry, "lod")) sm.levelOfDetail = geometry;
        sm.domain = domainOf(*geometry);
        // `implicit`: the surface f = 0, whichever side is positive: not closed
        // by its box, oriented by the volume it encloses (if it closes), else
        // seen from both sides. `explicit`: the FRep solid f >= 0, cut by its box.
        const bool surface = type == GeometryType::Implicit;
        auto orient = [surface](MeshResult&& made) {
            if (surface && made.ok() && !made.mesh.isPointCloud())
                made.closedSurface = orientClosedSurfaceOutward(made.mesh);
            return std::move(made);
        };
        ImplicitField field;
        field.tape = *tape;
        field.box = domainOf(*geometry);
        if (surface) field.boundary = BoxBoundary::Open;
        field.t = timeOf(*geometry);
        field.parameters = parametersFor(*tape);
        sm.t = field.t;
        sm.parameters = field.parameters;
        // A displacement texture: added to f here, or moves a parametric
        // surface along its normals once meshed.
        const Node* appearance = context_.appearanceOf(n);
        const Node* texture =
            appearance ? scene::effectiveNode(moment_.node(*appearance, "texture")) : nullptr;
        std::optional<Displacement> displacement;
        if (texture && texture->kind() == scene::NodeKind::FTexture3D)
            if (const formula::Tape* d = scene_.definition(*texture, "definition"))
                displacement = Displacement{*d, domainOf(*texture)};
        if (type != GeometryType::Parametric) field.displacement = displacement;
        MeshOptions o = options_.mesh;
        MeshResult r;
        // A point cloud instead of a mesh: asked for by the file or the caller.
        const std::size_t points =
            options_.points > 0 ? options_.points
                                : std::size_t(std::max(0.0, moment_.number(*geometry, "points")));
        PointCloudOptions pc;
        pc.count = points;
        pc.threads = o.threads;
        if (points > 0 && type != GeometryType::Parametric) {
            // An explicit (FRep) solid shows its inside; an implicit surface, itself.
            r = type == GeometryType::Explicit ? pointsInSolid(field, pc)
                                               : pointsOnSurface(field, pc);
        } else if (type == GeometryType::Parametric) {
            ParametricField pf;
            pf.tape = *tape;
            pf.t = field.t;
            pf.parameters = field.parameters;
            pf.box = field.box;
            const char* ranges[3] = {"uRange", "vRange", "wRange"};
            for (std::size_t k = 0; k < 3; ++k) {
                const auto range = moment_.numbers(*geometry, ranges[k]);
                pf.ranges[k] = {range[0], range[1]};
            }
            ParametricOptions po;
            po.resolution = options_.useFileResolution || options_.targetError > 0
                                ? moment_.number(*geometry, "resolution", 0, 32)
                                : o.resolution;
            if (auto it = options_.resolutions.find(geometry); it != options_.resolutions.end())
                po.resolution = it->second;
            sm.resolution = po.resolution;
            // A target error (a fraction of the box diagonal) is the chord
            // tolerance of the adaptive parameter lines.
            if (options_.targetError > 0) {
                po.tolerance = options_.targetError * field.box.diagonal();
                po.resolution = std::max(po.resolution, 64.0); // room to refine into
            }
            r = cached(MeshCache::keyOf(pf, po, points), [&] {
                return points > 0 ? pointsOverParameters(pf, pc) : meshParametric(pf, po);
            });
            if (options_.targetError > 0 && r.ok()) {
                sm.measuredError = r.stats.chordError / field.box.diagonal();
                if (r.stats.chordError > po.tolerance)
                    sm.warnings.push_back("the target error was not reached: chords stray " +
                                          std::to_string(sm.measuredError) +
                                          " of the box diagonal at the finest sampling");
            }
        } else if (options_.targetError > 0) {
            ErrorDrivenResult e = meshForError(field, options_.targetError, o);
            r = orient(std::move(e.result));
            sm.measuredError = e.error.max;
            if (r.ok() && !e.met)
                sm.warnings.push_back("the target error was not reached: " +
                                      std::to_string(e.error.max) + " of the box diagonal");
        } else {
            if (options_.useFileResolution)
                o.resolution = moment_.number(*geometry, "resolution", 0, 32);
            if (auto it = options_.resolutions.find(geometry); it != options_.resolutions.end())
                o.resolution = it->second;
            sm.resolution = o.resolution;
            r = cached(MeshCache::keyOf(field, o.resolution),
                       [&] { return orient(meshImplicit(field, o)); });
        }
        sm.stats = r.stats;
        sm.warnings.insert(sm.warnings.end(), r.warnings.begin(), r.warnings.end());
        sm.cancelled = r.cancelled;
        sm.error = r.cancelled ? "cancelled" : r.error;
        sm.mesh = std::move(r.mesh);
        if (type != GeometryType::Parametric) {
            sm.field = std::make_shared<const ImplicitField>(field);
            sm.texts = {{geometry, "definition"}};
        }
        if (type == GeometryType::Parametric && displacement && !sm.mesh.empty() &&
            !sm.mesh.isPointCloud()) {
            const auto w =
                displaceAlongNormals(sm.mesh, *displacement, field.box, timeOf(*texture));
            sm.warnings.insert(sm.warnings.end(), w.begin(), w.end());
        }
        colour(context_, appearance, field.box, sm);
        sm.look = lookOf(context_, appearance, n.kind() == NodeKind::FShape);
        sm.appearance = appearance;
        if (surface && !sm.mesh.isPointCloud()) sm.look.solid = r.closedSurface;
        // A parametric surface has two sides and no inside: both are drawn.
        // (Curves become closed tubes and solids their closed boundary.)
        if (type == GeometryType::Parametric) {
            int used = 0;
            for (formula::Input in : {formula::Input::U, formula::Input::V, formula::Input::W})
                used += tape->usesInput[std::size_t(in)] ? 1 : 0;
            sm.look.solid = used != 2;
        }
        place(sm, m);
        out_.shapes.push_back(std::move(sm));
    }

    // The parameter values asked for that this definition has (only those,
    // so the cache key does not change with unrelated sliders).
    std::vector<std::pair<std::string, double>> parametersFor(const formula::Tape& tape) const {
        std::vector<std::pair<std::string, double>> out;
        for (const auto& [name, value] : options_.parameters)
            for (const formula::ParameterInfo& p : tape.params)
                if (p.name == name) out.emplace_back(name, value);
        return out;
    }

    // Box, Sphere, IndexedFaceSet ... under a Shape or an FShape.
    // A PDE model (FPdeSurface): its patches on a (u, v) grid, the grid set
    // by `resolution` (or the level of detail), coloured like a parametric
    // shape (FMaterial formulas read u and v), touched as polygons.
    void pdeShape(const Node& n, const Node& geometry, const Affine& m) {
        ShapeMesh sm;
        sm.shape = &n;
        sm.name = nameOf(n);
        sm.geometry = &geometry;
        sm.functionGeometry = true; // FunctionLab's own: other browsers get a preview
        const PdeSurfaceModel loaded =
            pdeSurfaceModel(scene_, geometry, moment_.strings(geometry, "url"));
        if (!loaded.model) {
            sm.error = "FPdeSurface url: " + loaded.error;
            out_.shapes.push_back(std::move(sm));
            return;
        }
        sm.pdeModel = loaded.model;
        double resolution = moment_.number(geometry, "resolution", 0, 32);
        if (!options_.useFileResolution && options_.mesh.resolution > 0)
            resolution = options_.mesh.resolution;
        if (auto it = options_.resolutions.find(&geometry); it != options_.resolutions.end())
            resolution = it->second;
        sm.resolution = resolution;
        if (moment_.flag(geometry, "lod")) sm.levelOfDetail = &geometry;
        sm.domain = field::Box3{loaded.model->lo, loaded.model->hi};
        const pde::BoundedGrid bounded =
            pde::boundedGrid(*loaded.model, pde::meshOptionsFor(resolution));
        if (!bounded.fits) {
            sm.error = "FPdeSurface: the model has " +
                       std::to_string(loaded.model->patches.size()) +
                       " patches, more than a scene meshes (" +
                       std::to_string(std::llround(pde::MeshOptions{}.maxCells / 3)) + " at most)";
            out_.shapes.push_back(std::move(sm));
            return;
        }
        if (bounded.reduced)
            sm.warnings.push_back("FPdeSurface: meshed at " +
                                  std::to_string(bounded.options.stepsU) + " x " +
                                  std::to_string(bounded.options.stepsV) +
                                  " a patch, coarser than asked: the model has " +
                                  std::to_string(loaded.model->patches.size()) + " patches");
        const pde::MeshOptions grid = bounded.options;
        MeshResult r = cached("pde|" + loaded.file + "|" + std::to_string(grid.stepsU) + "x" +
                                  std::to_string(grid.stepsV),
                              [&] {
                                  MeshResult made;
                                  made.mesh = pde::meshModel(*loaded.model, grid);
                                  return made;
                              });
        sm.mesh = std::move(r.mesh);
        const Node* appearance = context_.appearanceOf(n);
        sm.look = lookOf(context_, appearance, n.kind() == NodeKind::FShape);
        sm.appearance = appearance;
        colour(context_, appearance, colourBoxOf(sm.mesh), sm);
        place(sm, m);
        out_.shapes.push_back(std::move(sm));
    }

    void standardShape(const Node& n, const Node& geometry, const Affine& m) {
        if (!options_.standardShapes) {
            out_.notes.push_back(nameOf(n) + ": standard geometry " + geometry.type +
                                 " is left to the viewer");
            return;
        }
        StandardGeometryResult r = tessellated(geometry);
        if (!r.unsupported.empty()) {
            out_.notes.push_back(nameOf(n) + ": " + r.unsupported);
            return;
        }
        ShapeMesh sm;
        sm.shape = &n;
        sm.name = nameOf(n);
        sm.functionGeometry = false;
        sm.mesh = std::move(r.mesh);
        sm.warnings = std::move(r.warnings);
        const Node* appearance = context_.appearanceOf(n);
        sm.look = lookOf(context_, appearance, n.kind() == NodeKind::FShape);
        sm.appearance = appearance;
        sm.look.solid = r.solid;
        sm.look.texture =
            sm.mesh.texCoords.empty() ? std::nullopt : textureOf(scene_, appearance, sm.warnings);
        if (sm.look.texture)
            applyTextureTransform(appearance, sm.mesh);
        else
            sm.mesh.texCoords.clear(); // nothing reads them
        if (sm.mesh.isLines() && sm.mesh.colours.empty()) {
            // X3D lines take the Material's emissive colour (white without one).
            const Node* material = context_.materialOf(appearance);
            const auto e =
                material ? moment_.numbers(*material, "emissiveColor") : std::vector<double>{};
            const std::array<float, 4> c =
                e.size() == 3 ? std::array<float, 4>{float(e[0]), float(e[1]), float(e[2]), 1}
                              : std::array<float, 4>{1, 1, 1, 1};
            sm.mesh.colours.assign(sm.mesh.vertexCount(), c);
        } else if (sm.mesh.colours.empty()) {
            // FMaterial functions see the shape's own coordinates, its bounds as the box.
            colour(context_, appearance, colourBoxOf(sm.mesh), sm);
        } else if (const Node* material = context_.materialOf(appearance)) {
            // A Color node replaces the diffuse colour; the material's transparency stays.
            const float alpha = float(1 - moment_.number(*material, "transparency"));
            for (auto& c : sm.mesh.colours)
                c[3] *= alpha;
        }
        place(sm, m);
        out_.shapes.push_back(std::move(sm));
    }

    // A standard geometry's triangles at this moment. Where no event has set
    // a value of the geometry or of a node it holds (Coordinate, Color ...),
    // they are the file's at every moment: kept in the cache, so a Box under
    // a Transform an interpolator turns is tessellated once, and each frame
    // only moves its matrix (the effects plan's `transform`).
    StandardGeometryResult tessellated(const Node& geometry) const {
        auto make = [&] {
            return standardGeometryMesh(geometry, options_.segments, options_.text, moment_);
        };
        if (!options_.cache || setByEvents(geometry, 0)) return make();
        const std::string key = "standard " + std::to_string(scene_.serial.value()) + " " +
                                std::to_string(reinterpret_cast<std::uintptr_t>(&geometry)) + " " +
                                std::to_string(options_.segments) + (options_.text ? " text" : "");
        const auto kept = options_.cache->get(key, [&] {
            StandardGeometryResult made = make();
            MeshResult r;
            r.mesh = std::move(made.mesh);
            r.warnings = std::move(made.warnings);
            r.error = std::move(made.unsupported);
            return r;
        });
        StandardGeometryResult r;
        r.mesh = kept->mesh;
        r.warnings = kept->warnings;
        r.unsupported = kept->error;
        r.solid = standardGeometryIsSolid(geometry, moment_);
        return r;
    }

    // Whether an event has set a field of `node` or of a node below it.
    bool setByEvents(const Node& node, int depth) const {
        if (moment_.holdsEventValues(node)) return true;
        if (depth > 16) return true; // deeper than any geometry: do not keep
        for (const scene::Field& f : node.fields)
            for (const Node* child : f.value.nodes)
                if (const Node* c = scene::effectiveNode(child); c && setByEvents(*c, depth + 1))
                    return true;
        return false;
    }

    // An FTransform whose children are combined into one shape.
    void composite(const Node& ft, const Affine& m) {
        std::optional<ComposedShape> composed =
            composeFunctionTransform(context_, guard_, ft, out_.notes);
        if (!composed) return;
        ShapeMesh sm;
        sm.shape = &ft;
        sm.name = nameOf(ft);
        ImplicitField& field = composed->field;
        if (!field.box.valid()) {
            sm.error = "the children's boxes do not overlap: the " +
                       moment_.string(ft, "operation") + " is empty";
            out_.shapes.push_back(std::move(sm));
            return;
        }
        MeshOptions o = options_.mesh;
        MeshResult r;
        if (options_.targetError > 0) {
            ErrorDrivenResult e = meshForError(field, options_.targetError, o);
            r = std::move(e.result);
            sm.measuredError = e.error.max;
        } else {
            if (options_.useFileResolution) o.resolution = composed->resolution;
            // The viewer's level of detail keys a combined shape by its FTransform.
            if (auto it = options_.resolutions.find(&ft); it != options_.resolutions.end())
                o.resolution = it->second;
            sm.resolution = o.resolution;
            r = cached(MeshCache::keyOf(field, o.resolution),
                       [&] { return meshImplicit(field, o); });
        }
        sm.stats = r.stats;
        sm.warnings = r.warnings;
        sm.cancelled = r.cancelled;
        sm.error = r.cancelled ? "cancelled" : r.error;
        sm.mesh = std::move(r.mesh);
        sm.field = std::make_shared<const ImplicitField>(std::move(field));
        sm.texts = std::move(composed->texts);
        colour(context_, composed->appearance, sm.field->box, sm);
        sm.look = lookOf(context_, composed->appearance, true);
        sm.appearance = composed->appearance;
        sm.levelOfDetail = composed->levelOfDetail;
        place(sm, m);
        out_.shapes.push_back(std::move(sm));
    }

    const SceneWalkContext& context_;
    const SceneMeshOptions& options_;
    const scene::Scene& scene_;
    const animation::Animator& moment_; // the one clock at the moment meshed
    SceneMeshes& out_;
    WalkGuard guard_;
    std::vector<const Node*> touchSensors_; // of the lowest group the walk is inside that has any
    const Node* root_ = nullptr;            // see ShapeRootScope
    std::unordered_set<const Node*> meshedRoots_; // meshInRootFrame: each root once
    static constexpr std::size_t kMaxVisits = 200000;
    std::size_t visits_ = 0;
    bool overBudget_ = false;
};

} // namespace

Box3 domainOf(const scene::Node& node) {
    const auto lo = scene::numbersField(node, "domainMin"),
               hi = scene::numbersField(node, "domainMax");
    if (lo.size() != 3 || hi.size() != 3) return {};
    return {{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}};
}

Box3 pointBounds(const std::vector<Vec3f>& points, Box3 box) {
    for (const Vec3f& p : points)
        for (std::size_t k = 0; k < 3; ++k) {
            box.lo[k] = std::min(box.lo[k], double(p[k]));
            box.hi[k] = std::max(box.hi[k], double(p[k]));
        }
    return box;
}

std::optional<field::Vec3> shapeCoordinates(const ShapeMesh& shape, const field::Vec3& point) {
    const auto back = field::Affine::fromMatrix(shape.placement).inverse();
    if (!back) return std::nullopt;
    return back->point(point);
}

std::optional<Box3> boundingBoxOf(const scene::Node& node) {
    const auto centre = scene::numbersField(node, "bboxCenter");
    const auto size = scene::numbersField(node, "bboxSize");
    if (centre.size() != 3 || size.size() != 3 || !(size[0] > 0 && size[1] > 0 && size[2] > 0))
        return std::nullopt;
    return Box3{{centre[0] - size[0] / 2, centre[1] - size[1] / 2, centre[2] - size[2] / 2},
                {centre[0] + size[0] / 2, centre[1] + size[1] / 2, centre[2] + size[2] / 2}};
}

animation::Instant momentOf(const SceneMeshOptions& options) {
    const std::int64_t seconds = animation::secondsToNanoseconds(options.sceneSeconds);
    return options.instant.value_or(animation::Instant{seconds, seconds, 0});
}

SceneMeshes meshScene(const scene::Scene& scene, const SceneMeshOptions& options) {
    SceneMeshes out;
    // Without the caller's clock, the moment is replayed from the start: one
    // tick at it, as every other cold reader of the same moment does.
    std::unique_ptr<animation::Animator> own;
    if (!options.animator) {
        own = std::make_unique<animation::Animator>(scene);
        own->tick(momentOf(options));
    }
    const SceneWalkContext context{scene, options, options.animator ? *options.animator : *own};
    Walker walker(context, out);
    for (const Node* root : scene.roots)
        walker.walk(root, {});
    lendAppearances(context, out);
    return out;
}

std::vector<formula::ParameterInfo> sceneParameters(const scene::Scene& scene) {
    std::vector<formula::ParameterInfo> out;
    for (const scene::Scene* shown : scene::scenesShownBy(scene))
        for (const scene::CompiledDefinition& d : shown->definitions)
            for (const formula::ParameterInfo& p : d.tape->params)
                if (std::none_of(out.begin(), out.end(),
                                 [&](const formula::ParameterInfo& q) { return q.name == p.name; }))
                    out.push_back(p);
    return out;
}

namespace {
// An alpha that rounds to nothing in an 8-bit framebuffer.
constexpr float kInvisibleAlpha = 0.5f / 255.0f;
} // namespace

bool isDrawnTriangle(const Mesh& mesh, const Triangle& t) {
    if (mesh.colours.size() != mesh.positions.size()) return true; // no colours: opaque grey
    for (std::uint32_t i : t)
        if (i < mesh.colours.size() && mesh.colours[i][3] > kInvisibleAlpha) return true;
    return false;
}

bool isDrawn(const ShapeMesh& shape) {
    const Mesh& m = shape.mesh;
    if (m.colours.size() != m.positions.size() || m.colours.empty()) return true;
    return std::any_of(m.colours.begin(), m.colours.end(),
                       [](const auto& c) { return c[3] > kInvisibleAlpha; });
}

Mesh mergeMeshes(const std::vector<ShapeMesh>& shapes, Primitive primitive) {
    Mesh all;
    all.primitive = primitive;
    for (const ShapeMesh& s : shapes) {
        if (s.mesh.primitive != primitive) continue;
        const auto base = std::uint32_t(all.positions.size());
        all.positions.insert(all.positions.end(), s.mesh.positions.begin(), s.mesh.positions.end());
        all.normals.insert(all.normals.end(), s.mesh.normals.begin(), s.mesh.normals.end());
        // Colours: a shape without them is shown in the default grey.
        if (!s.mesh.colours.empty() || !all.colours.empty()) {
            all.colours.resize(base, {0.8f, 0.8f, 0.8f, 1.0f});
            if (s.mesh.colours.size() == s.mesh.positions.size())
                all.colours.insert(all.colours.end(), s.mesh.colours.begin(), s.mesh.colours.end());
            else
                all.colours.resize(all.positions.size(), {0.8f, 0.8f, 0.8f, 1.0f});
        }
        for (Triangle t : s.mesh.triangles) {
            for (auto& i : t)
                i += base;
            all.triangles.push_back(t);
        }
        for (Segment g : s.mesh.segments) {
            for (auto& i : g)
                i += base;
            all.segments.push_back(g);
        }
    }
    return all;
}

} // namespace fl::mesh
