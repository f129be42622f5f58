#pragma once
// File → Import Mesh as PDE (a polygon mesh fitted as PDE patches, then
// opened as a scene: PdeImportDialog), Export Mesh (glTF, STL, OBJ, PLY,
// X3D: the scene at the time and slider values shown, all shapes merged)
// and Export Image (the view's frame).
#include <QObject>
#include <QString>

#include <functional>
#include <string>
#include <utility>
#include <vector>

class QMenu;

namespace fl::suite {

class PanelContext;
class PdeImportDialog;

class ExportActions : public QObject {
    Q_OBJECT
  public:
    using Parameters = std::vector<std::pair<std::string, double>>;
    ExportActions(PanelContext& context, std::function<Parameters()> parameters,
                  QObject* parent = nullptr);

    void fillMenu(QMenu* file);

    // Opens the import dialog on this mesh (the menu asks for the file); it
    // reads the file on a worker, and closes with the window told why when
    // the file is not a mesh it can fit.
    PdeImportDialog* importMeshAsPde(const QString& objPath);

  private:
    void exportMesh();
    void exportImage();

    PanelContext& context_;
    std::function<Parameters()> parameters_;
};

} // namespace fl::suite
