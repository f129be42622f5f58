#include "export_actions.h"

#include "mesh/mesh_export.h"
#include "mesh/scene_meshing.h"
#include "panel_context.h"
#include "pde_import_dialog.h"
#include "viewer/scene_player.h"
#include "viewer/scene_widget.h"
#include "viewer/text_outliner.h"

#include <QDir>
#include <QFileDialog>
#include <QImage>
#include <QMenu>
#include <QStatusBar>

namespace fl::suite {

ExportActions::ExportActions(PanelContext& context, std::function<Parameters()> parameters,
                             QObject* parent)
    : QObject(parent), context_(context), parameters_(std::move(parameters)) {}

void ExportActions::fillMenu(QMenu* file) {
    file->addAction(tr("Import Mesh as &PDE…"), this, [this] {
        const QString path = QFileDialog::getOpenFileName(
            context_.window, tr("Import a mesh as PDE patches"), QDir::homePath(),
            tr("Wavefront OBJ meshes (*.obj);;All files (*)"));
        if (!path.isEmpty()) importMeshAsPde(path);
    });
    file->addAction(tr("Export &Mesh…"), this, &ExportActions::exportMesh);
    file->addAction(tr("Export &Image…"), this, &ExportActions::exportImage);
}

PdeImportDialog* ExportActions::importMeshAsPde(const QString& objPath) {
    auto* dialog = new PdeImportDialog(context_.window);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    // The file is read on a worker: the dialog opens at once and says it is
    // reading; a file that is not a mesh closes it and is said in the window.
    connect(dialog, &PdeImportDialog::loadFailed, this, [this, dialog](const QString& why) {
        dialog->close();
        context_.problem(why);
    });
    connect(dialog, &PdeImportDialog::sceneSaved, this, [this](const QString& scene) {
        if (context_.keepChanges()) context_.open(scene);
    });
    dialog->load(objPath);
    dialog->show();
    return dialog;
}

void ExportActions::exportMesh() {
    const auto scene = context_.scene();
    if (!scene)
        return context_.problem(tr("There is no scene to export yet: fix the errors listed first"));
    const QString path = QFileDialog::getSaveFileName(
        context_.window, tr("Export mesh"), QDir::homePath(),
        tr("glTF binary (*.glb);;STL (*.stl);;OBJ (*.obj);;PLY (*.ply);;X3D (*.x3d)"));
    if (path.isEmpty()) return;
    mesh::SceneMeshOptions o;
    o.sceneSeconds = context_.player->sceneSeconds();
    o.parameters = parameters_();
    o.text = viewer::qtTextOutliner();
    const mesh::SceneMeshes meshes = mesh::meshScene(*scene, o);
    std::string error;
    if (!mesh::writeMesh(mesh::mergeMeshes(meshes.shapes), path.toStdString(), error))
        context_.problem(QString::fromStdString(error));
    else
        context_.status->showMessage(tr("Wrote %1").arg(path), 5000);
}

void ExportActions::exportImage() {
    const QString path = QFileDialog::getSaveFileName(context_.window, tr("Export image"),
                                                      QDir::homePath(), tr("PNG image (*.png)"));
    if (path.isEmpty()) return;
    const QImage image = context_.view->grabFrame();
    if (image.isNull() || !image.save(path))
        context_.problem(tr("Cannot write the image %1").arg(path));
    else
        context_.status->showMessage(tr("Wrote %1").arg(path), 5000);
}

} // namespace fl::suite
