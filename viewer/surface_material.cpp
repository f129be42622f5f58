#include "surface_material.h"

#include <Qt3DRender/QBlendEquation>
#include <Qt3DRender/QBlendEquationArguments>
#include <Qt3DRender/QCullFace>
#include <Qt3DRender/QDepthTest>
#include <Qt3DRender/QEffect>
#include <Qt3DRender/QFilterKey>
#include <Qt3DRender/QGraphicsApiFilter>
#include <Qt3DRender/QNoDepthMask>
#include <Qt3DRender/QPaintedTextureImage>
#include <Qt3DRender/QParameter>
#include <Qt3DRender/QPointSize>
#include <Qt3DRender/QRenderPass>
#include <Qt3DRender/QTechnique>
#include <Qt3DRender/QTexture>
#include <Qt3DRender/QTextureWrapMode>

#include <QColor>
#include <QPainter>
#include <QUrl>
#include <QVector3D>

static void initViewerResources() {
    Q_INIT_RESOURCE(viewer);
}

namespace fl::viewer {
namespace {

QVector3D vec(const std::array<float, 3>& v) {
    return {v[0], v[1], v[2]};
}

// A decoded image handed to Qt3D. Painted upside down: OpenGL's texture rows
// start at the bottom (t = 0), a QImage's at the top.
class PaintedImage : public Qt3DRender::QPaintedTextureImage {
  public:
    PaintedImage(QImage image, Qt3DCore::QNode* parent)
        : QPaintedTextureImage(parent), image_(std::move(image)) {
        setSize(image_.size());
    }

  protected:
    void paint(QPainter* painter) override {
        painter->setCompositionMode(QPainter::CompositionMode_Source);
        painter->drawImage(0, 0, image_.mirrored(false, true));
    }

  private:
    QImage image_;
};

} // namespace

Qt3DRender::QShaderProgram* makeSurfaceShader(Qt3DCore::QNode* parent) {
    initViewerResources();
    auto* shader = new Qt3DRender::QShaderProgram(parent);
    shader->setVertexShaderCode(Qt3DRender::QShaderProgram::loadSource(
        QUrl(QStringLiteral("qrc:/functionlab/viewer/shaders/surface.vert"))));
    shader->setFragmentShaderCode(Qt3DRender::QShaderProgram::loadSource(
        QUrl(QStringLiteral("qrc:/functionlab/viewer/shaders/surface.frag"))));
    return shader;
}

SurfaceMaterial::SurfaceMaterial(const mesh::SurfaceLook& look, const SurfaceOptions& options,
                                 Qt3DRender::QShaderProgram* shader, Qt3DCore::QNode* parent)
    : QMaterial(parent) {
    auto* effect = new Qt3DRender::QEffect(this);
    auto* technique = new Qt3DRender::QTechnique(effect);
    technique->graphicsApiFilter()->setApi(Qt3DRender::QGraphicsApiFilter::OpenGL);
    technique->graphicsApiFilter()->setProfile(Qt3DRender::QGraphicsApiFilter::CoreProfile);
    technique->graphicsApiFilter()->setMajorVersion(3);
    technique->graphicsApiFilter()->setMinorVersion(3);

    auto* pass = new Qt3DRender::QRenderPass(technique);
    pass->setShaderProgram(shader);
    auto* key = new Qt3DRender::QFilterKey(pass);
    key->setName(QString::fromLatin1(kPassKey));
    key->setValue(QString::fromLatin1(options.transparent ? kTransparentPass : kOpaquePass));
    pass->addFilterKey(key);

    auto* depth = new Qt3DRender::QDepthTest(pass);
    depth->setDepthFunction(Qt3DRender::QDepthTest::LessOrEqual);
    pass->addRenderState(depth);
    // X3D `solid`: only the front faces (a see-through solid too: light
    // passes its front once); else both, lit from the side seen.
    auto* cull = new Qt3DRender::QCullFace(pass);
    const bool solid = look.solid && !options.bothSides;
    cull->setMode(solid ? Qt3DRender::QCullFace::Back : Qt3DRender::QCullFace::NoCulling);
    pass->addRenderState(cull);
    if (options.transparent) {
        auto* blend = new Qt3DRender::QBlendEquationArguments(pass);
        blend->setSourceRgb(Qt3DRender::QBlendEquationArguments::SourceAlpha);
        blend->setDestinationRgb(Qt3DRender::QBlendEquationArguments::OneMinusSourceAlpha);
        blend->setSourceAlpha(Qt3DRender::QBlendEquationArguments::One);
        blend->setDestinationAlpha(Qt3DRender::QBlendEquationArguments::OneMinusSourceAlpha);
        pass->addRenderState(blend);
        auto* equation = new Qt3DRender::QBlendEquation(pass);
        equation->setBlendFunction(Qt3DRender::QBlendEquation::Add);
        pass->addRenderState(equation);
        pass->addRenderState(new Qt3DRender::QNoDepthMask(pass));
    }
    if (options.points) {
        auto* size = new Qt3DRender::QPointSize(pass);
        size->setSizeMode(Qt3DRender::QPointSize::Programmable);
        pass->addRenderState(size);
    }
    technique->addRenderPass(pass);
    effect->addTechnique(technique);
    setEffect(effect);

    auto param = [this](const char* name, const QVariant& value) {
        addParameter(new Qt3DRender::QParameter(QString::fromLatin1(name), value, this));
    };
    param("lit", look.lit ? 1 : 0);
    param("emissive", vec(look.emissive));
    param("specular", vec(look.specular));
    param("shininess", look.shininess);
    param("ambientIntensity", look.ambientIntensity);
    param("twoSided", solid ? 0 : 1);
    param("pointSize", options.pointSize);
    // X3D 17.2.2.4: an intensity image (1 or 2 components) brightens the
    // diffuse colour; a colour image replaces it.
    int textured = 0;
    if (options.texture && look.texture) {
        textured = options.texture->components <= 2 ? 1 : 3;
        auto* texture = new Qt3DRender::QTexture2D(this);
        texture->addTextureImage(new PaintedImage(options.texture->image, texture));
        texture->setGenerateMipMaps(true);
        texture->setMinificationFilter(Qt3DRender::QAbstractTexture::LinearMipMapLinear);
        texture->setMagnificationFilter(Qt3DRender::QAbstractTexture::Linear);
        const auto wrap = [](bool repeat) {
            return repeat ? Qt3DRender::QTextureWrapMode::Repeat
                          : Qt3DRender::QTextureWrapMode::ClampToEdge;
        };
        texture->wrapMode()->setX(wrap(look.texture->repeatS));
        texture->wrapMode()->setY(wrap(look.texture->repeatT));
        param("diffuseTexture", QVariant::fromValue(texture));
    }
    param("textured", textured);
}

} // namespace fl::viewer
