#pragma once
// Inside the gradebook (not for other wings): the log's schema, each kind
// of entry's JSON payload (written and read back by the same functions, so
// a replay applies exactly what was written), and the hashes.
#include "gradebook.h"
#include "grading/check_report_json.h" // locationsJson, locationsOf

#include <string>
#include <vector>

namespace fl::grading {

// Schema 4: the append-only log and the signed heads. The triggers refuse an
// UPDATE or DELETE of an entry (someone with sqlite3 can drop them; then the
// hash chain shows what they did).
extern const char* const kLogSchema;

std::string sha256(const std::string& text);

// Each kind of change as the log holds it: canonical JSON (keys sorted,
// numbers written to round-trip exactly).
std::string studentPayload(const Student& s);
std::string assignmentPayload(const AssignmentRecord& a);
std::string gradePayload(const GradeRecord& g);
std::string manualScorePayload(const std::string& student, const std::string& assignment,
                               const ManualScore& m);
std::string overridePayload(const std::string& student, const std::string& assignment, double score,
                            const std::string& who, const std::string& why, const std::string& at);

// An entry's hash: of the one before it, its number, time, kind and payload.
std::string entryHash(const std::string& previous, std::int64_t seq, const std::string& at,
                      std::string_view kind, const std::string& payload);

} // namespace fl::grading
