// Friction and density as colour (haptics/effect_colours.h): the value the
// servo loop would feel at each vertex, through the effect's domain box.
#include "haptics/effect_colours.h"

#include "mesh/scene_meshing.h"
#include "scene/scene_reader.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace fl;
using namespace fl::haptics;

TEST(EffectColours, BlueGreenRedFromNothingToOneAndGreyForNaN) {
    EXPECT_EQ(effectColour(0), (std::array<float, 4>{0, 0, 1, 1}));
    EXPECT_EQ(effectColour(0.5), (std::array<float, 4>{0, 1, 0, 1}));
    EXPECT_EQ(effectColour(1), (std::array<float, 4>{1, 0, 0, 1}));
    EXPECT_EQ(effectColour(7), effectColour(1));
    EXPECT_EQ(effectColour(-1), effectColour(0));
    EXPECT_EQ(effectColour(std::nan("")), (std::array<float, 4>{0.5f, 0.5f, 0.5f, 1}));
}

TEST(EffectColours, TheWatermelonsRindIsDenserThanItsFlesh) {
    auto r = scene::readSceneFile(std::string(FUNCTIONLAB_EXAMPLES_DIR) + "/watermelon.x3d");
    ASSERT_TRUE(r.ok());
    mesh::SceneMeshOptions o;
    o.useFileResolution = false;
    o.mesh.resolution = 24;
    o.placeInScene = false;
    const mesh::SceneMeshes frame = mesh::meshScene(*r.scene, o);
    const TangibleScene tangible = makeTangibleScene(*r.scene, 0);
    const auto coloured = colouredByEffect(frame, tangible, scene::TangibleKind::Density);
    ASSERT_EQ(coloured->shapes.size(), 1u);
    const mesh::Mesh& m = coloured->shapes[0].mesh;
    ASSERT_EQ(m.colours.size(), m.positions.size());
    std::size_t rind = 0, flesh = 0;
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        const auto& p = m.positions[i];
        const double d = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        if (d > 0.95) {
            EXPECT_EQ(m.colours[i], effectColour(0.8)) << d; // the rind's 0.8
            ++rind;
        } else if (d < 0.85) {
            EXPECT_LT(m.colours[i][0], effectColour(0.8)[0]) << d; // 0.3 +- 0.2: less red
            ++flesh;
        }
    }
    EXPECT_GT(rind, 100u);
    EXPECT_GT(flesh, 10u); // on the cut faces
    // Friction is 0.1 everywhere; the input frame is untouched.
    const auto rough = colouredByEffect(frame, tangible, scene::TangibleKind::Friction);
    EXPECT_EQ(rough->shapes[0].mesh.colours.front(), effectColour(0.1));
    EXPECT_NE(frame.shapes[0].mesh.colours.front(), effectColour(0.1));
}
