// Files other tools open: what `functionlab convert` and `functionlab mesh`
// write for every example, opened by the programs students hand them to.
//   view3dscene (Castle Game Engine): X3D and ClassicVRML open without an
//     error and draw a picture that is not blank;
//   the Khronos glTF validator (npm gltf-validator): .glb with 0 errors;
//   assimp (assimp-utils): STL, OBJ and PLY with the triangle count that
//     `functionlab mesh` reported.
// A missing tool skips its tests with a message saying how to install it
// (scripts/test installs them all); where FUNCTIONLAB_REQUIRE_TOOLS is set, as
// in CI, it fails them. CTest label: interop.
#include "../common/example_files.h"
#include "../common/required_tool.h"
#include "../common/tool_run.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QProcessEnvironment>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <ostream>
#include <string>
#include <vector>

namespace {

using fl::test::run;
using fl::test::ToolRun;

const QString kFunctionLab = QStringLiteral(FUNCTIONLAB_EXE);
const QString kExamples = QStringLiteral(FUNCTIONLAB_EXAMPLES_DIR);
const QString kOutDir = QStringLiteral(FUNCTIONLAB_INTEROP_OUT_DIR);
const QString kValidatorDir = QStringLiteral(FUNCTIONLAB_GLTF_VALIDATOR_DIR);
const QString kValidateScript = QStringLiteral(FUNCTIONLAB_VALIDATE_GLTF_SCRIPT);

QString tool(const QString& name) {
    return QStandardPaths::findExecutable(name);
}

// Every example scene, by file name (watermelon.x3d and watermelon.x3dv both).
std::vector<std::string> examples() {
    return fl::test::exampleFiles(kExamples);
}

std::string testName(const std::string& file) {
    return fl::test::exampleTestName(file);
}

QString outputPath(const std::string& example, const QString& suffix) {
    QDir().mkpath(kOutDir);
    return kOutDir + "/" + QString::fromStdString(testName(example)) + suffix;
}

// `functionlab mesh EXAMPLE -o OUT`: the triangle count it reports, or -1.
long long meshExample(const std::string& example, const QString& out, std::string& failure) {
    QFile::remove(out);
    const ToolRun r =
        run(kFunctionLab, {"mesh", kExamples + "/" + QString::fromStdString(example), "-o", out});
    if (r.exitCode != 0 || !QFileInfo::exists(out)) {
        failure = "functionlab mesh failed: " + r.describe();
        return -1;
    }
    static const QRegularExpression wrote(R"(wrote .* \(.*, (\d+) triangles\))");
    const QRegularExpressionMatch m = wrote.match(r.err);
    if (!m.hasMatch()) {
        failure = "functionlab mesh reported no triangle count: " + r.describe();
        return -1;
    }
    return m.captured(1).toLongLong();
}

// ---------------------------------------------------------------- view3dscene

// FunctionLab's own node types: view3dscene rightly warns that it does not
// know them (a converted scene keeps them; its preview is plain X3D).
const QString kFunctionNodeTypes =
    "F(?:Shape|Geometry|Appearance|Material|Texture3D|Physics|Surface|Friction|Tension|"
    "Density|Force|Transform)";

// The DEF names of function nodes in a written scene (either encoding): a
// ROUTE to one of them is lost with the node in a browser that skips it.
QStringList functionNodeNames(const QString& file) {
    QFile f(file);
    if (!f.open(QIODevice::ReadOnly)) return {};
    const QString text = QString::fromUtf8(f.readAll());
    const QRegularExpression xml("<" + kFunctionNodeTypes + R"(\b[^>]*\bDEF=['"]([^'"]+)['"])");
    const QRegularExpression classic(R"(\bDEF\s+(\S+)\s+)" + kFunctionNodeTypes + R"(\s*\{)");
    QStringList names;
    for (const QRegularExpression* re : {&xml, &classic}) {
        for (auto it = re->globalMatch(text); it.hasNext();)
            names << it.next().captured(1);
    }
    return names;
}

// A warning that is only about function nodes: their type named, or a ROUTE
// that ends at one of them.
bool isAboutFunctionNodes(const QString& line, const QStringList& functionNames) {
    static const QRegularExpression typeNamed("\"" + kFunctionNodeTypes + "\"");
    if (typeNamed.match(line).hasMatch()) return true;
    static const QRegularExpression route(
        R"re(Route (?:source|destination) node name "([^"]+)" not found)re");
    const QRegularExpressionMatch m = route.match(line);
    return m.hasMatch() && functionNames.contains(m.captured(1));
}

// Castle Game Engine's remark about its own start-up order, on every run.
bool isStartUpChatter(const QString& line) {
    return line.contains("Application.OnInitialize");
}

struct Picture {
    double coveredFraction = 0; // pixels that differ from the background corner
    int distinctColours = 0;
};

Picture measure(const QImage& image) {
    Picture p;
    if (image.isNull()) return p;
    const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
    const QRgb background = rgb.pixel(0, 0);
    long long covered = 0;
    std::vector<QRgb> seen;
    for (int y = 0; y < rgb.height(); ++y) {
        for (int x = 0; x < rgb.width(); ++x) {
            const QRgb c = rgb.pixel(x, y);
            const int d = std::abs(qRed(c) - qRed(background)) +
                          std::abs(qGreen(c) - qGreen(background)) +
                          std::abs(qBlue(c) - qBlue(background));
            if (d > 24) ++covered;
            if (seen.size() < 64 && std::find(seen.begin(), seen.end(), c) == seen.end())
                seen.push_back(c);
        }
    }
    p.coveredFraction = double(covered) / double(rgb.width() * rgb.height());
    p.distinctColours = int(seen.size());
    return p;
}

// Opens FILE in view3dscene (under xvfb-run when there is no display),
// takes a screenshot at time 0 and checks the three promises.
void expectView3dsceneShows(const QString& file) {
    const QString viewer = tool("view3dscene");
    if (viewer.isEmpty())
        FUNCTIONLAB_SKIP_WITHOUT_TOOL("view3dscene is not installed: apt-get install view3dscene "
                                      "(scripts/test installs it)");
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    QString program = viewer;
    QStringList arguments;
    if (env.value("DISPLAY").isEmpty()) {
        const QString xvfb = tool("xvfb-run");
        if (xvfb.isEmpty())
            FUNCTIONLAB_SKIP_WITHOUT_TOOL(
                "no display and no xvfb-run: apt-get install xvfb, or run under X");
        program = xvfb;
        arguments = {"-a", "-s", "-screen 0 800x600x24", viewer};
    }
    // Its log (where it reports errors and warnings) goes to a folder of our own.
    QTemporaryDir config;
    ASSERT_TRUE(config.isValid());
    env.insert("XDG_CONFIG_HOME", config.path());
    const QString png = file + ".png";
    QFile::remove(png);
    arguments << file << "--screenshot"
              << "0" << png;
    const ToolRun r = run(program, arguments, env);
    ASSERT_TRUE(r.started) << "could not start " << program.toStdString();
    ASSERT_TRUE(r.finished) << "view3dscene did not finish within 2 minutes";
    EXPECT_EQ(r.exitCode, 0) << r.describe();

    QFile logFile(config.path() + "/view3dscene/view3dscene.log");
    ASSERT_TRUE(logFile.open(QIODevice::ReadOnly)) << "view3dscene wrote no log";
    const QString log = QString::fromUtf8(logFile.readAll()) + "\n" + r.out + "\n" + r.err;
    const QStringList functionNames = functionNodeNames(file);
    for (const QString& line : log.split('\n')) {
        if (isStartUpChatter(line) || isAboutFunctionNodes(line, functionNames)) continue;
        EXPECT_FALSE(line.contains("error", Qt::CaseInsensitive))
            << "view3dscene: " << line.toStdString();
        EXPECT_FALSE(line.startsWith("Warning")) << "view3dscene: " << line.toStdString();
    }

    const QImage image(png);
    ASSERT_FALSE(image.isNull()) << "view3dscene wrote no screenshot " << png.toStdString();
    const Picture p = measure(image);
    EXPECT_GT(p.coveredFraction, 0.01)
        << png.toStdString() << ": the picture is blank (background only)";
    EXPECT_GE(p.distinctColours, 8) << png.toStdString() << ": a flat picture, nothing shaded";
}

class View3dscene : public testing::TestWithParam<std::string> {};

// `functionlab convert EXAMPLE OUT` with OUT ending in `suffix`, opened in view3dscene.
void expectConvertedShows(const std::string& example, const QString& suffix) {
    const QString out = outputPath(example, suffix);
    const ToolRun r =
        run(kFunctionLab, {"convert", kExamples + "/" + QString::fromStdString(example), out});
    ASSERT_EQ(r.exitCode, 0) << r.describe();
    expectView3dsceneShows(out);
}

TEST_P(View3dscene, OpensTheConvertedX3d) {
    expectConvertedShows(GetParam(), "-converted.x3d");
}

TEST_P(View3dscene, OpensTheConvertedClassicVrml) {
    expectConvertedShows(GetParam(), "-converted.x3dv");
}

TEST_P(View3dscene, OpensTheMeshAsX3d) {
    std::string failure;
    const QString out = outputPath(GetParam(), "-mesh.x3d");
    ASSERT_GT(meshExample(GetParam(), out, failure), 0) << failure;
    expectView3dsceneShows(out);
}

INSTANTIATE_TEST_SUITE_P(Examples, View3dscene, testing::ValuesIn(examples()),
                         [](const auto& info) { return testName(info.param); });

// ------------------------------------------------------------ glTF validator

class GltfValidator : public testing::TestWithParam<std::string> {};

TEST_P(GltfValidator, FindsNoErrors) {
    const QString node = tool("node").isEmpty() ? tool("nodejs") : tool("node");
    if (node.isEmpty())
        FUNCTIONLAB_SKIP_WITHOUT_TOOL(
            "Node.js is not installed: apt-get install nodejs npm (scripts/test does)");
    if (!QFileInfo::exists(kValidatorDir + "/package.json"))
        FUNCTIONLAB_SKIP_WITHOUT_TOOL(
            "the glTF validator is not installed at "
            << kValidatorDir.toStdString()
            << ": scripts/test installs it (npm ci in build/interop-tools)");
    std::string failure;
    const QString out = outputPath(GetParam(), ".glb");
    const long long triangles = meshExample(GetParam(), out, failure);
    ASSERT_GT(triangles, 0) << failure;
    const ToolRun r = run(node, {kValidateScript, kValidatorDir, out});
    ASSERT_EQ(r.exitCode, 0) << r.describe();
    const QJsonObject report = QJsonDocument::fromJson(r.out.toUtf8()).object();
    ASSERT_TRUE(report.contains("issues")) << "no report: " << r.describe();
    const QJsonObject issues = report["issues"].toObject();
    EXPECT_EQ(issues["numErrors"].toInt(-1), 0)
        << out.toStdString() << ": "
        << QJsonDocument(issues["messages"].toArray()).toJson(QJsonDocument::Compact).toStdString();
    // The validator counts the triangles too: the same as mesh reported.
    EXPECT_EQ(report["info"].toObject()["totalTriangleCount"].toVariant().toLongLong(), triangles);
}

INSTANTIATE_TEST_SUITE_P(Examples, GltfValidator, testing::ValuesIn(examples()),
                         [](const auto& info) { return testName(info.param); });

// -------------------------------------------------------------------- assimp

struct MeshFile {
    std::string example;
    std::string extension; // stl, obj, ply
};

void PrintTo(const MeshFile& f, std::ostream* os) {
    *os << f.example << " as ." << f.extension;
}

class Assimp : public testing::TestWithParam<MeshFile> {};

TEST_P(Assimp, CountsTheReportedTriangles) {
    const QString assimp = tool("assimp");
    if (assimp.isEmpty())
        FUNCTIONLAB_SKIP_WITHOUT_TOOL(
            "assimp is not installed: apt-get install assimp-utils (scripts/test does)");
    std::string failure;
    const QString out =
        outputPath(GetParam().example, "." + QString::fromStdString(GetParam().extension));
    const long long triangles = meshExample(GetParam().example, out, failure);
    ASSERT_GT(triangles, 0) << failure;
    const ToolRun r = run(assimp, {"info", out});
    ASSERT_EQ(r.exitCode, 0) << r.describe();
    static const QRegularExpression faces(R"(^Faces:\s+(\d+)\s*$)",
                                          QRegularExpression::MultilineOption);
    const QRegularExpressionMatch f = faces.match(r.out);
    ASSERT_TRUE(f.hasMatch()) << "assimp printed no face count: " << r.describe();
    EXPECT_EQ(f.captured(1).toLongLong(), triangles) << out.toStdString();
}

std::vector<MeshFile> meshFiles() {
    std::vector<MeshFile> files;
    for (const std::string& e : examples())
        for (const char* ext : {"stl", "obj", "ply"})
            files.push_back({e, ext});
    return files;
}

INSTANTIATE_TEST_SUITE_P(Examples, Assimp, testing::ValuesIn(meshFiles()), [](const auto& info) {
    return testName(info.param.example) + "_" + info.param.extension;
});

} // namespace

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
