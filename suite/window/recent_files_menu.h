#pragma once
// File → Open Recent: the last eight scene files opened or saved, newest
// first, kept in the settings; choosing one opens it (unsaved work kept first).
#include <QMenu>

#include <functional>

namespace fl::suite {

class RecentFilesMenu : public QMenu {
    Q_OBJECT
  public:
    RecentFilesMenu(const QString& title, std::function<void(const QString&)> open,
                    QWidget* parent = nullptr);
    void add(const QString& path);

  private:
    void fill();
    std::function<void(const QString&)> open_;
};

} // namespace fl::suite
