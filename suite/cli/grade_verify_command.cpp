// `functionlab grade verify GRADEBOOK [--head HASH] [--key PUB] [--json]`:
// is the gradebook what its log says, and the log what the instructor
// signed? The first entry that breaks the chain, or the table row changed
// behind the log's back, with what changed (grading/gradebook.h).
#include "cli/commands.h"
#include "cli/grade_options.h"
#include "cli/json.h"
#include "platform/exit_codes.h"

#include "grading/gradebook.h"
#include "grading/signing.h"

#include <iostream>

namespace fl::cli {

const CommandSpec& gradeVerifySpec() {
    static const CommandSpec spec{
        .name = "grade verify",
        .summary = "check a gradebook against its hash-chained log and the instructor's signature",
        .synopsis = {"grade verify GRADEBOOK [--head HASH] [--key PUB] [--json]"},
        .description =
            "Checks that the gradebook's log is whole (every entry numbered, chained to the\n"
            "one before and hashing to what it holds), that its tables are exactly what the\n"
            "log rebuilds, and the heads signed in it. With --head (the hash an export or a\n"
            "report carries) that head must be in the log: entries deleted from its end\n"
            "show. With --key (the instructor's public key) a head signed with it must hold:\n"
            "a log hashed again by someone without the key shows. Prints the first problem\n"
            "with where it is and what changed.\n",
        .positionals = {{.name = "GRADEBOOK", .help = "the gradebook (.sqlite)"}},
        .options = {{.name = "head",
                     .kind = OptionKind::Text,
                     .valueName = "HASH",
                     .help = "a head the log must contain (from an export's .head.json or a "
                             "report)"},
                    {.name = "key",
                     .kind = OptionKind::Text,
                     .valueName = "PUB",
                     .help = "the instructor's public key: 64 hex digits, or a .pub file"},
                    {.name = "json",
                     .help = "print one JSON object: {\"intact\", \"entries\", \"head\", "
                             "\"bad_entry\", \"problem\", \"signed\": {\"entry\", \"public_key\", "
                             "\"holds\"} or null, \"unsigned_entries\"}"}},
        .exitStatus = "0 intact, 1 tampered, unsigned with --key, or unreadable, 2 usage error",
    };
    return spec;
}

int gradeVerifyCommand(const Args& args) {
    int exit = 0;
    const auto a = parseOrExplain(gradeVerifySpec(), args, exit, std::cout, std::cerr);
    if (!a) return exit;
    const std::string path = a->positional("GRADEBOOK");
    if (!gradebookExists("grade verify", path, std::cerr)) return kExitDiagnostic;
    grading::VerifyOptions o;
    if (a->given("head")) o.head = a->text("head");
    if (a->given("key")) {
        std::string why;
        o.publicKey = grading::readPublicKey(a->text("key"), why);
        if (!o.publicKey) return usageError(gradeVerifySpec(), "--key: " + why, std::cerr);
    }
    grading::GradebookCheck c;
    try {
        grading::Gradebook book(path);
        c = book.verify(o);
    } catch (const std::exception& e) {
        std::cerr << "functionlab grade verify: " << path << ": " << e.what() << "\n";
        return kExitDiagnostic;
    }
    if (a->flag("json")) {
        std::string out = "{\"intact\":" + std::string(c.intact ? "true" : "false");
        out += ",\"entries\":" + std::to_string(c.entries);
        out += ",\"head\":" + headJson(c.head, std::nullopt);
        out += ",\"bad_entry\":" + std::to_string(c.badEntry);
        out += ",\"problem\":" + jsonString(c.problem);
        out += ",\"signed\":";
        if (c.signedHead)
            out += "{\"entry\":" + std::to_string(c.signedHead->head.seq) +
                   ",\"public_key\":" + jsonString(c.signedHead->publicKey) +
                   ",\"holds\":" + (c.signatureHolds ? "true" : "false") + "}";
        else
            out += "null";
        out += ",\"unsigned_entries\":" + std::to_string(c.unsignedEntries) + "}";
        std::cout << out << "\n";
    } else if (c.intact) {
        std::cout << path << ": intact: " << c.entries << " entries, head entry " << c.head.seq
                  << " (" << c.head.hash.substr(0, 16) << "…); the tables are what the log says\n";
        if (c.signedHead)
            std::cout << "signed at entry " << c.signedHead->head.seq << " with key "
                      << c.signedHead->publicKey.substr(0, 16) << "…: the signature holds"
                      << (c.unsignedEntries ? "; " + std::to_string(c.unsignedEntries) +
                                                  " entries came after it (not yet signed)"
                                            : std::string())
                      << "\n";
        else
            std::cout << "no signed head: run a grade command with a signing key (functionlab "
                         "grade key new)\n";
    } else {
        std::cout << path << ": NOT INTACT: " << c.problem << "\n";
    }
    return c.intact ? kExitOk : kExitDiagnostic;
}

} // namespace fl::cli
