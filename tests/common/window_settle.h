#pragma once
// Waiting in GUI tests until the window has nothing left to do: parsed,
// meshed, and the last frame in the view (the level of detail has looked).
#include "suite/window/main_window.h"

#include <QElapsedTimer>
#include <QTest>

namespace fl::test {

// A window as a student first has it, without dialogs, at `size`, on screen.
inline bool shownAt(suite::MainWindow& w, QSize size = {1280, 800}) {
    w.setPromptsEnabled(false);
    w.resize(size);
    w.show();
    return QTest::qWaitForWindowExposed(&w);
}

inline bool settle(suite::MainWindow& w, int timeoutMs = 30000) {
    QElapsedTimer clock;
    clock.start();
    QTest::qWait(50);
    while (clock.elapsed() < timeoutMs) {
        if (!w.busy()) {
            QTest::qWait(200); // the last frame reaches the view (and the LOD looks at it)
            if (!w.busy()) return true;
        }
        QTest::qWait(20);
    }
    return false;
}

} // namespace fl::test
