#pragma once
// A class's grades for a learning management system: the Canvas gradebook
// CSV, Moodle's grade import CSV, Gradescope-style results.json per
// submission, and a plain CSV with every requirement. Text a spreadsheet
// would run as a formula (= + - @ at the start of a cell) is escaped.
#include "gradebook.h"

#include <filesystem>
#include <string>

namespace fl::grading {

enum class ExportFormat : std::uint8_t { Canvas, Moodle, Gradescope, Csv };

// A cell as CSV writes it: quoted when it must be, formula-safe.
std::string csvCell(const std::string& text);

// The CSV formats as text; Gradescope as a folder of STUDENT/results.json.
std::string exportCsvText(Gradebook& book, const AssignmentRecord& assignment, ExportFormat format);
void exportGradescope(Gradebook& book, const AssignmentRecord& assignment,
                      const std::filesystem::path& folder);

} // namespace fl::grading
