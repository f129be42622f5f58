#pragma once
// Meshes the shapes of a scene at one moment: every FShape's FGeometry
// (implicit, explicit, parametric) in its domain box at the geometry's own t
// for that moment, and the standard geometry of Shape and FShape nodes (Box,
// Sphere, IndexedFaceSet, ...), each coloured by its appearance and placed by
// the Transform and FTransform nodes above it, with the values the scene's
// animation (TimeSensors, interpolators, ROUTEs) gives them at that moment.
#include "animation/animator.h"
#include "animation/clock.h"
#include "colouring.h"
#include "dual_contouring.h"
#include "field_names.h"
#include "mesh.h"
#include "mesh_cache.h"
#include "scene/scene.h"
#include "scene_texture.h"
#include "scene_view.h"
#include "text_layout.h"

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace fl::pde {
struct Model;
}

namespace fl::mesh {

struct SceneMeshOptions {
    MeshOptions mesh;              // threads, budget, cancel ...
    bool useFileResolution = true; // each FGeometry's `resolution`; false: mesh.resolution
    double targetError = 0;        // > 0: mesh each shape to this error instead
    double sceneSeconds = 0; // the moment, in scene time (wall clocks: the scene started at 0 UTC)
    // The moment on every clock (a running viewer's timeline): overrides
    // sceneSeconds, so `timeBase "local"` nodes (the clock) show the real time.
    std::optional<animation::Instant> instant;
    // The one clock (DESIGN §3): every field (a Transform's rotation set by an
    // interpolator, a Material's colour ...) and every function node's t is
    // read from it. Null: meshScene runs the scene's animation to the moment
    // above itself, from the start, as a cold `render --time` does (design
    // notes: a moment is replayed, not stepped to). Not owned.
    const animation::Animator* animator = nullptr;
    // > 0: every function shape as a cloud of about this many points (its
    // FGeometry's `points` field otherwise; 0 there: a mesh).
    std::size_t points = 0;
    bool standardShapes = true; // also mesh Box, Sphere, IndexedFaceSet, ... (false: notes only)
    // true: meshes in scene coordinates; false: in the shape's own, with
    // ShapeMesh::placement taking them to the scene (a viewer animating
    // transforms moves the matrix and keeps the mesh).
    bool placeInScene = true;
    // true: every shape is placed in the frame of the parent of its root —
    // the topmost FShape, Shape or FTransform above it (ShapeMesh::root) —
    // instead of the scene's: `export-web` puts each mesh where that root
    // stood, under the scene's own (animated) Transforms. A root reached
    // again (USE) is meshed once: in that frame its meshes are the same.
    bool meshInRootFrame = false;
    // true: every child of a Switch and every level of an LOD is meshed, not
    // only the one shown (`export-web` keeps the Switch and LOD).
    bool everyChoice = false;
    int segments = 48; // around the axis of standard spheres, cones and cylinders
    // Meshes reused across calls (a viewer playing time asks again and again):
    // shapes whose geometry does not read t are meshed once. Optional.
    MeshCache* cache = nullptr;
    // Values for the formulas' named parameters (`param R = 0.8 in [0.2, 1.5];`)
    // other than their defaults: the suite's sliders set them.
    std::vector<std::pair<std::string, double>> parameters;
    // Per FGeometry node: the resolution to mesh it at instead of its own
    // (the viewer's level of detail). Shapes not listed use the rule above.
    std::unordered_map<const scene::Node*, double> resolutions;
    // Outlines glyphs for Text nodes (the suite's, from Qt: viewer/text_outliner.h);
    // without one, Text is named in a note.
    TextOutliner text;
};

// Every named parameter of the scene's function definitions (each name once,
// with the first definition's default and range).
std::vector<formula::ParameterInfo> sceneParameters(const scene::Scene& scene);

// How a shape's surface takes light: the constant terms of its Material or
// FMaterial (the diffuse colour, per vertex, is in Mesh::colours).
struct SurfaceLook {
    std::array<float, 3> emissive{0, 0, 0};
    std::array<float, 3> specular{0, 0, 0};
    float shininess = 0.2f;
    float ambientIntensity = 0.2f;
    // X3D: a Shape without a Material is unlit (its colour, or white, as is).
    // An FShape without one is lit grey: a formula's first look should show its form.
    bool lit = true;
    bool solid = true; // only the front faces are drawn (X3D `solid`)
    // An image texture on standard geometry (the mesh then has texCoords):
    // its colour replaces the diffuse colour (intensity images modulate it).
    std::optional<SurfaceTexture> texture;

