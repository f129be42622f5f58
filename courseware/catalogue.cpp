#include "catalogue.h"

#include "scene/field_access.h"
#include "scene/scene_reader.h"

#include <algorithm>
#include <cstdlib>
#include <tuple>

namespace fl::courseware {
namespace {

std::string titleOf(const scene::Scene& s, std::string fallback, std::string& description) {
    std::string title;
    for (const scene::Node* root : s.roots)
        if (const scene::Node* n = scene::effectiveNode(root);
            n && n->kind() == scene::NodeKind::WorldInfo) {
            title = scene::stringField(*n, "title");
            break;
        }
    for (const auto& [name, content] : s.meta) {
        if (name == "description") description = content;
        if (name == "title" && title.empty()) title = content;
    }
    return title.empty() ? fallback : title;
}

} // namespace

namespace {

// share/functionlab/PART next to the running executable's bin/, if installed.
std::filesystem::path installedPart(const char* part) {
    std::error_code ec;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) return {};
    const auto installed = exe.parent_path() / ".." / "share" / "functionlab" / part;
    if (!std::filesystem::is_directory(installed, ec)) return {};
    return std::filesystem::weakly_canonical(installed, ec);
}

bool isWithin(const std::filesystem::path& path, const std::filesystem::path& folder) {
    if (folder.empty()) return false;
    std::error_code ec;
    const auto p = std::filesystem::weakly_canonical(path, ec);
    const auto f = std::filesystem::weakly_canonical(folder, ec);
    const auto [end, at] = std::mismatch(f.begin(), f.end(), p.begin(), p.end());
    return end == f.end();
}

} // namespace

std::filesystem::path coursewareFolder() {
    if (auto installed = installedPart("courseware"); !installed.empty()) return installed;
    return FUNCTIONLAB_COURSEWARE_DIR;
}

bool isInsideCourseware(const std::filesystem::path& path) {
    return isWithin(path, coursewareFolder());
}

std::filesystem::path instructorFolderFor(const std::filesystem::path& folder,
                                          const std::string& id) {
    std::error_code ec;
    if (const char* dir = std::getenv("FUNCTIONLAB_INSTRUCTOR_DIR"); dir && *dir && !id.empty())
        if (std::filesystem::is_directory(std::filesystem::path(dir) / id, ec))
            return std::filesystem::path(dir) / id;
    if (auto installed = installedPart("instructor"); !installed.empty() && !id.empty())
        if (std::filesystem::is_directory(installed / id, ec)) return installed / id;
    // A student's installed courseware never holds solutions: not looked in.
    if (isWithin(folder, installedPart("courseware"))) return {};
    return folder;
}

std::vector<ExampleScene> listExamples(const std::filesystem::path& folder) {
    std::vector<ExampleScene> out;
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(folder, ec))
        if (e.path().extension() == ".x3d" && e.is_regular_file(ec)) {
            ExampleScene x;
            x.path = e.path();
            x.title = x.path.filename().string();
            const scene::ReadResult r = scene::readSceneFile(x.path);
            if (r.scene) x.title = titleOf(*r.scene, x.title, x.description);
            out.push_back(std::move(x));
        }
    std::sort(out.begin(), out.end(),
              [](const ExampleScene& a, const ExampleScene& b) { return a.path < b.path; });
    return out;
}

std::vector<AssignmentLoad> listAssignments(const std::filesystem::path& folder) {
    std::vector<std::filesystem::path> folders;
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(folder, ec))
        if (e.is_directory(ec) && std::filesystem::exists(e.path() / "manifest.json", ec))
            folders.push_back(e.path());
    std::sort(folders.begin(), folders.end());
    std::vector<AssignmentLoad> out;
    for (const auto& f : folders)
        out.push_back(loadAssignment(f));
    // The course's order: "Lab 1", "Lab 2" … by their numbers (not their
    // folders' names), then the others (the final assignment) by title;
    // one that does not load, last.
    auto key = [](const AssignmentLoad& a) {
        if (!a.assignment) return std::tuple(2, 0L, std::string());
        const std::string& title = a.assignment->title;
        long number = 0;
        if (title.rfind("Lab ", 0) == 0) {
            const char* begin = title.c_str() + 4;
            char* end = nullptr;
            number = std::strtol(begin, &end, 10);
            if (end != begin) return std::tuple(0, number, title);
        }
        return std::tuple(1, 0L, title);
    };
    std::stable_sort(out.begin(), out.end(), [&](const AssignmentLoad& a, const AssignmentLoad& b) {
        return key(a) < key(b);
    });
    return out;
}

AssignmentLoad findAssignment(const std::string& idOrFolder) {
    std::error_code ec;
    const bool plainId =
        !idOrFolder.empty() && std::all_of(idOrFolder.begin(), idOrFolder.end(), [](char c) {
            return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-';
        });
    // A folder of the working directory named like an id ("time") is the
    // assignment only when it holds a manifest; else the id is the course's.
    const bool isFolder = std::filesystem::is_directory(idOrFolder, ec);
    if (isFolder &&
        (!plainId || std::filesystem::exists(std::filesystem::path(idOrFolder) / "manifest.json")))
        return loadAssignment(idOrFolder);
    const auto folder = coursewareFolder() / "assignments" / idOrFolder;
    if (plainId && std::filesystem::is_directory(folder, ec)) return loadAssignment(folder);
    if (isFolder) return loadAssignment(idOrFolder); // says what the folder lacks
    AssignmentLoad load;
    std::string known;
    for (const AssignmentLoad& a : listAssignments())
        if (a.assignment) known += (known.empty() ? "" : ", ") + a.assignment->id;
    load.diagnostics.push_back(
        {scene::Severity::Error,
         idOrFolder,
         {1, 1},
         "no assignment '" + idOrFolder + "' (neither an id nor a folder)",
         known.empty() ? "" : "the assignments that come with FunctionLab: " + known});
    return load;
}

} // namespace fl::courseware
