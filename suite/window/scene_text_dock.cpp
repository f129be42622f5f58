#include "scene_text_dock.h"

#include "editor/code_editor.h"
#include "editor/find_bar.h"

#include <QVBoxLayout>

namespace fl::suite {

SceneTextDock::SceneTextDock(editor::CodeEditor* editor, editor::FindBar* find, QWidget* parent)
    : Panel(tr("Scene text"), QStringLiteral("editor"), Qt::LeftDockWidgetArea, parent) {
    auto* panel = new QWidget;
    auto* column = new QVBoxLayout(panel);
    column->setContentsMargins(0, 0, 0, 0);
    column->addWidget(editor, 1);
    column->addWidget(find);
    setWidget(panel);
    // Room for a formula line, while leaving the view the most on a 1366-pixel
    // screen (the window widens it to about a quarter of its width).
    setMinimumWidth(320);
}

} // namespace fl::suite
