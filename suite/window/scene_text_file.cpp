#include "scene_text_file.h"

#include "scene/gzip.h"

#include <QCoreApplication>
#include <QFile>
#include <QSaveFile>

namespace fl::suite {
namespace {

constexpr qint64 kMaxFileBytes = 64ll << 20;

QString tr(const char* text) {
    return QCoreApplication::translate("SceneTextFile", text);
}

} // namespace

std::optional<QString> readSceneText(const QString& path, QString& problem) {
    const QString tooBig =
        tr("%1 is larger than 64 MiB; FunctionLab does not edit files this big").arg(path);
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        problem = tr("Cannot open %1: %2").arg(path, f.errorString());
        return std::nullopt;
    }
    if (f.size() > kMaxFileBytes) {
        problem = tooBig;
        return std::nullopt;
    }
    QByteArray bytes = f.read(kMaxFileBytes + 1); // a device without a size cannot run on
    if (bytes.size() > kMaxFileBytes) {
        problem = tooBig;
        return std::nullopt;
    }
    const std::string_view view(bytes.constData(), std::size_t(bytes.size()));
    if (scene::isGzip(view)) {
        std::string why;
        auto text = scene::gunzip(view, std::size_t(kMaxFileBytes), why);
        if (!text) {
            problem = tr("Cannot read %1: %2").arg(path, QString::fromStdString(why));
            return std::nullopt;
        }
        bytes = QByteArray::fromStdString(*text);
    }
    return QString::fromUtf8(bytes);
}

bool writeSceneText(const QString& path, const QString& text, QString& problem) {
    QSaveFile out(path);
    if (!out.open(QIODevice::WriteOnly) || out.write(text.toUtf8()) < 0 || !out.commit()) {
        problem = tr("Cannot save %1: %2").arg(path, out.errorString());
        return false;
    }
    return true;
}

QString newSceneText() {
    return QStringLiteral(R"(<?xml version="1.0" encoding="UTF-8"?>
<X3D profile='Immersive' version='3.3'>
  <Scene>
    <Viewpoint description='Front' position='0 0 4'/>
    <FShape>
      <FGeometry definition='"1 - x^2 - y^2 - z^2"'/>
      <FAppearance>
        <FMaterial type='parametric' definition='"r = 0.5 + 0.5*x;" "g = 0.6;" "b = 0.5 - 0.5*x;"'/>
      </FAppearance>
    </FShape>
  </Scene>
</X3D>
)");
}

} // namespace fl::suite
