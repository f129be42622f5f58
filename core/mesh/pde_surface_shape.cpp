#include "pde_surface_shape.h"

#include "pde/pde_data_url.h"
#include "pde/pde_file.h"
#include "scene/scene_references.h"

#include <filesystem>
#include <functional>
#include <map>
#include <mutex>

namespace fl::mesh {
namespace {

struct Kept {
    std::filesystem::file_time_type written;
    std::uintmax_t size = 0;
    std::shared_ptr<const pde::Model> model;
};

// Models read, by canonical path; the oldest half dropped past 32.
std::shared_ptr<const pde::Model> keptOrRead(const std::filesystem::path& file, std::string& why) {
    static std::mutex lock;
    static std::map<std::filesystem::path, Kept> kept;
    std::error_code ec;
    const auto written = std::filesystem::last_write_time(file, ec);
    const auto size = std::filesystem::file_size(file, ec);
    {
        const std::lock_guard guard(lock);
        if (const auto it = kept.find(file);
            it != kept.end() && !ec && it->second.written == written && it->second.size == size)
            return it->second.model;
    }
    pde::ReadResult r = pde::readModelFile(file.string());
    if (!r.ok()) {
        why = r.error;
        return nullptr;
    }
    auto model = std::make_shared<const pde::Model>(std::move(*r.model));
    const std::lock_guard guard(lock);
    if (kept.size() >= 32) kept.clear();
    kept[file] = {written, size, model};
    return model;
}

} // namespace

PdeSurfaceModel pdeSurfaceModel(const scene::Scene& scene, const scene::Node& surface,
                                const std::vector<std::string>& urls) {
    PdeSurfaceModel out;
    const std::string& top = scene.pathOf(0);
    const std::string& own = scene.pathOf(surface.file);
    const bool fromFile = !top.empty() && !own.empty();
    if (urls.empty()) {
        out.error = "no url: name the .pde file (functionlab pde fit makes one)";
        return out;
    }
    scene::ReferenceContext context;
    std::error_code ec;
    if (fromFile) {
        context.root =
            std::filesystem::weakly_canonical(std::filesystem::path(top).parent_path(), ec);
        context.displayRoot = std::filesystem::path(top).parent_path();
    }
    const std::filesystem::path base =
        fromFile ? std::filesystem::path(own).parent_path() : std::filesystem::path();
    std::string reasons;
    for (const std::string& url : urls) {
        std::string why;
        if (pde::isDataUrl(url)) { // the model carried in the scene itself
            pde::ReadResult r = pde::readDataUrl(url, "the data url");
            if (r.ok()) {
                out.model = std::make_shared<const pde::Model>(std::move(*r.model));
                out.file = "data:" + std::to_string(std::hash<std::string>{}(url)) + ":" +
                           std::to_string(url.size());
                return out;
            }
            reasons += (reasons.empty() ? "" : "; ") + r.error;
            continue;
        }
        if (!fromFile) {
            reasons += (reasons.empty() ? "" : "; ") +
                       ("\"" + url +
                        "\": the scene was not read from a file, so its url cannot "
                        "be followed (a data url carries the model in the scene)");
            continue;
        }
        const auto target = scene::resolveUrl(context, base, url, why);
        if (target) {
            out.model = keptOrRead(target->file, why);
            if (out.model) {
                out.file = target->file.string();
                return out;
            }
        }
        reasons += (reasons.empty() ? "" : "; ") + ("\"" + url + "\": " + why);
    }
    out.error = reasons;
    return out;
}

} // namespace fl::mesh
