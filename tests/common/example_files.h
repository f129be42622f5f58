#pragma once
// The example scenes the outside-tool tests run over (interop, web): every
// .x3d, .x3dv and .wrl of a folder by name, and a test name for each.
#include <QDir>
#include <QString>
#include <QStringList>

#include <algorithm>
#include <string>
#include <vector>

namespace fl::test {

inline std::vector<std::string> exampleFiles(const QString& folder) {
    std::vector<std::string> names;
    for (const QString& f :
         QDir(folder).entryList({"*.x3d", "*.x3dv", "*.wrl"}, QDir::Files, QDir::Name))
        names.push_back(f.toStdString());
    return names;
}

// "watermelon.x3dv" -> "watermelon_x3dv": a gtest parameter name.
inline std::string exampleTestName(const std::string& file) {
    std::string s = file;
    std::replace(s.begin(), s.end(), '.', '_');
    return s;
}

} // namespace fl::test
