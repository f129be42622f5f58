#pragma once
// Where the window was and how its panels were laid out, kept in the
// settings between runs; never larger than the screen it opens on (on a
// 1366×768 laptop the status bar with its error figure stays in sight).
class QMainWindow;

namespace fl::suite {

void restorePlacement(QMainWindow& window);
void savePlacement(const QMainWindow& window);
// Whether a layout was saved (else the window lays its panels out itself).
bool placementSaved();

} // namespace fl::suite
