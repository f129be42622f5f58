// The OBJ reader: what scanners and modellers write is read (every face
// form, negative indices, polygons as fans), and what is not an OBJ mesh is
// refused at its line and column.
#include "mesh/obj_reader.h"

#include <gtest/gtest.h>

using namespace fl::mesh;

TEST(ObjReader, ReadsEveryFaceFormAndSplitsPolygonsIntoFans) {
    const ObjReadResult r = readObj("# a quad and a triangle\n"
                                    "mtllib x.mtl\no thing\nv 0 0 0\nv 1 0 0\nv 1 1 0 1\nv 0 1 0\n"
                                    "vt 0 0\nvn 0 0 1\ns off\ng g1\nusemtl m\n"
                                    "f 1/1/1 2/1/1 3//1 4\n"
                                    "f -1 -2 -3\n",
                                    "q.obj");
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(r.mesh->vertexCount(), 4u);
    ASSERT_EQ(r.mesh->triangleCount(), 3u);
    EXPECT_EQ(r.mesh->triangles[0], (Triangle{0, 1, 2}));
    EXPECT_EQ(r.mesh->triangles[1], (Triangle{0, 2, 3}));
    EXPECT_EQ(r.mesh->triangles[2], (Triangle{3, 2, 1}));
    EXPECT_EQ(r.triangleLines, (std::vector<std::uint32_t>{13, 13, 14}));
    EXPECT_EQ(r.vertexLines.front(), 4u);
}

TEST(ObjReader, MistakesAreLocated) {
    struct Case {
        const char* text;
        const char* error;
    } cases[] = {
        {"", "m.obj: no vertices"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\n", "m.obj: no faces"},
        {"v 0 0 0\nv 1 0 x\n", "m.obj:2:7: expected a coordinate, not 'x'"},
        {"v 0 nan 0\n", "m.obj:1:5: the coordinate 'nan' is not a finite number"},
        {"v 0 1e999 0\n", "m.obj:1:5: expected a coordinate, not '1e999'"},
        {"v 0 0\n", "m.obj:1:6: a vertex needs three coordinates"},
        {"v 0 0 0\nf 1 2 3\n", "m.obj:2:5: vertex 2 is not defined above (1 so far)"},
        {"v 0 0 0\nf 1 1\n", "m.obj:2:1: a face needs at least three vertices"},
        {"v 0 0 0\nf 0 1 1\n", "m.obj:2:3: expected a vertex number"},
        {"v 0 0 0\nf -2 1 1\n", "m.obj:2:3: vertex -2 is not defined above"},
        {"<html><body>not a mesh</body></html>\n", "m.obj:1:1: '<html><body>not' is not an OBJ"},
        {"\x7f"
         "ELF\x02\x01\n",
         "m.obj:1:1: '?ELF?"
         "?' is not an OBJ mesh statement"},
        {"v 1 2 3\nsolid cube\n", "m.obj:2:1: 'solid' is not an OBJ mesh statement"},
    };
    for (const Case& c : cases) {
        const ObjReadResult r = readObj(c.text, "m.obj");
        EXPECT_FALSE(r.ok()) << c.text;
        EXPECT_EQ(r.error.rfind(c.error, 0), 0u) << "got: " << r.error << "\nwanted: " << c.error;
    }
}

TEST(ObjReader, AFileTooLargeIsRefusedBeforeItIsRead) {
    const ObjReadResult r = readObj(std::string(kMaxObjBytes + 1, '#'), "big.obj");
    EXPECT_FALSE(r.ok());
    EXPECT_NE(r.error.find("at most 256 MiB"), std::string::npos) << r.error;
}
