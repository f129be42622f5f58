// libFuzzer target: an assignment manifest from anyone (a course shared by
// another instructor is hostile until checked). Beyond "no crash, no hang":
// a manifest that loads has only known requirement kinds and unique ids, and
// every diagnostic has a position inside the text.
#include "courseware/assignment.h"

#include <cstdint>
#include <cstdlib>
#include <set>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    // Paths resolve against a folder that does not exist: file checks fail
    // cleanly, everything else is exercised.
    const auto load = fl::courseware::parseAssignment(text, "/nonexistent-fuzz-folder");
    int lines = 1;
    for (char c : text)
        lines += c == '\n';
    for (const auto& d : load.diagnostics)
        if (d.pos.line < 1 || d.pos.line > lines || d.pos.column < 1) std::abort();
    if (load.assignment) {
        std::set<std::string> ids;
        for (const auto& r : load.assignment->requirements)
            if (!ids.insert(r.id).second) std::abort();
    }
    return 0;
}
