#pragma once
// A function scene as standard X3D any X3D browser draws (issue 32 §1): each
// FShape, FTransform and Shape whose look comes from functions — its "root",
// the topmost of them (mesh/scene_meshing.h) — is replaced where it stood by
// its meshes, each an LOD of the resolutions asked for (the continuous level
// of detail, approximated), and a root that changes with time by N frames of
// its cycle in a Switch that a TimeSensor flips through an IntegerSequencer.
// Standard nodes, ROUTEs and viewpoints pass through; PROTO instances are
// written expanded and Inlines as Groups of what they show. What a browser
// must not do is left out, each with a warning: Script nodes (never run,
// DESIGN §3) and urls outside the scene's folder (the page needs no network).
#include "field/box3.h"
#include "scene/scene.h"

#include <atomic>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace fl::web {

struct BakeOptions {
    std::vector<double> resolutions{16, 32, 64}; // cells along a shape's longest side
    int frames = 24;                             // moments of a cycle that varies with time
    int threads = 0;                             // 0: one per core
    // The most triangles the page may hold, all levels and frames together:
    // past it the bake stops and says what to lower (a browser would not
    // open the page anyway). About 60 bytes of X3D text each.
    std::size_t maxTriangles = 20'000'000;
    // Called with the fraction done (0..1) as meshing goes.
    std::function<void(double)> progress;
    const std::atomic<bool>* cancel = nullptr;
};

// Which clock a baked TimeSensor keeps time by: the page sets its startTime
// (`scene`: when the page opened; `utc`: 1970; `local`: 1970 in the
// reader's time zone), so a wall clock shows the reader's time.
enum class ClockBase { Scene, Utc, Local };
std::string_view clockBaseName(ClockBase base); // "scene", "utc", "local"

struct BakedClock {
    std::string timeSensor; // its DEF name in the baked scene
    ClockBase base = ClockBase::Scene;
    double startSeconds = 0; // after the clock's origin
    double cycleSeconds = 1;
    bool loop = true;
};

// A file the baked scene names (an ImageTexture's image ...): copied from
// `source` to `target`, relative to the scene, which the url now says.
struct BakedFile {
    std::filesystem::path source;
    std::string target; // "files/images/wood.png"
};

struct BakeResult {
    scene::Scene scene; // standard X3D only
    std::vector<BakedClock> clocks;
    std::vector<BakedFile> files;
    std::vector<std::string> warnings;
    std::size_t roots = 0;     // replaced by meshes
    std::size_t animated = 0;  // of those, with frames
    std::size_t triangles = 0; // in every level and frame
    bool cancelled = false;
    std::string error; // why nothing usable was baked (the triangle budget)
};

BakeResult bakeForWeb(const scene::Scene& source, const BakeOptions& options = {});

// The distances at which an LOD of `resolutions` (finest first) changes
// level for a shape in `box`: where FunctionLab's own level of detail
// (mesh/level_of_detail.h) would ask for the geometric mean of two
// neighbouring resolutions. One fewer than the resolutions; increasing.
std::vector<double> lodRanges(const std::vector<double>& resolutionsFinestFirst,
                              const field::Box3& box);

} // namespace fl::web
