#include "cli/grade_options.h"

#include "catalogue.h"

#include <filesystem>
#include <ostream>

namespace fl::cli {

OptionSpec assignmentOption() {
    return {.name = "assignment",
            .kind = OptionKind::Text,
            .valueName = "ID|DIR",
            .help = "the assignment: an id of courseware/assignments (implicit-fantasies) or the "
                    "folder of its manifest.json"};
}

OptionSpec gradebookOption(std::string_view help) {
    return {.name = "db", .kind = OptionKind::Path, .valueName = "GRADEBOOK.sqlite", .help = help};
}

std::optional<courseware::Assignment> assignmentOrExplain(const std::string& idOrFolder,
                                                          std::ostream& err) {
    courseware::AssignmentLoad load = courseware::findAssignment(idOrFolder);
    for (const auto& d : load.diagnostics)
        err << scene::formatSceneDiagnostic(d) << "\n";
    return std::move(load.assignment);
}

bool gradebookExists(const std::string& command, const std::string& path, std::ostream& err) {
    std::error_code ec;
    if (std::filesystem::is_regular_file(path, ec)) return true;
    err << "functionlab " << command << ": no gradebook " << path
        << " (functionlab grade batch makes one)\n";
    return false;
}

} // namespace fl::cli
