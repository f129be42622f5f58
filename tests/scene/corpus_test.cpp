// Every file of the public corpus (../shared/corpus) is a test: files in `bad`
// folders and those listed in corpus_expectations.txt are rejected with a
// located error; every other file loads; and every file that loads is written
// as X3D XML and as ClassicVRML and read back as the same model.
#include "scene/scene_builder.h"
#include "scene/scene_compare.h"
#include "scene/scene_reader.h"
#include "scene/scene_writer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <regex>
#include <sstream>

namespace fs = std::filesystem;
using namespace fl::scene;

namespace {

const fs::path kCorpus = FUNCTIONLAB_CORPUS_DIR;
const fs::path kExpectations = FUNCTIONLAB_CORPUS_EXPECTATIONS;

bool isSceneFile(const fs::path& p) {
    const std::string s = p.filename().string();
    for (const char* ext : {".wrl", ".x3d", ".x3dv", ".gz", ".x3dvz", ".x3dz", ".wrz"})
        if (s.size() > std::strlen(ext) && s.ends_with(ext)) return true;
    return false;
}

std::vector<std::string> corpusFiles() {
    std::vector<std::string> files;
    std::error_code ec;
    if (!fs::is_directory(kCorpus, ec)) return files;
    for (auto it = fs::recursive_directory_iterator(kCorpus, ec); it != fs::end(it);
         it.increment(ec))
        if (it->is_regular_file() && isSceneFile(it->path()))
            files.push_back(fs::relative(it->path(), kCorpus).generic_string());
    std::sort(files.begin(), files.end());
    return files;
}

// path -> reason, for files outside `bad` folders that must be rejected.
const std::map<std::string, std::string>& expectedRejections() {
    static const std::map<std::string, std::string> table = [] {
        std::map<std::string, std::string> t;
        std::ifstream in(kExpectations);
        std::string line;
        while (std::getline(in, line)) {
            if (line.empty() || line[0] == '#') continue;
            const auto colon = line.find(": ");
            if (colon != std::string::npos && !line.starts_with("roundtrip ") &&
                !line.starts_with("fixedpoint "))
                t[line.substr(0, colon)] = line.substr(colon + 2);
        }
        return t;
    }();
    return table;
}

// path -> reason, for files whose round trip is a known, open defect.
const std::map<std::string, std::string>& knownRoundTripGaps() {
    static const std::map<std::string, std::string> table = [] {
        std::map<std::string, std::string> t;
        std::ifstream in(kExpectations);
        std::string line;
        while (std::getline(in, line)) {
            if (!line.starts_with("roundtrip ")) continue;
            const auto colon = line.find(": ");
            if (colon != std::string::npos) t[line.substr(10, colon - 10)] = line.substr(colon + 2);
        }
        return t;
    }();
    return table;
}

// path -> (line:column, start of the message) of its first error.
const std::map<std::string, std::pair<std::string, std::string>>& expectedRejectionPlaces() {
    static const std::map<std::string, std::pair<std::string, std::string>> table = [] {
        std::map<std::string, std::pair<std::string, std::string>> t;
        std::ifstream in(FUNCTIONLAB_CORPUS_REJECTIONS);
        std::string line;
        while (std::getline(in, line)) {
            if (line.empty() || line[0] == '#') continue;
            const auto a = line.find(' '), b = line.find(' ', a + 1);
            if (a == std::string::npos || b == std::string::npos) continue;
            t[line.substr(0, a)] = {line.substr(a + 1, b - a - 1), line.substr(b + 1)};
        }
        return t;
    }();
    return table;
}

bool mustReject(const std::string& file) {
    return file.find("/bad/") != std::string::npos || expectedRejections().count(file) > 0;
}

std::string testName(const testing::TestParamInfo<std::string>& info) {
    std::string name;
    for (char c : info.param)
        name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    return name;
}

class Corpus : public testing::TestWithParam<std::string> {};

TEST_P(Corpus, LoadsOrIsRejectedWithALocatedError) {
    const std::string file = GetParam();
    ReadResult r = readSceneFile(kCorpus / file);
    std::string all;
    for (const auto& d : r.diagnostics)
        all += formatSceneDiagnostic(d) + "\n";
    if (mustReject(file)) {
        EXPECT_FALSE(r.ok()) << file << " should be rejected ("
                             << (expectedRejections().count(file) ? expectedRejections().at(file)
                                                                  : std::string("bad folder"))
                             << ")";
        // The first error stands where corpus_rejections.txt says, for the
        // reason it says.
        const auto expected = expectedRejectionPlaces().find(file);
        ASSERT_NE(expected, expectedRejectionPlaces().end())
            << file << " is not in corpus_rejections.txt\n"
            << all;
        const SceneDiagnostic* first = nullptr;
        for (const auto& d : r.diagnostics)
            if (d.severity == Severity::Error && !first) first = &d;
        ASSERT_NE(first, nullptr) << all;
        EXPECT_EQ(std::to_string(first->pos.line) + ":" + std::to_string(first->pos.column),
                  expected->second.first)
            << formatSceneDiagnostic(*first);
        EXPECT_TRUE(first->message.starts_with(expected->second.second))
            << "expected '" << expected->second.second << "', got: " << first->message;
    } else {
        EXPECT_TRUE(r.ok()) << file << " should load\n" << all;
    }
}

TEST_P(Corpus, WritingThenReadingGivesTheSameModel) {
    const std::string file = GetParam();
    ReadOptions options;
    options.compileFunctions = false;
    ReadResult r = readSceneFile(kCorpus / file, options);
    if (!r.ok()) GTEST_SKIP() << "does not load";
    if (knownRoundTripGaps().count(file))
        GTEST_SKIP() << "known round-trip gap: " << knownRoundTripGaps().at(file);
    for (Encoding e : {Encoding::Xml, Encoding::ClassicVrml}) {
        const std::string text = writeScene(*r.scene, e);
        ReadResult back = readSceneBytes(
            text, "written." + std::string(e == Encoding::Xml ? "x3d" : "x3dv"), options);
        std::string all;
        for (const auto& d : back.diagnostics)
            if (d.severity == Severity::Error) all += formatSceneDiagnostic(d) + "\n";
        ASSERT_TRUE(back.ok()) << "written as " << encodingName(e) << ", it does not read back:\n"
                               << all << "\n--- written text (start) ---\n"
                               << text.substr(0, 3000);
        std::string difference;
        EXPECT_TRUE(sameModel(*r.scene, *back.scene, &difference))
            << "written as " << encodingName(e) << ": " << difference;
    }
}

// Lines that may stand in one ClassicVRML text and not the other, each a
// regular expression over a trimmed line with its reason
// (corpus_expectations.txt, "fixedpoint REGEX: reason").
const std::vector<std::pair<std::regex, std::string>>& acceptedTextDifferences() {
    static const std::vector<std::pair<std::regex, std::string>> list = [] {
        std::vector<std::pair<std::regex, std::string>> l;
        std::ifstream in(kExpectations);
        std::string line;
        while (std::getline(in, line)) {
            if (!line.starts_with("fixedpoint ")) continue;
            const auto colon = line.rfind(": ");
            if (colon != std::string::npos)
                l.emplace_back(std::regex(line.substr(11, colon - 11)), line.substr(colon + 2));
        }
        return l;
    }();
    return list;
}

// The text's lines, each trimmed, as a sorted list. The writer puts every
// field, declaration, IS, ROUTE and node header on a line of its own, so two
// texts with the same lines hold the same values; sorting forgives only the
// order of a node's fields, which X3D XML attributes do not keep. Lines an
// accepted difference names are left out first, and a node they leave empty
// ("Group {" then "}") is written as the writer writes one ("Group { }").
std::vector<std::string> normalisedLines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        const auto a = line.find_first_not_of(" \t\r");
        if (a == std::string::npos) continue;
        line = line.substr(a, line.find_last_not_of(" \t\r") - a + 1);
        const bool accepted = std::any_of(
            acceptedTextDifferences().begin(), acceptedTextDifferences().end(),
            [&](const auto& difference) { return std::regex_match(line, difference.first); });
        if (accepted) continue;
        if (line == "}" && !lines.empty() && lines.back().ends_with(" {")) {
            lines.back() += " }";
            continue;
        }
        lines.push_back(line);
    }
    std::sort(lines.begin(), lines.end());
    return lines;
}

