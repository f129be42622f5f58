#include "workspace.h"

#include <cstdlib>
#include <system_error>

namespace fl::courseware {

std::filesystem::path workspaceFolder() {
    if (const char* dir = std::getenv("FUNCTIONLAB_WORKSPACE"); dir && *dir) return dir;
    const char* home = std::getenv("HOME");
    return std::filesystem::path(home && *home ? home : ".") / "FunctionLab";
}

WorkingCopy workingCopyOf(const std::filesystem::path& source, const std::string& folder) {
    WorkingCopy out;
    // The folder is a name of ours (an id or "examples"): one path segment.
    if (folder.empty() || folder.find('/') != std::string::npos || folder == "." ||
        folder == "..") {
        out.error = "'" + folder + "' is not a folder name";
        return out;
    }
    std::error_code ec;
    const std::filesystem::path dir = workspaceFolder() / folder;
    std::filesystem::create_directories(dir, ec);
    if (ec) {
        out.error = "cannot make " + dir.string() + ": " + ec.message();
        return out;
    }
    const std::filesystem::path copy = dir / source.filename();
    if (std::filesystem::exists(copy, ec)) {
        out.path = copy;
        out.existed = true;
        return out;
    }
    std::filesystem::copy_file(source, copy, std::filesystem::copy_options::skip_existing, ec);
    if (ec) {
        out.error = "cannot copy " + source.string() + " to " + dir.string() + ": " + ec.message();
        return out;
    }
    // The course's file may be read-only (installed): the copy is the student's.
    std::filesystem::permissions(
        copy, std::filesystem::perms::owner_read | std::filesystem::perms::owner_write,
        std::filesystem::perm_options::add, ec);
    out.path = copy;
    return out;
}

} // namespace fl::courseware
