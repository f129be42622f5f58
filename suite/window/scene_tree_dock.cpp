#include "scene_tree_dock.h"

#include "scene/scene.h"

#include <QSet>
#include <QTreeWidget>

#include <functional>

namespace fl::suite {

SceneTreeDock::SceneTreeDock(QWidget* parent)
    : Panel(tr("Scene tree"), QStringLiteral("tree"), Qt::LeftDockWidgetArea, parent),
      tree_(new QTreeWidget) {
    tree_->setHeaderLabels({tr("Node"), tr("DEF")});
    setWidget(tree_);
    connect(tree_, &QTreeWidget::itemClicked, this, [this](QTreeWidgetItem* item) {
        Q_EMIT nodeActivated(item->data(0, Qt::UserRole).toInt(),
                             item->data(0, Qt::UserRole + 1).toInt());
    });
}

void SceneTreeDock::showScene(const scene::Scene& scene) {
    tree_->clear();
    // A node met again (USE) is a leaf naming it: a DEF/USE graph never
    // multiplies into an exponential tree. At most kMaxItems items.
    constexpr int kMaxItems = 20000;
    int items = 0;
    QSet<const scene::Node*> shown;
    std::function<void(const scene::Node*, QTreeWidgetItem*, int)> add =
        [&](const scene::Node* n, QTreeWidgetItem* parent, int depth) {
            if (!n || depth > 64 || items >= kMaxItems) return;
            ++items;
            auto* item = parent ? new QTreeWidgetItem(parent) : new QTreeWidgetItem(tree_);
            const bool again = shown.contains(n);
            item->setText(0, again ? QStringLiteral("USE ") + QString::fromStdString(n->defName)
                                   : QString::fromStdString(n->type));
            item->setText(1, QString::fromStdString(n->defName));
            item->setData(0, Qt::UserRole, n->where.line);
            item->setData(0, Qt::UserRole + 1, n->where.column);
            if (again) return;
            shown.insert(n);
            for (const scene::Field& f : n->fields)
                for (const scene::Node* c : f.value.nodes)
                    add(c, item, depth + 1);
        };
    for (const scene::Node* root : scene.roots)
        add(root, nullptr, 0);
    tree_->expandToDepth(1);
}

void SceneTreeDock::attach(PanelContext& context) {
    connect(this, &SceneTreeDock::nodeActivated, this,
            [&context](int line, int column) { context.goTo(line, column); });
}

} // namespace fl::suite
