// libFuzzer target: a roster CSV from an LMS or a spreadsheet (outside
// input) imported into an in-memory gradebook. No crash, no hang; every
// problem names a line of the text; every student imported has an id.
#include "grading/gradebook.h"

#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    fl::grading::Gradebook book(":memory:");
    int lines = 1;
    for (char c : text)
        lines += c == '\n';
    for (const auto& p : book.importRoster(text))
        if (p.line < 1 || p.line > lines) std::abort();
    for (const auto& s : book.students())
        if (s.id.empty()) std::abort();
    return 0;
}
