#pragma once
// File → Export Mesh (glTF, STL, OBJ, PLY, X3D: the scene at the time and
// slider values shown, all shapes merged) and Export Image (the view's frame).
#include <QObject>

#include <functional>
#include <string>
#include <utility>
#include <vector>

class QMenu;

namespace fl::suite {

class PanelContext;

class ExportActions : public QObject {
    Q_OBJECT
  public:
    using Parameters = std::vector<std::pair<std::string, double>>;
    ExportActions(PanelContext& context, std::function<Parameters()> parameters,
                  QObject* parent = nullptr);

    void fillMenu(QMenu* file);

  private:
    void exportMesh();
    void exportImage();

    PanelContext& context_;
    std::function<Parameters()> parameters_;
};

} // namespace fl::suite
