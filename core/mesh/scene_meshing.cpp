#include "scene_meshing.h"

#include "animation/clock.h"
#include "colouring.h"
#include "error_driven.h"
#include "formula/eval_scalar.h"
#include "formula/tape_builder.h"
#include "formula/tape_compose.h"
#include "mesh_topology.h"
#include "parametric.h"
#include "point_cloud.h"
#include "scene/effects_plan.h"
#include "scene/field_access.h"
#include "scene/function_kinds.h"
#include "scene/node_graph.h"
#include "scene_standard_geometry.h"
#include "surface_displacement.h"

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
using scene::SetOperation;

// X3D Transform: T * C * R * SR * S * -SR * -C, with the moment's values.
Affine transformOf(const Node& n, const scene::FieldSource& fields) {
    const auto t = fields.numbers(n, "translation"), c = fields.numbers(n, "center"),
               s = fields.numbers(n, "scale");
    const auto r = fields.numbers(n, "rotation"), sr = fields.numbers(n, "scaleOrientation");
    Affine srInverse = Affine::rotate(sr);
    if (sr.size() == 4) srInverse = Affine::rotate(sr[0], sr[1], sr[2], -sr[3]);
    return Affine::translate(t[0], t[1], t[2]) * Affine::translate(c[0], c[1], c[2]) *
           Affine::rotate(r) * Affine::rotate(sr) * Affine::scale(s[0], s[1], s[2]) * srInverse *
           Affine::translate(-c[0], -c[1], -c[2]);
}

