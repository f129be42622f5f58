#pragma once
// Following a scene's references: Inline urls and EXTERNPROTO urls. Only files
// inside the top scene's folder tree are read (never the network, never a
// path that climbs out of the folder); cycles, depth and the number of files
// are bounded; whatever cannot be loaded is a warning, never an error, so
// the scene itself still opens.
#include "read_limits.h"
#include "scene.h"

#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fl::scene {

struct ReadOptions;

// What one top-level read shares while it follows references.
struct ReferenceContext {
    std::filesystem::path root;        // canonical folder: nothing outside it is read
    std::filesystem::path displayRoot; // the same folder as the user named it (for messages)
    std::vector<std::filesystem::path> loading; // files being read, outermost first
    std::size_t filesRead = 0;
    // Budgets shared by every file of the read (ReadLimits::maxNodes and
    // maxDecodedBytes hold for all of them together).
    std::size_t nodesRead = 0;
    std::size_t bytesRead = 0;
};

struct UrlTarget {
    std::filesystem::path file; // canonical, inside the root
    std::string fragment;       // after '#': a PROTO name or a Viewpoint
};

// The file `url` names relative to `baseDir`, or why it cannot be read.
std::optional<UrlTarget> resolveUrl(const ReferenceContext& context,
                                    const std::filesystem::path& baseDir, std::string_view url,
                                    std::string& why);

// Loads the references of one scene as it is read. Each file is read once per
// referring scene; its own references are followed with the same context.
class ReferenceLoader {
  public:
    // `context` null: the scene was read from memory, not from a file, so urls
    // cannot be followed (each reference says so in a warning).
    ReferenceLoader(ReferenceContext* context, Scene& scene, std::filesystem::path baseDir,
                    const ReadOptions& options, std::vector<SceneDiagnostic>& diagnostics);

    // Points `proto.resolved` at the PROTO its urls name; returns why not
    // (empty when resolved).
    std::string resolveExternProto(ProtoDeclaration& proto);
    // Loads every Inline of the scene (load TRUE) into `Node::inlined`.
    void resolveInlines();

  private:
    Scene* load(const std::filesystem::path& file, std::string& why);
    std::string tryUrls(const std::vector<std::string>& urls,
                        const std::function<bool(Scene&, const UrlTarget&, std::string&)>& use);

    ReferenceContext* context_;
    Scene& scene_;
    std::filesystem::path baseDir_;
    const ReadOptions& options_;
    std::vector<SceneDiagnostic>& diagnostics_;
    std::map<std::filesystem::path, Scene*> loaded_;
};

} // namespace fl::scene

namespace fl::scene {
struct ReadResult;
// readSceneBytes with the references followed inside `context` (null: none).
ReadResult readSceneIn(std::string bytes, const std::string& path, const ReadOptions& options,
                       ReferenceContext* context, const std::filesystem::path& baseDir);
} // namespace fl::scene
