#include "gradebook_merge.h"

#include "text/json_text.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <filesystem>
#include <map>
#include <set>

namespace fl::grading {
namespace {

std::string field(const QJsonObject& o, const char* key) {
    return o.value(QLatin1String(key)).toString().toStdString();
}

QJsonObject parsed(const std::string& payload) {
    return QJsonDocument::fromJson(QByteArray::fromStdString(payload)).object();
}

std::string nameOf(const std::string& path) {
    return std::filesystem::path(path).filename().string();
}

// What one part holds that another may contradict.
struct PartFacts {
    std::map<std::string, std::string> students, assignments; // id -> last payload
    std::set<std::pair<std::string, std::string>> work;       // (student, assignment)
};

PartFacts factsOf(const std::vector<LogEntry>& log) {
    PartFacts f;
    for (const LogEntry& e : log) {
        const QJsonObject o = parsed(e.payload);
        if (e.kind == "student")
            f.students[field(o, "id")] = e.payload;
        else if (e.kind == "assignment")
            f.assignments[field(o, "id")] = e.payload;
        else if (e.kind == "grade" || e.kind == "manual-score" || e.kind == "override")
            f.work.insert({field(o, "student"), field(o, "assignment")});
    }
    return f;
}

QJsonObject recordOf(const std::string& path, const std::vector<LogEntry>& log, const LogHead& head,
                     const std::vector<SignedHead>& signatures) {
    QJsonObject o;
    o.insert(QStringLiteral("file"), QString::fromStdString(nameOf(path)));
    o.insert(QStringLiteral("entries"), double(log.size()));
    o.insert(QStringLiteral("headSeq"), double(head.seq));
    o.insert(QStringLiteral("headHash"), QString::fromStdString(head.hash));
    QJsonArray signedHeads;
    for (const SignedHead& h : signatures) {
        QJsonObject s;
        s.insert(QStringLiteral("seq"), double(h.head.seq));
        s.insert(QStringLiteral("hash"), QString::fromStdString(h.head.hash));
        s.insert(QStringLiteral("publicKey"), QString::fromStdString(h.publicKey));
        s.insert(QStringLiteral("signature"), QString::fromStdString(h.signature));
        s.insert(QStringLiteral("at"), QString::fromStdString(h.at));
        signedHeads.append(s);
    }
    o.insert(QStringLiteral("signedHeads"), signedHeads);
    return o;
}

} // namespace

std::size_t shardOf(const std::string& student, std::size_t parts) {
    std::uint64_t h = 14695981039346656037ull; // FNV-1a 64
    for (unsigned char c : student) {
        h ^= c;
        h *= 1099511628211ull;
    }
    return parts ? std::size_t(h % parts) : 0;
}

std::optional<MergeSummary> mergeGradebooks(const std::vector<std::string>& sources,
                                            const std::string& out, std::string* why) {
    auto refuse = [&](std::string text) -> std::optional<MergeSummary> {
        if (why) *why = std::move(text);
        return std::nullopt;
    };
    namespace fs = std::filesystem;
    std::error_code ec;
    if (sources.empty()) return refuse("no gradebooks to merge");
    if (fs::exists(out, ec))
        return refuse(out + " exists: merge into a new file (the parts' entries would be mixed "
                            "into its own)");
    std::set<std::string> seen;
    for (const std::string& s : sources) {
        if (!fs::is_regular_file(s, ec)) return refuse(s + ": there is no gradebook there");
        const std::string canonical = fs::weakly_canonical(s, ec).string();
        if (!seen.insert(canonical).second) return refuse(s + " is named twice");
        if (canonical == fs::weakly_canonical(out, ec).string())
            return refuse(s + " is also the output");
    }

    // Each part read and verified: a part whose log does not hold is not merged.
    std::vector<std::vector<LogEntry>> logs;
    std::vector<PartFacts> facts;
    QJsonArray records;
    for (const std::string& s : sources) {
        try {
            Gradebook part(s, Gradebook::ReadOnly::Yes); // someone's file: never written
            const GradebookCheck check = part.verify();
            if (!check.intact) return refuse(s + ": its log does not verify: " + check.problem);
            logs.push_back(part.logEntries());
            facts.push_back(factsOf(logs.back()));
            records.append(recordOf(s, logs.back(), check.head, part.signedHeads()));
        } catch (const std::exception& e) { // not a gradebook, or one of a newer FunctionLab
            return refuse(s + ": " + e.what());
        }
    }

    // Parts must agree on whom and what they describe, and be disjoint in work.
    std::map<std::pair<std::string, std::string>, std::size_t> workOwner;
    for (std::size_t i = 0; i < facts.size(); ++i) {
        for (std::size_t j = 0; j < i; ++j) {
            for (const auto& [id, payload] : facts[i].students)
                if (auto it = facts[j].students.find(id);
                    it != facts[j].students.end() && it->second != payload)
                    return refuse("the student " + text::shownName(id) +
                                  " has another name or email in " + sources[i] + " than in " +
                                  sources[j] + ": import the same roster into every part");
            for (const auto& [id, payload] : facts[i].assignments)
                if (auto it = facts[j].assignments.find(id);
                    it != facts[j].assignments.end() && it->second != payload)
                    return refuse("the assignment " + text::shownName(id) + " is not the same in " +
                                  sources[i] + " as in " + sources[j] +
                                  " (title, points, due date or rubric): grade every part "
                                  "against the same assignment");
        }
        for (const auto& key : facts[i].work) {
            const auto [it, inserted] = workOwner.emplace(key, i);
            if (!inserted)
                return refuse("the work of " + text::shownName(key.first) + " on " +
                              text::shownName(key.second) + " is in both " + sources[it->second] +
                              " and " + sources[i] +
                              ": the parts of a class must be disjoint (grade batch --shard "
                              "K/N grades each student in one part only)");
        }
    }

    // Written beside the output, moved into place when complete.
    const fs::path partial = fs::path(out).string() + ".partial";
    removeGradebookFiles(partial.string());
    MergeSummary summary;
    try {
        {
            Gradebook merged(partial.string());
            for (const auto& log : logs)
                merged.appendFrom(log);
            QJsonObject record;
            record.insert(QStringLiteral("sources"), records);
            merged.appendFrom({{0,
                                utcNow(),
                                "merge",
                                QJsonDocument(record).toJson(QJsonDocument::Compact).toStdString(),
                                {}}});
            summary.sources = sources.size();
            summary.entries = merged.entries();
            summary.students = merged.students().size();
            for (const AssignmentRecord& a : merged.assignments())
                summary.grades += merged.latestGrades(a.id).size();
            summary.head = merged.head();
            const GradebookCheck check = merged.verify();
            if (!check.intact) throw platform::SqliteError("the merged log: " + check.problem);
        }
        // One file again (the write-ahead log folded in), then into place.
        {
            platform::SqliteDatabase db(partial.string());
            db.execute("PRAGMA wal_checkpoint(TRUNCATE)");
            db.execute("PRAGMA journal_mode = DELETE");
        }
        fs::rename(partial, out);
    } catch (const std::exception& e) {
        removeGradebookFiles(partial.string());
        return refuse(out + ": " + e.what());
    }
    return summary;
}

} // namespace fl::grading
