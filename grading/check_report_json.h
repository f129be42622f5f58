#pragma once
// The one owner of the `grade check --json` document (docs/grading.md): the
// command line writes it, `grade batch` reads each isolated child's back,
// and the gradebook stores its locations the same way. Tools outside this
// repository read it: its fields are a contract.
//
//   {"assignment", "gradable", "score", "max_score", "checker_version",
//    "requirements": [{"id", "met", "points", "max_points", "evidence",
//                      "locations": [{"file", "line", "column"}]}],
//    "manual_max", "budget_exceeded",
//    "diagnostics": [{"file", "line", "column", "severity", "message", "suggestion"}]}
#include "grading/checker.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fl::grading {

struct CheckReportDocument {
    std::string assignment;
    std::string checkerVersion = kCheckerVersion;
    CheckReport report; // its timings are measurements, never written
    double manualMax = 0;
};

std::string checkReportJson(const CheckReportDocument& document);

// Read back with every field checked: the right JSON type, numbers finite
// and in range (points within [0, max_points], lines and columns >= 0 and
// int-sized), at most kMaxCheckReportBytes; none, with `error` saying which
// field is wrong, when it is not a check report.
inline constexpr std::size_t kMaxCheckReportBytes = std::size_t(16) << 20;
std::optional<CheckReportDocument> readCheckReportJson(std::string_view json,
                                                       std::string* error = nullptr);

// A requirement's locations as the report writes them: [{"file","line","column"}].
std::string locationsJson(const std::vector<Location>& locations);
// Read back; entries that are not a location are left out.
std::vector<Location> locationsOf(std::string_view json);

} // namespace fl::grading