// Lines of `a` missing from `b`.
std::vector<std::string> unexplained(const std::vector<std::string>& a,
                                     const std::vector<std::string>& b) {
    std::vector<std::string> only;
    std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(only));
    return only;
}

std::string written(const Scene& scene, Encoding e, const std::string& name,
                    std::unique_ptr<Scene>* back) {
    ReadOptions options;
    options.compileFunctions = false;
    const std::string text = writeScene(scene, e);
    ReadResult r = readSceneBytes(text, name, options);
    if (back) *back = std::move(r.scene);
    return text;
}

// Issue 20: A -> ClassicVRML -> X3D XML -> ClassicVRML holds the same lines
// (and VRML97 where the file is VRML97): no encoding drops a user's value.
TEST_P(Corpus, ClassicTextSurvivesXml) {
    const std::string file = GetParam();
    ReadOptions options;
    options.compileFunctions = false;
    ReadResult r = readSceneFile(kCorpus / file, options);
    if (!r.ok()) GTEST_SKIP() << "does not load";
    std::unique_ptr<Scene> classic, xml, again;
    const std::string first = written(*r.scene, Encoding::ClassicVrml, "a.x3dv", &classic);
    ASSERT_TRUE(classic) << "the ClassicVRML text does not read back";
    written(*classic, Encoding::Xml, "b.x3d", &xml);
    ASSERT_TRUE(xml) << "the X3D XML text does not read back";
    const std::string second = written(*xml, Encoding::ClassicVrml, "c.x3dv", &again);
    ASSERT_TRUE(again);
    const auto a = normalisedLines(first), b = normalisedLines(second);
    for (const std::string& line : unexplained(a, b))
        ADD_FAILURE() << "lost through X3D XML: " << line;
    for (const std::string& line : unexplained(b, a))
        ADD_FAILURE() << "appeared through X3D XML: " << line;
    if (r.scene->encoding == Encoding::Vrml97) {
        std::unique_ptr<Scene> vrml97;
        written(*again, Encoding::Vrml97, "d.wrl", &vrml97);
        ASSERT_TRUE(vrml97) << "the VRML97 text does not read back";
        const std::string third = written(*vrml97, Encoding::ClassicVrml, "e.x3dv", nullptr);
        const auto c = normalisedLines(third);
        for (const std::string& line : unexplained(b, c))
            ADD_FAILURE() << "lost through VRML97: " << line;
        for (const std::string& line : unexplained(c, b))
            ADD_FAILURE() << "appeared through VRML97: " << line;
    }
}

INSTANTIATE_TEST_SUITE_P(Files, Corpus, testing::ValuesIn(corpusFiles()), testName);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(Corpus);

TEST(CorpusManifest, EveryListedFileExists) {
    const auto files = corpusFiles();
    if (files.empty()) GTEST_SKIP() << "no corpus at " << kCorpus;
    for (const auto& [file, reason] : knownRoundTripGaps())
        EXPECT_TRUE(std::binary_search(files.begin(), files.end(), file)) << file;
    for (const auto& [file, reason] : expectedRejections())
        EXPECT_TRUE(std::binary_search(files.begin(), files.end(), file))
            << file << " is listed in corpus_expectations.txt but not in the corpus";
}

} // namespace
