// Every scene of the public corpus that loads also animates: wiring its
// ROUTEs and ticking its clocks for a while never crashes, never hangs, and
// keeps every value it produces finite where the file's were.
#include "animation/animator.h"
#include "scene/field_access.h"
#include "scene/scene_reader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

using namespace fl::animation;
namespace fs = std::filesystem;

TEST(CorpusAnimation, EveryLoadingSceneTicksWithoutTrouble) {
    const fs::path root = FUNCTIONLAB_CORPUS_DIR;
    if (!fs::exists(root)) GTEST_SKIP() << "no corpus at " << root;
    std::size_t animated = 0, routes = 0, scenes = 0;
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
        if (!entry.is_regular_file()) continue;
        auto r = fl::scene::readSceneFile(entry.path());
        if (!r.ok()) continue;
        ++scenes;
        Animator a(*r.scene);
        routes += a.routeCount();
        const std::int64_t start = 1'795'000'000 * kNanosecondsPerSecond;
        bool moved = false;
        for (int frame = 0; frame < 40; ++frame) {
            const std::int64_t ns = std::int64_t(frame) * 137'000'000; // 0.137 s steps
            a.tick({ns, start + ns, 0});
            moved = moved || !a.changes().empty();
            for (const FieldChange& c : a.changes()) {
                // Finite where the file's value was (an event may set a field
                // the file left at its finite default, too).
                const auto file = fl::scene::fieldValue(*c.node, c.field).numbers;
                if (!std::all_of(file.begin(), file.end(),
                                 [](double v) { return std::isfinite(v); }))
                    continue;
                for (double v : a.value(*c.node, c.field).numbers)
                    ASSERT_TRUE(std::isfinite(v))
                        << entry.path() << " " << c.node->type << "." << c.field << " = " << v;
            }
        }
        animated += moved;
    }
    std::cout << scenes << " scenes, " << animated << " animate by themselves, " << routes
              << " ROUTEs\n";
    EXPECT_GT(animated, 10u);
}