    bool operator==(const SurfaceLook&) const = default;
};

constexpr Matrix4 kIdentity4{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

// A text of a node (a field's value) that formulas were compiled from.
struct DefinitionText {
    const scene::Node* node = nullptr;
    std::string field; // "definition", "operation", "domainMin" ...
};

struct ShapeMesh {
    const scene::Node* shape = nullptr;
    std::string name;               // "FShape WATERMELON (file:line:col)"
    Mesh mesh;                      // in scene coordinates, or the shape's own (see placeInScene)
    Matrix4 placement = kIdentity4; // shape to scene (identity once placed in the scene)
    SurfaceLook look;
    bool functionGeometry = true;          // FGeometry (false: standard geometry)
    const scene::Node* geometry = nullptr; // the FGeometry (function shapes)
    // The FGeometry whose lod and lodRange it is drawn with: its own, or for
    // a combined shape (an FTransform's set operation) its first child's with
    // lod TRUE; null without level of detail. The viewer keys the resolution
    // it picks by `geometry`, else by the combining FTransform (`shape`).
    const scene::Node* levelOfDetail = nullptr;
    // The appearance it is drawn with: its shape's, or for a combined shape
    // (an FTransform's set operation) its first child's.
    const scene::Node* appearance = nullptr;
    // The colour its FMaterial gives at the moment meshed (null without one):
    // the grader colours points of a shape too small for its coarse mesh.
    std::shared_ptr<const ColourField> colourField;
    Box3 domain;           // its domain box, in the shape's coordinates
    double resolution = 0; // what it was meshed at
    double t = 0;          // the geometry's t at the moment meshed
    std::vector<std::pair<std::string, double>> parameters; // `param` values used
    // Implicit, explicit and combined (FTransform) shapes: the field exactly
    // as it was meshed — definition, displacement, parameters, t, box — for
    // picking, haptic contact and the grader to sample (field/ray_march.h).
    std::shared_ptr<const ImplicitField> field;
    // An FPdeSurface's model as it was meshed (the Accuracy panel measures
    // what drawing it costs); null for every other shape.
    std::shared_ptr<const pde::Model> pdeModel;
    // The texts the field's instructions come from: an instruction's origin
    // range is in texts[origin.source] (an FGeometry's definition; for a
    // combined shape also each child's, each FTransform's operation and its
    // children's domain boxes). The grader locates operations by it.
    std::vector<DefinitionText> texts;
    MeshStats stats;
    double measuredError = -1; // with a target error: what was reached
    // The enabled TouchSensors a click on this shape triggers: those beside
    // it, or beside the lowest group above it that has any (X3D §20.2.1).
    std::vector<const scene::Node*> touchSensors;
    // The topmost FShape, Shape or FTransform the shape was meshed under (the
    // FTransform of a set operation's children, the FShape itself ...).
    const scene::Node* root = nullptr;
    std::vector<std::string> warnings;
    std::string error;
    bool cancelled = false; // stopped by MeshOptions::cancel (error then says so)
};

struct SceneMeshes {
    std::vector<ShapeMesh> shapes;
    std::vector<std::string> notes; // what was not meshed and why
    SceneView view;                 // lights, viewpoints, background, navigation
    // The scene these meshes were made from, when the maker shares it (the
    // viewer's player does): the shapes' node pointers stay valid as long as
    // the meshes are kept, even after the editor has replaced the scene.
    std::shared_ptr<const scene::Scene> source;
    // FShapes without geometry, which lend their appearance and physics to the
    // shapes grouped with them, and where each stands: its coordinates to the
    // scene's (the frame its bboxCenter/bboxSize and components are read in).
    struct Lender {
        const scene::Node* shape = nullptr;
        Matrix4 placement = kIdentity4;
    };
    std::vector<Lender> lenders;
};

SceneMeshes meshScene(const scene::Scene& scene, const SceneMeshOptions& options);

// The moment SceneMeshOptions names: `instant`, else sceneSeconds on every clock.
animation::Instant momentOf(const SceneMeshOptions& options);

// A function node's domain box (domainMin .. domainMax).
Box3 domainOf(const scene::Node& node);

// A grouping node's or FShape's bboxCenter/bboxSize as a box, when one is
// given (a positive size on every axis; X3D's -1 -1 -1 means none).
std::optional<Box3> boundingBoxOf(const scene::Node& node);

// The smallest box holding `points`, grown from `box`; grown from nothing
// (the default), a box that is not valid() when there are no points.
Box3 pointBounds(const std::vector<Vec3f>& points,
                 Box3 box = {{1e300, 1e300, 1e300}, {-1e300, -1e300, -1e300}});

// A point of the scene in a shape's own coordinates (its placement undone);
// none when the placement cannot be undone (a zero scale).
std::optional<field::Vec3> shapeCoordinates(const ShapeMesh& shape, const field::Vec3& point);

// Whether any of a shape is drawn: not when every vertex is fully
// transparent (transparency 1: the fan's wind, the shark's water). What is
// not drawn catches no click, no TouchSensor and no error figure (issue 29
// §4), as a student would expect of what they cannot see.
bool isDrawn(const ShapeMesh& shape);
// The same for one triangle: its three vertices fully transparent.
bool isDrawnTriangle(const Mesh& mesh, const Triangle& triangle);

// All shapes' meshes of one kind (triangles, or point clouds) as one.
Mesh mergeMeshes(const std::vector<ShapeMesh>& shapes, Primitive primitive = Primitive::Triangles);

} // namespace fl::mesh
