#pragma once
// The folder `functionlab export-web` writes (issue 32 §1): a static page any
// current browser opens from a web server or straight from the file system,
// with no network: index.html, the baked scene as X3D (scene.x3d, and the
// same text in scene.js for a page opened from a file, which may not fetch),
// X_ITE and the page's own script in viewer/, the files the scene names in
// files/, and the scene's own source in source/.
#include "web_bake.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace fl::web {

// Where X_ITE's dist folder is: $FUNCTIONLAB_X_ITE_DIR, else the copy
// scripts/run installed from npm at build time (web/package-lock.json pins
// it), else beside an installed functionlab (share/functionlab/x_ite).
// None, with `why` saying what to do, when no folder holds x_ite.min.js.
std::optional<std::filesystem::path> findXite(std::string& why);

struct PageOptions {
    std::filesystem::path xIteDir;   // X_ITE's dist folder (findXite)
    std::vector<double> resolutions; // said on the page
    int frames = 0;                  // said on the page (0: nothing varies)
};

struct PageResult {
    std::vector<std::filesystem::path> written; // relative to the folder
    std::size_t bytes = 0;
};

// Writes the folder; false with `error` (naming the file) when a file cannot
// be written or read. Files already there are replaced, others left alone.
bool writeWebFolder(const BakeResult& baked, const scene::Scene& source,
                    const std::filesystem::path& dir, const PageOptions& options,
                    PageResult& result, std::string& error);

// The baked scene's X3D text with each image it names (files/...) carried
// inside as a data: url, as the page's own copy has it (scene.js): a page
// opened from a file may not fetch, but may read data: urls.
std::string withImagesInside(std::string x3d, const BakeResult& baked);

// Text as a JavaScript string literal that is safe anywhere in a page:
// quotes, backslashes, line ends, control characters and '<' escaped.
std::string javaScriptString(std::string_view text);
// Text as HTML element content or a quoted attribute value (the scene
// writer's XML escaping, valid in HTML5); control characters other than tab
// and newline are dropped.
std::string htmlText(std::string_view text);

} // namespace fl::web