// Coordinate k of `map` applied to the local coordinates, written with no
// term that is zero and no factor that is one: an identity or axis-aligned
// placement gives exactly `x`, as in one formula. (0 * x and t + 0 are not
// folded by the tape builder, rightly for arbitrary values; here the
// coordinates are finite. Each such step would widen an interval by an ulp,
// and a face lying on a cell boundary — box(0.5, …) in [-1, 1] — would never
// be proven on one side.)
formula::Val affineCoordinate(formula::TapeBuilder& b, const Affine& map, int k,
                              const std::array<formula::Val, formula::kInputCount>& local) {
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

class Walker {
  public:
    Walker(const scene::Scene& scene, const SceneMeshOptions& options, SceneMeshes& out,
           const animation::Animator& moment)
        : scene_(scene), options_(options), out_(out), moment_(moment) {}

    void walk(const Node* raw, const Affine& m) {
        const Node* n = scene::effectiveNode(raw);
        const scene::WalkPath::Step step(path_, n);
        if (!n || refused(step)) return;
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
        const scene::NodeKind kind = n->kind();
        if (kind == scene::NodeKind::FShape || kind == scene::NodeKind::Shape) {
            const std::size_t first = out_.shapes.size();
            shape(*n, m);
            senseTouches(first);
            return;
        }
        const SensorScope sensors(*this, *n);
        if (viewNode(*n, m)) return;
        Affine here = m;
        if (kind == scene::NodeKind::Transform) here = m * transformOf(*n, moment_);
        if (kind == scene::NodeKind::FTransform) {
            here = m * functionTransform(*n);
            if (operationOf(*n) != SetOperation::Group) {
                const std::size_t first = out_.shapes.size();
                composite(*n, here);
                senseTouches(first);
                return;
            }
        }
        if (kind == scene::NodeKind::Switch) {
            const auto choice = moment_.number(*n, "whichChoice", 0, -1);
            const auto children = moment_.nodes(*n, "children");
            if (choice >= 0 && choice < double(children.size()))
                walk(children[std::size_t(choice)], here);
            return;
        }
        if (kind == scene::NodeKind::LOD) { // the most detailed level
            const auto levels = moment_.nodes(*n, "level");
            const auto children = moment_.nodes(*n, "children");
            if (!children.empty())
                walk(children.front(), here);
            else if (!levels.empty())
                walk(levels.front(), here);
            return;
        }
        for (const char* field : {"children"})
            if (n->spec && scene::findFieldSpec(*n->spec, field))
                for (const Node* child : moment_.nodes(*n, field))
                    walk(child, here);
        if (n->inlined)
            for (const Node* root : n->inlined->roots)
                walk(root, here);
    }

  private:
    // The TouchSensors among a group's children sense every shape below it
    // while the walk is inside that group; the lowest group with any shadows
    // those above it (X3D 19775-1 §20.2.1: the lowest sensors are activated).
    struct SensorScope {
        SensorScope(Walker& w, const Node& group) : walker(w) {
            if (!group.spec || !scene::findFieldSpec(*group.spec, "children")) return;
            std::vector<const Node*> here;
            for (const Node* child : w.moment_.nodes(group, "children")) {
                const Node* sensor = scene::effectiveNode(child);
                if (sensor && sensor->kind() == scene::NodeKind::TouchSensor &&
                    w.moment_.flag(*sensor, "enabled"))
                    here.push_back(sensor);
            }
            if (here.empty()) return;
            outer = std::exchange(w.touchSensors_, std::move(here));
            shadowing = true;
        }
        ~SensorScope() {
            if (shadowing) walker.touchSensors_ = std::move(outer);
        }
        SensorScope(const SensorScope&) = delete;
        SensorScope& operator=(const SensorScope&) = delete;
        Walker& walker;
        std::vector<const Node*> outer;
        bool shadowing = false;
    };

    void senseTouches(std::size_t firstShape) {
        for (std::size_t i = firstShape; i < out_.shapes.size(); ++i)
            out_.shapes[i].touchSensors = touchSensors_;
    }

    static std::array<double, 3> apply(const Affine& m, const std::vector<double>& p) {
        std::array<double, 3> out{};
        for (int k = 0; k < 3; ++k)
            out[std::size_t(k)] = m.m[k][0] * p[0] + m.m[k][1] * p[1] + m.m[k][2] * p[2] + m.t[k];
        return out;
    }
    static std::array<double, 3> turn(const Affine& m, const std::array<double, 3>& d) {
        std::array<double, 3> out{};
        for (int k = 0; k < 3; ++k)
            out[std::size_t(k)] = m.m[k][0] * d[0] + m.m[k][1] * d[1] + m.m[k][2] * d[2];
        const double n = std::sqrt(out[0] * out[0] + out[1] * out[1] + out[2] * out[2]);
        if (n > 0)
            for (double& v : out)
                v /= n;
        return out;
    }

    // Lights, viewpoints, Background and NavigationInfo, in scene
    // coordinates. Returns whether `n` was one of them.
    bool viewNode(const Node& n, const Affine& m) {
        SceneView& view = out_.view;
        const scene::NodeKind kind = n.kind();
        auto rgb = [&](const char* field, std::array<float, 3>& out) {
            const auto v = moment_.numbers(n, field);
            if (v.size() >= 3) out = {float(v[0]), float(v[1]), float(v[2])};
        };
        if (kind == scene::NodeKind::DirectionalLight || kind == scene::NodeKind::PointLight ||
            kind == scene::NodeKind::SpotLight) {
            if (!moment_.flag(n, "on")) return true;
            ViewLight l;
            l.kind = kind == scene::NodeKind::DirectionalLight ? ViewLight::Kind::Directional
                     : kind == scene::NodeKind::PointLight     ? ViewLight::Kind::Point
                                                               : ViewLight::Kind::Spot;
            rgb("color", l.colour);
            l.intensity = float(moment_.number(n, "intensity", 0, 1));
            l.ambientIntensity = float(moment_.number(n, "ambientIntensity"));
            if (l.kind != ViewLight::Kind::Point) {
                const auto d = moment_.numbers(n, "direction");
                if (d.size() == 3) l.direction = turn(m, {d[0], d[1], d[2]});
            }
            if (l.kind != ViewLight::Kind::Directional) {
                const auto p = moment_.numbers(n, "location");
                if (p.size() == 3) l.location = apply(m, p);
                const auto a = moment_.numbers(n, "attenuation");
                if (a.size() == 3) l.attenuation = {float(a[0]), float(a[1]), float(a[2])};
                l.radius = moment_.number(n, "radius", 0, 100);
            }
            if (l.kind == ViewLight::Kind::Spot) {
                l.beamWidth = moment_.number(n, "beamWidth", 0, l.beamWidth);
                l.cutOffAngle = moment_.number(n, "cutOffAngle", 0, l.cutOffAngle);
            }
            view.lights.push_back(l);
            return true;
        }
        if (kind == scene::NodeKind::Viewpoint || kind == scene::NodeKind::OrthoViewpoint) {
            ViewPoint v;
            v.name = moment_.string(n, "description");
            if (v.name.empty()) v.name = n.defName;
            if (v.name.empty()) v.name = "Viewpoint " + std::to_string(view.viewpoints.size() + 1);
            const auto p = moment_.numbers(n, "position");
            if (p.size() == 3) v.position = apply(m, p);
            const Affine frame = m * Affine::rotate(moment_.numbers(n, "orientation"));
            v.direction = turn(frame, {0, 0, -1});
            v.up = turn(frame, {0, 1, 0});
            const auto c = moment_.numbers(n, "centerOfRotation");
            if (c.size() == 3) v.centerOfRotation = apply(m, c);
            if (kind == scene::NodeKind::Viewpoint)
                v.fieldOfView = moment_.number(n, "fieldOfView", 0, v.fieldOfView);
            // The first is bound at load; a set_bind event binds another.
            if (view.viewpoints.empty() || moment_.flag(n, "isBound"))
                view.boundViewpoint = int(view.viewpoints.size());
            view.viewpoints.push_back(v);
            return true;
        }
        // Backgrounds and NavigationInfos: the first, unless an event bound another.
        if (kind == scene::NodeKind::Background || kind == scene::NodeKind::TextureBackground) {
            if (!view.hasBackground || moment_.flag(n, "isBound")) {
                rgb("skyColor", view.background);
                view.hasBackground = true;
            }
            return true;
        }
        if (kind == scene::NodeKind::NavigationInfo) {
            if (!view.hasNavigation || moment_.flag(n, "isBound")) {
                view.navigation.types = moment_.strings(n, "type");
                view.navigation.headlight = moment_.flag(n, "headlight");
                view.navigation.speed = moment_.number(n, "speed", 0, 1);
                const auto a = moment_.numbers(n, "avatarSize");
                for (std::size_t i = 0; i < 3 && i < a.size(); ++i)
                    view.navigation.avatarSize[i] = a[i];
                view.hasNavigation = true;
            }
            return true;
        }
        return false;
    }

    // An unknown word was reported by the reader: such a shape is drawn as a solid.
    GeometryType geometryTypeOf(const Node& geometry) const {
        return scene::geometryTypeNamed(moment_.string(geometry, "type"))
            .value_or(GeometryType::Explicit);
    }

    // None for a word the reader reported: the first child is shown.
    std::optional<SetOperation> operationOf(const Node& ft) const {
        return scene::setOperationNamed(moment_.string(ft, "operation"));
    }

    std::string nameOf(const Node& n) const {
        return n.type + (n.defName.empty() ? "" : " " + n.defName) + " (" + scene_.locationOf(n) +
               ")";
    }

    // The node's t at the moment asked for: the one clock's answer.
    double timeOf(const Node& n) const { return moment_.time(n); }

    // translation, rotationAngle about rotationAxis and scale as functions of t, about center.
    Affine functionTransform(const Node& n) {
        const double t = timeOf(n);
        auto outputs = [&](const char* field, std::vector<double> fallback) {
            const formula::Tape* tape = scene_.definition(n, field);
            if (!tape) return fallback;
            formula::ScalarEvaluator e(*tape);
            std::vector<double> values(tape->outputs.size());
            e.evaluateAll({0, 0, 0, t, 0, 0, 0}, values.data());
            return values;
        };
        const auto tr = outputs("translation", {0, 0, 0});
        const auto angle = outputs("rotationAngle", {0});
        const auto sc = outputs("scale", {1, 1, 1});
        const auto axis = moment_.numbers(n, "rotationAxis"), c = moment_.numbers(n, "center");
        if (tr.size() < 3 || sc.size() < 3 || angle.empty()) return {};
        return Affine::translate(tr[0], tr[1], tr[2]) * Affine::translate(c[0], c[1], c[2]) *
               Affine::rotate(axis[0], axis[1], axis[2], angle[0]) *
               Affine::scale(sc[0], sc[1], sc[2]) * Affine::translate(-c[0], -c[1], -c[2]);
    }

    void shape(const Node& n, const Affine& m) {
        const Node* geometry = scene::effectiveNode(moment_.node(n, "geometry"));
        if (!geometry) { // lends its properties to the shapes grouped with it
            if (n.kind() == scene::NodeKind::FShape) out_.lenders.push_back({&n, m.matrix()});
            return;
        }
        if (geometry->kind() != scene::NodeKind::FGeometry) {
            standardShape(n, *geometry, m);
            return;
        }
        const GeometryType type = geometryTypeOf(*geometry);
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
        const Node* appearance = scene::effectiveNode(moment_.node(n, "appearance"));
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
        colour(appearance, field.box, sm);
        sm.look = lookOf(appearance, n.kind() == scene::NodeKind::FShape);
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

    // A mesh from the cache when there is one (a copy: colours and placement
    // are applied to it afterwards), else made now.
    MeshResult cached(const std::string& key, const std::function<MeshResult()>& make) const {
        if (!options_.cache) return make();
        return *options_.cache->get(key, make);
    }

    // Box, Sphere, IndexedFaceSet ... under a Shape or an FShape.
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
        const Node* appearance = scene::effectiveNode(moment_.node(n, "appearance"));
        sm.look = lookOf(appearance, n.kind() == scene::NodeKind::FShape);
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
            const Node* material = materialOf(appearance);
            const auto e =
                material ? moment_.numbers(*material, "emissiveColor") : std::vector<double>{};
            const std::array<float, 4> c =
                e.size() == 3 ? std::array<float, 4>{float(e[0]), float(e[1]), float(e[2]), 1}
                              : std::array<float, 4>{1, 1, 1, 1};
            sm.mesh.colours.assign(sm.mesh.vertexCount(), c);
        } else if (sm.mesh.colours.empty()) {
            // FMaterial functions see the shape's own coordinates, its bounds as the box.
            colour(appearance, boundsOf(sm.mesh), sm);
        } else if (const Node* material = materialOf(appearance)) {
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

    const Node* materialOf(const Node* appearance) const {
        return appearance ? scene::effectiveNode(moment_.node(*appearance, "material")) : nullptr;
    }

    static Box3 boundsOf(const Mesh& m) {
        if (m.positions.empty()) return {};
        Box3 b = pointBounds(m.positions);
        for (std::size_t k = 0; k < 3; ++k) // a flat shape still has a box
            if (!(b.hi[k] > b.lo[k])) b.lo[k] -= 0.5, b.hi[k] += 0.5;
        return b;
    }

    // The constant light terms of the appearance's Material or FMaterial.
    SurfaceLook lookOf(const Node* appearance, bool functionShape) const {
        SurfaceLook look;
        const Node* material = materialOf(appearance);
        if (!material) {
            look.lit = functionShape;
            return look;
        }
        auto rgb = [&](const char* field, std::array<float, 3>& out) {
            const auto v = moment_.numbers(*material, field);
            if (v.size() == 3) out = {float(v[0]), float(v[1]), float(v[2])};
        };
        rgb("emissiveColor", look.emissive);
        rgb("specularColor", look.specular);
        look.shininess = float(moment_.number(*material, "shininess", 0, 0.2));
        look.ambientIntensity = float(moment_.number(*material, "ambientIntensity", 0, 0.2));
        return look;
    }

    // One function for a subtree of an FTransform that combines its children.
    struct Piece {
        formula::Val f;
        Box3 box;                         // in the FTransform's local coordinates
        const Node* appearance = nullptr; // of the first FShape in it
        double resolution = 0;
        // The first FGeometry in it drawn with lod TRUE: a combined shape is
        // drawn with its level of detail (ShapeMesh::levelOfDetail).
        const Node* levelOfDetail = nullptr;
    };

    // The pieces under `raw`, whose coordinates are `toLocal` of the
    // combining FTransform's.
    void collect(const Node* raw, const Affine& toLocal, formula::TapeBuilder& b,
                 const std::array<formula::Val, formula::kInputCount>& local,
                 std::vector<Piece>& out) {
        const Node* n = scene::effectiveNode(raw);
        const scene::WalkPath::Step step(path_, n);
        if (!n || refused(step)) return;
        if (n->kind() == scene::NodeKind::FShape) {
            const Node* geometry = scene::effectiveNode(moment_.node(*n, "geometry"));
            if (!geometry || geometry->kind() != scene::NodeKind::FGeometry ||
                geometryTypeOf(*geometry) == GeometryType::Parametric) {
                out_.notes.push_back(nameOf(*n) +
                                     ": only implicit and explicit geometry takes part in "
                                     "an FTransform's set operation; left out");
                return;
            }
            const formula::Tape* tape = scene_.definition(*geometry, "definition");
            if (!tape) return;
            // The child's own coordinates, from the local ones.
            // A singular map (a zero scale) flattens the child to nothing.
            const std::optional<Affine> inverse = toLocal.inverse();
            if (!inverse) return;
            const Affine& back = *inverse;
            std::array<formula::Val, formula::kInputCount> in = local;
            for (int k = 0; k < 3; ++k)
                in[std::size_t(k)] = affineCoordinate(b, back, k, local);
            in[std::size_t(formula::Input::T)] = formula::Val::constant(timeOf(*geometry));
            formula::Val f = formula::inlineTape(b, *tape, in, std::vector<double>{},
                                                 textTag(*geometry, "definition"))[0];
            // Nothing of the child exists outside its box.
            formula::SourceRange boxText;
            boxText.source = textTag(*geometry, "domainMin");
            b.setOrigin(boxText);
            const Box3 box = domainOf(*geometry);
            for (std::size_t k = 0; k < 3; ++k) {
                f = b.min(f, b.sub(in[k], formula::Val::constant(box.lo[k])));
                f = b.min(f, b.sub(formula::Val::constant(box.hi[k]), in[k]));
            }
            out.push_back({f, field::boundsOf(box, toLocal),
                           scene::effectiveNode(moment_.node(*n, "appearance")),
                           moment_.number(*geometry, "resolution", 0, 32),
                           moment_.flag(*geometry, "lod") ? geometry : nullptr});
            return;
        }
        if (n->kind() == scene::NodeKind::Transform || n->kind() == scene::NodeKind::FTransform) {
            const Affine inner =
                toLocal * (n->kind() == scene::NodeKind::Transform ? transformOf(*n, moment_)
                                                                   : functionTransform(*n));
            std::vector<Piece> pieces;
            for (const Node* child : moment_.nodes(*n, "children"))
                collect(child, inner, b, local, pieces);
            if (n->kind() == scene::NodeKind::FTransform &&
                operationOf(*n) != SetOperation::Group && !pieces.empty()) {
                out.push_back(combine(*n, pieces, b, local));
                return;
            }
            out.insert(out.end(), pieces.begin(), pieces.end());
            return;
        }
        if (n->spec && scene::findFieldSpec(*n->spec, "children"))
            for (const Node* child : moment_.nodes(*n, "children"))
                collect(child, toLocal, b, local, out);
    }

    Piece combine(const Node& ft, const std::vector<Piece>& pieces, formula::TapeBuilder& b,
                  const std::array<formula::Val, formula::kInputCount>& local) {
        const std::optional<SetOperation> op = operationOf(ft);
        // The combining instructions are the FTransform's `operation`.
        formula::SourceRange here;
        here.source = textTag(ft, "operation");
        b.setOrigin(here);
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
        const double t = timeOf(ft);
        if (op == SetOperation::Union) {
            for (std::size_t i = 1; i < pieces.size(); ++i)
                r.f = b.max(r.f, pieces[i].f);
        } else if (op == SetOperation::Intersection) {
            for (std::size_t i = 1; i < pieces.size(); ++i)
                r.f = b.min(r.f, pieces[i].f);
        } else if (op == SetOperation::Difference) { // the first child minus the others
            for (std::size_t i = 1; i < pieces.size(); ++i)
                r.f = b.min(r.f, b.neg(pieces[i].f));
        } else if (op == SetOperation::Morph) {
            double s = 0;
            if (const formula::Tape* tape = scene_.definition(ft, "morphFactor")) {
                formula::ScalarEvaluator e(*tape);
                s = e.evaluate({0, 0, 0, t, 0, 0, 0});
            }
            if (pieces.size() >= 2 && std::isfinite(s))
                r.f = b.add(b.mul(formula::Val::constant(1 - s), pieces[0].f),
                            b.mul(formula::Val::constant(s), pieces[1].f));
        } else if (op == SetOperation::Formula) {
            if (const formula::Tape* tape = scene_.definition(ft, "operationDefinition")) {
                std::vector<formula::Val> values;
                for (const formula::ParameterInfo& p : tape->params) {
                    // f1, f2, ... are the children in order; a missing one reads 0.
                    const std::size_t i = std::size_t(std::atoi(p.name.c_str() + 1)) - 1;
                    values.push_back(i < pieces.size() ? pieces[i].f : formula::Val::constant(0));
                }
                auto in = local;
                in[std::size_t(formula::Input::T)] = formula::Val::constant(t);
                r.f = formula::inlineTape(b, *tape, in, values,
                                          textTag(ft, "operationDefinition"))[0];
            }
        }
        return r;
    }

    // The number of a text a composed tape's instructions come from
    // (SourceRange::source, ShapeMesh::texts).
    int textTag(const Node& node, const char* field) {
        for (std::size_t i = 0; i < texts_.size(); ++i)
            if (texts_[i].node == &node && texts_[i].field == field) return int(i);
        texts_.push_back({&node, field});
        return int(texts_.size()) - 1;
    }

    // An FTransform whose children are combined into one shape.
    void composite(const Node& ft, const Affine& m) {
        texts_.clear();
        formula::TapeBuilder b;
        std::array<formula::Val, formula::kInputCount> local{};
        for (int i = 0; i < formula::kInputCount; ++i)
            local[std::size_t(i)] = b.input(formula::Input(i));
        std::vector<Piece> pieces;
        for (const Node* child : moment_.nodes(ft, "children"))
            collect(child, Affine{}, b, local, pieces);
        ShapeMesh sm;
        sm.shape = &ft;
        sm.name = nameOf(ft);
        if (pieces.empty()) {
            out_.notes.push_back(sm.name + ": no implicit or explicit child to combine");
            return;
        }
        const Piece whole = combine(ft, pieces, b, local);
        ImplicitField field;
        field.tape = b.finish({{"value", whole.f}}, {});
        field.box = whole.box;
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
            if (options_.useFileResolution) o.resolution = whole.resolution;
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
        sm.texts = std::move(texts_);
        colour(whole.appearance, sm.field->box, sm);
        sm.look = lookOf(whole.appearance, true);
        sm.appearance = whole.appearance;
        sm.levelOfDetail = whole.levelOfDetail;
        place(sm, m);
        out_.shapes.push_back(std::move(sm));
    }

  public:
    // Standard shapes without an appearance of their own take the one an
    // FShape without geometry beside them lends (docs/nodes.md, "Standard
    // shapes with function properties"): its FMaterial's colour over the
    // lender's box — its bboxCenter/bboxSize, else the bounds of every shape
    // it lends to — in the lender's coordinates. After the walk: a lender
    // may come after the shapes it lends to.
    void lendAppearances() {
        if (out_.lenders.empty()) return;
        const auto lent = scene::lendingShapes(scene_);
        std::unordered_map<const Node*, Affine> lenderToScene;
        for (const SceneMeshes::Lender& l : out_.lenders)
            lenderToScene.emplace(l.shape, Affine::fromMatrix(l.placement));
        struct Borrower {
            ShapeMesh* shape;
            std::vector<Vec3f> points; // its vertices in the lender's coordinates
        };
        std::vector<std::pair<const Node*, std::vector<Borrower>>> byLender;
        for (ShapeMesh& sm : out_.shapes) {
            if (sm.functionGeometry || sm.appearance || !sm.error.empty() ||
                !sm.mesh.colours.empty())
                continue;
            const auto it = lent.find(sm.shape);
            if (it == lent.end()) continue;
            for (const Node* lender : it->second) {
                const auto where = lenderToScene.find(lender);
                if (!scene::effectiveNode(moment_.node(*lender, "appearance")) ||
                    where == lenderToScene.end())
                    continue;
                const std::optional<Affine> back = where->second.inverse();
                if (!back) break; // the lender is flattened: nothing to map onto
                const Affine toLender =
                    options_.placeInScene ? *back : *back * Affine::fromMatrix(sm.placement);
                Borrower b{&sm, {}};
                for (const Vec3f& p : sm.mesh.positions) {
                    const auto q = toLender.point({p[0], p[1], p[2]});
                    b.points.push_back({float(q[0]), float(q[1]), float(q[2])});
                }
                auto group = std::find_if(byLender.begin(), byLender.end(),
                                          [&](const auto& g) { return g.first == lender; });
                if (group == byLender.end()) group = byLender.insert(byLender.end(), {lender, {}});
                group->second.push_back(std::move(b));
                break;
            }
        }
        for (auto& [lender, borrowers] : byLender) {
            const Node* appearance = scene::effectiveNode(moment_.node(*lender, "appearance"));
            Box3 box{{1e300, 1e300, 1e300}, {-1e300, -1e300, -1e300}};
            if (const auto given = boundingBoxOf(*lender))
                box = *given;
            else
                for (const Borrower& b : borrowers)
                    box = pointBounds(b.points, box);
            if (!box.valid()) continue;
            for (Borrower& b : borrowers) {
                ShapeMesh probe; // the borrower's vertices where the lender sees them
                probe.mesh.positions = std::move(b.points);
                colour(appearance, box, probe);
                ShapeMesh& sm = *b.shape;
                sm.mesh.colours = std::move(probe.mesh.colours);
                sm.warnings.insert(sm.warnings.end(), probe.warnings.begin(), probe.warnings.end());
                const bool solid = sm.look.solid;
                sm.look = lookOf(appearance, true);
                sm.look.solid = solid;
                sm.appearance = appearance;
                // Its colour field sees the lender's coordinates, not the
                // shape's: left out (the grader samples the mesh's colours).
            }
        }
    }

  private:
    // Moves a mesh from its geometry's coordinates into the scene's.
    void place(ShapeMesh& sm, const Affine& m) const {
        if (!options_.placeInScene) {
            sm.placement = m.matrix();
            return;
        }
        placeMesh(sm, m);
    }

    static void placeMesh(ShapeMesh& sm, const Affine& m) {
        // Normals by the inverse transpose: the cofactors, with det's sign
        // (the length is normalised away), once per shape.
        const double det = m.determinant();
        const auto c = m.cofactors();
        const double sign = det < 0 ? -1 : 1;
        for (std::size_t i = 0; i < sm.mesh.positions.size(); ++i) {
            Vec3f& p = sm.mesh.positions[i];
            const double x = p[0], y = p[1], z = p[2];
            for (int k = 0; k < 3; ++k)
                p[std::size_t(k)] = float(m.m[k][0] * x + m.m[k][1] * y + m.m[k][2] * z + m.t[k]);
            const Vec3f& n = sm.mesh.normals[i];
            std::array<double, 3> r{};
            for (std::size_t k = 0; k < 3; ++k)
                r[k] = sign * (c[k][0] * n[0] + c[k][1] * n[1] + c[k][2] * n[2]);
            const double len = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
            if (len > 0)
                sm.mesh.normals[i] = {float(r[0] / len), float(r[1] / len), float(r[2] / len)};
        }
        // A mirroring transform turns the triangles inside out: turn them back.
        if (det < 0)
            for (Triangle& t : sm.mesh.triangles)
                std::swap(t[1], t[2]);
    }

    // Vertex colours from the shape's appearance, in the geometry's own
    // coordinates (before the transforms above it move the mesh).
    void colour(const Node* appearance, const Box3& geometryBox, ShapeMesh& sm) {
        const Node* material =
            appearance ? scene::effectiveNode(moment_.node(*appearance, "material")) : nullptr;
        if (!material) return;
        ColourField cf;
        cf.geometryBox = geometryBox;
        cf.componentBox = geometryBox;
        const auto diffuse = moment_.numbers(*material, "diffuseColor");
        if (diffuse.size() == 3) cf.fallback = {diffuse[0], diffuse[1], diffuse[2]};
        cf.constantTransparency = moment_.number(*material, "transparency");
        if (material->kind() == scene::NodeKind::FMaterial) {
            if (const formula::Tape* tape = scene_.definition(*material, "definition"))
                cf.colour = *tape;
            if (const formula::Tape* tape = scene_.definition(*material, "transparencyDefinition"))
                cf.transparency = *tape;
            cf.key = moment_.numbers(*material, "key");
            const auto kv = moment_.numbers(*material, "keyValue");
            for (std::size_t i = 0; i + 2 < kv.size(); i += 3)
                cf.keyValue.push_back({kv[i], kv[i + 1], kv[i + 2]});
            cf.componentBox = domainOf(*material);
            cf.t = timeOf(*material);
        }
        const auto warnings = applyColour(sm.mesh, cf);
        sm.warnings.insert(sm.warnings.end(), warnings.begin(), warnings.end());
        if (cf.colour) sm.colourField = std::make_shared<const ColourField>(std::move(cf));
    }

    const scene::Scene& scene_;
    const SceneMeshOptions& options_;
    SceneMeshes& out_;
    const animation::Animator& moment_;     // the one clock at the moment meshed
    std::vector<const Node*> touchSensors_; // of the lowest group the walk is inside that has any
    std::vector<DefinitionText> texts_;     // of the composite being built
    static constexpr std::size_t kMaxVisits = 200000;
    // The reader refuses scenes deeper than this; one changed by events (a
    // ROUTE into a children field) may still reach it.
    bool refused(const scene::WalkPath::Step& step) {
        if (step.entered()) return false;
        if (!loopNoted_)
            out_.notes.push_back("a node contains itself, or nodes nest more than " +
                                 std::to_string(scene::kMaxWalkDepth) +
                                 " deep; the walk stops there and what is below is not meshed");
        loopNoted_ = true;
        return true;
    }
    scene::WalkPath path_;
    bool loopNoted_ = false;
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
    Walker walker(scene, options, out, options.animator ? *options.animator : *own);
    for (const Node* root : scene.roots)
        walker.walk(root, {});
    walker.lendAppearances();
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
