#pragma once
// The Scene text panel: the editor of the scene's text with its find bar
// below. The window owns neither: it hands them in and keeps using them.
#include "panel.h"

namespace fl::editor {
class CodeEditor;
class FindBar;
} // namespace fl::editor

namespace fl::suite {

class SceneTextDock : public Panel {
    Q_OBJECT
  public:
    SceneTextDock(editor::CodeEditor* editor, editor::FindBar* find, QWidget* parent = nullptr);
};

} // namespace fl::suite
