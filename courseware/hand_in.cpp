#include "hand_in.h"

#include "scene/field_access.h"

#include <fstream>
#include <set>

namespace fl::courseware {
namespace {

// `file` relative to `root`, when it lies inside it.
std::optional<std::filesystem::path> inside(const std::filesystem::path& root,
                                            const std::filesystem::path& file) {
    std::error_code ec;
    const auto canonical = std::filesystem::weakly_canonical(file, ec);
    if (ec) return std::nullopt;
    const auto relative = canonical.lexically_relative(root);
    if (relative.empty() || *relative.begin() == "..") return std::nullopt;
    return relative;
}

bool copyFile(const std::filesystem::path& from, const std::filesystem::path& to) {
    std::error_code ec;
    std::filesystem::create_directories(to.parent_path(), ec);
    return !ec && std::filesystem::copy_file(from, to, ec) && !ec;
}

} // namespace

HandIn packSubmission(const scene::Scene& scene, const std::filesystem::path& sceneFile,
                      const std::string& text, const std::filesystem::path& folder) {
    HandIn out;
    out.folder = folder;
    std::error_code ec;
    if (std::filesystem::exists(folder, ec) && !std::filesystem::is_empty(folder, ec)) {
        out.problems.push_back(folder.string() + " exists and is not empty: choose a new folder");
        return out;
    }
    std::filesystem::create_directories(folder, ec);
    if (ec) {
        out.problems.push_back("cannot make " + folder.string() + ": " + ec.message());
        return out;
    }
    const auto root = std::filesystem::weakly_canonical(sceneFile, ec).parent_path();
    // The scene, as the editor holds it.
    {
        std::ofstream file(folder / sceneFile.filename(), std::ios::binary);
        file << text;
        if (!file) {
            out.problems.push_back("cannot write " + (folder / sceneFile.filename()).string());
            return out;
        }
    }
    out.packed.push_back(sceneFile.filename());
    std::set<std::filesystem::path> done{sceneFile.filename()};
    auto pack = [&](const std::filesystem::path& file, const std::string& what) {
        const auto relative = inside(root, file);
        if (!relative) {
            out.problems.push_back(what + " " + file.string() +
                                   " is outside the scene's folder: not packed");
            return;
        }
        if (!done.insert(*relative).second) return;
        if (copyFile(file, folder / *relative))
            out.packed.push_back(*relative);
        else
            out.problems.push_back("cannot copy " + file.string());
    };
    // Inline and EXTERNPROTO files the reader followed (files[0] is the scene).
    for (std::size_t i = 1; i < scene.files.size(); ++i)
        pack(scene.files[i].path, "the referenced scene");
    // Images: the first url of each texture that names a file next to its scene.
    for (const scene::Scene* s : scene::scenesShownBy(scene))
        s->forEachNode([&](const scene::Node& n) {
            if (n.kind() != scene::NodeKind::ImageTexture &&
                n.kind() != scene::NodeKind::MovieTexture)
                return;
            const auto base = std::filesystem::path(scene.pathOf(n.file)).parent_path();
            for (const std::string& url : scene::stringsField(n, "url")) {
                if (url.find("://") != std::string::npos || url.empty()) continue;
                const auto file = base / url;
                if (std::filesystem::is_regular_file(file, ec)) {
                    pack(file, "the image");
                    break;
                }
            }
        });
    out.ok = true;
    return out;
}

} // namespace fl::courseware
