#pragma once
// Writes a Scene as X3D XML, ClassicVRML or VRML97. Only fields given in the
// file are written (defaults stay implicit); PROTO instances are written as
// instances, not as their expansion; unknown nodes and fields are written
// back as they were read.
#include "scene.h"

#include <string>

namespace fl::scene {

std::string writeXml(const Scene& scene);
std::string writeClassic(const Scene& scene, Encoding encoding = Encoding::ClassicVrml);
std::string writeScene(const Scene& scene, Encoding encoding);

// The encoding a file name asks for (.x3d, .x3dv, .wrl, with .gz or
// .x3dz/.x3dvz/.wrz for gzip); false when the extension is not a scene's.
bool encodingForPath(const std::string& path, Encoding& encoding, bool& gzipped);

// A scene file's name: one of those extensions after at least one character
// (the one list: the window, the grader and the batch ask here).
bool isSceneFileName(const std::string& name);

// The extensions as file-dialog patterns: "*.x3d *.x3dv *.wrl *.x3d.gz ...".
std::string sceneFilePatterns();

// Shortest text that reads back as exactly the same double.
std::string formatNumber(double v);

// Text as an X3D XML attribute value holds it: & < > ' " escaped, and the
// line breaks and tabs attribute normalization would fold, as character
// references. Valid in HTML5 text and attributes as well (grade reports).
std::string xmlEscape(std::string_view s);
// The same inside an attribute delimited by `quote` (' or "): the other
// quote is left as it is, so a definition reads as the student wrote it.
std::string xmlAttributeText(std::string_view s, char quote);

// A string as X3D writes it inside an SFString or MFString: in double
// quotes, with " and \ escaped by a backslash.
std::string quotedString(std::string_view s);

} // namespace fl::scene
