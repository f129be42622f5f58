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
#include <map>

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
            if (colon != std::string::npos && !line.starts_with("roundtrip "))
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
        bool located = false;
        for (const auto& d : r.diagnostics)
            located |= d.severity == Severity::Error && d.pos.line > 0;
        EXPECT_TRUE(located) << "no error with a line:column\n" << all;
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
