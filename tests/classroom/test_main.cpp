// GoogleTest inside a QCoreApplication: the loopback tests run Qt's event
// loop (QTest::qWaitFor) between their steps.
#include <QCoreApplication>

#include <gtest/gtest.h>

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
