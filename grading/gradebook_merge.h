#pragma once
// Grading a course on many machines (issue 32 §4): `grade batch --shard K/N`
// grades the K-th of N disjoint parts of a class (by a stable hash of the
// student id) into a gradebook of its own, and `grade merge` combines the
// parts into one. The merged log holds every entry of every part, with its
// own time, kind and payload, chained anew, and then one "merge" entry that
// records each part's file name, entry count, head and signed heads — so a
// part kept aside can still be matched to what was merged. Parts that
// disagree are refused, never combined: two parts with work of the same
// student on the same assignment (grades, manual scores or overrides), or
// a student or an assignment described differently.
#include "gradebook.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace fl::grading {

// Which of `parts` parts a student is graded in: FNV-1a of the id's bytes,
// modulo `parts` — the same on every machine, whatever the order of files.
std::size_t shardOf(const std::string& student, std::size_t parts);

struct MergeSummary {
    std::size_t sources = 0;
    std::size_t entries = 0; // in the merged log, the merge record included
    std::size_t students = 0, grades = 0;
    LogHead head;
};

// Merges the gradebooks `sources` (each must exist and verify) into a new
// gradebook at `out`, which must not exist yet; written beside it first and
// moved into place at the end, so a refused or failed merge leaves nothing.
// Nullopt, with `why` naming the files and whom they disagree about.
std::optional<MergeSummary> mergeGradebooks(const std::vector<std::string>& sources,
                                            const std::string& out, std::string* why);

} // namespace fl::grading
