#include "cli/grade_options.h"

#include "cli/json.h"

#include "courseware/catalogue.h"
#include "grading/signing.h"

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

OptionSpec signingKeyOption() {
    return {.name = "signing-key",
            .kind = OptionKind::Path,
            .valueName = "FILE",
            .help = "the secret key that signs the gradebook's log (functionlab grade key new); "
                    "without it FUNCTIONLAB_GRADING_KEY, else ~/.config/functionlab/grading.key "
                    "when there is one"};
}

std::optional<grading::SignedHead> signHeadOrSay(grading::Gradebook& book, const ParsedArgs& a,
                                                 const std::string& command, std::ostream& err) {
    const std::string path =
        a.given("signing-key") ? a.text("signing-key") : grading::defaultSigningKeyPath();
    if (path.empty()) {
        err << "functionlab " << command << ": the gradebook's log is not signed (no key: "
            << "functionlab grade key new makes one)\n";
        return std::nullopt;
    }
    std::string why;
    const auto key = grading::readSigningKey(path, why);
    if (!key) {
        err << "functionlab " << command << ": the log is not signed: " << why << "\n";
        return std::nullopt;
    }
    const grading::SignedHead h = book.signHead(*key);
    err << "functionlab " << command << ": signed the log's head, entry " << h.head.seq << " ("
        << h.head.hash.substr(0, 16) << "…), with key " << h.publicKey.substr(0, 16) << "…\n";
    return h;
}

std::string headJson(const grading::LogHead& head, const std::optional<grading::SignedHead>& s) {
    std::string out = "{\"entry\":" + std::to_string(head.seq);
    out += ",\"hash\":" + jsonString(head.hash);
    out += ",\"publicKey\":" + (s ? jsonString(s->publicKey) : std::string("null"));
    out += ",\"signature\":" + (s ? jsonString(s->signature) : std::string("null"));
    return out + "}";
}

} // namespace fl::cli
