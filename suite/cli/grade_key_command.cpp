// `functionlab grade key new [--out FILE]`: the instructor's signing key for
// gradebooks (Ed25519): the secret in FILE (mode 0600, never overwritten),
// the public key in FILE.pub and on stdout.
#include "cli/commands.h"
#include "platform/exit_codes.h"

#include "grading/signing.h"

#include <cstdlib>
#include <filesystem>
#include <iostream>

namespace fl::cli {

const CommandSpec& gradeKeySpec() {
    static const CommandSpec spec{
        .name = "grade key",
        .summary = "make the key that signs gradebooks (kept outside them)",
        .synopsis = {"grade key new [--out FILE]"},
        .description =
            "Makes an Ed25519 key pair. The secret key goes to FILE (default\n"
            "~/.config/functionlab/grading.key, mode 0600; an existing file is never\n"
            "overwritten) and signs the log of every gradebook the grade commands write;\n"
            "the public key goes to FILE.pub and is printed: give it to whoever checks\n"
            "a gradebook (functionlab grade verify --key). Keep the secret off shared\n"
            "machines and out of the gradebook's folder.\n",
        .positionals = {{.name = "ACTION", .help = "new"}},
        .options = {{.name = "out",
                     .kind = OptionKind::Path,
                     .valueName = "FILE",
                     .help = "where the secret key goes (default "
                             "~/.config/functionlab/grading.key)"}},
        .exitStatus = "0 the key was made, 1 it could not be written (or FILE exists), 2 usage "
                      "error",
    };
    return spec;
}

int gradeKeyCommand(const Args& args) {
    int exit = 0;
    const auto a = parseOrExplain(gradeKeySpec(), args, exit, std::cout, std::cerr);
    if (!a) return exit;
    if (a->positional("ACTION") != "new")
        return usageError(gradeKeySpec(), "the action is 'new'", std::cerr);
    std::string file = a->text("out");
    if (file.empty()) {
        const char* home = std::getenv("HOME");
        if (!home || !*home)
            return usageError(gradeKeySpec(), "no HOME: say where with --out", std::cerr);
        const std::filesystem::path dir = std::filesystem::path(home) / ".config" / "functionlab";
        std::error_code ec;
        std::filesystem::create_directories(dir, ec);
        std::filesystem::permissions(dir, std::filesystem::perms::owner_all,
                                     std::filesystem::perm_options::replace, ec);
        file = (dir / "grading.key").string();
    }
    const grading::SigningKey key = grading::newSigningKey();
    std::string why;
    if (!grading::writeSigningKey(key, file, why)) {
        std::cerr << "functionlab grade key: " << why << "\n";
        return kExitDiagnostic;
    }
    std::cerr << "functionlab grade key: the secret key is in " << file
              << " (keep it); its public key in " << file << ".pub:\n";
    std::cout << key.publicHex << "\n";
    return kExitOk;
}

} // namespace fl::cli
