#pragma once
// Small class scenes the tests share.
#include <string>

namespace fl::classroom::test {

// X3D with the class shape on line 4: FGeometry `definition` as given.
inline std::string classScene(const std::string& definition) {
    return "<X3D profile='Immersive' version='3.3'>\n"
           "<Scene>\n"
           "<FShape DEF='CLASS'>\n"
           "<FGeometry type='implicit' definition='\"" +
           definition +
           "\"'/>\n"
           "</FShape>\n"
           "</Scene>\n"
           "</X3D>\n";
}

} // namespace fl::classroom::test
