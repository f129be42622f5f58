// Each panel of the window driven alone (Qt Test, no 3D view needed): what it
// shows for a scene, and what it says when the student acts on it.
#include "suite/window/examples_dock.h"
#include "suite/window/issues_dock.h"
#include "suite/window/parameters_dock.h"
#include "suite/window/scene_tree_dock.h"
#include "suite/window/viewpoint_box.h"

#include "scene/scene_reader.h"

#include <QApplication>
#include <QFileInfo>
#include <QLabel>
#include <QListWidget>
#include <QSignalSpy>
#include <QSlider>
#include <QTest>
#include <QTreeWidget>

#include <memory>

using namespace fl;

namespace {

const char* kScene = R"(<?xml version="1.0" encoding="UTF-8"?>
<X3D profile='Immersive' version='3.3'>
  <Scene>
    <Transform DEF='BALL' translation='1 0 0'>
      <Shape><Sphere/></Shape>
    </Transform>
    <Transform DEF='AGAIN'>
      <Transform USE='BALL'/>
    </Transform>
    <FShape>
      <FGeometry definition='"param R = 0.5 in [0.2, 1]; param S = 2; return R*R*S - x^2 - y^2 - z^2;"'/>
    </FShape>
  </Scene>
</X3D>
)";

std::unique_ptr<scene::Scene> read(const char* text) {
    scene::ReadResult r = scene::readSceneBytes(text, "docks.x3d");
    return std::move(r.scene);
}

QList<QTreeWidgetItem*> allItems(QTreeWidget* tree) {
    QList<QTreeWidgetItem*> out;
    std::function<void(QTreeWidgetItem*)> walk = [&](QTreeWidgetItem* item) {
        out.push_back(item);
        for (int i = 0; i < item->childCount(); ++i)
            walk(item->child(i));
    };
    for (int i = 0; i < tree->topLevelItemCount(); ++i)
        walk(tree->topLevelItem(i));
    return out;
}

} // namespace

class DocksTest : public QObject {
    Q_OBJECT
  private Q_SLOTS:
    void theParametersDockShowsASliderPerParameterAndSaysWhatChanged() {
        const auto scene = read(kScene);
        QVERIFY(scene);
        suite::ParametersDock dock;
        dock.showScene(*scene);
        auto* r = dock.findChild<QSlider*>(QStringLiteral("param-R"));
        auto* s = dock.findChild<QSlider*>(QStringLiteral("param-S"));
        QVERIFY(r && s);
        QCOMPARE(r->value(), 375); // 0.5 in [0.2, 1]
        QVERIFY(dock.values().empty());

        QSignalSpy changed(&dock, &suite::ParametersDock::parameterChanged);
        QSignalSpy all(&dock, &suite::ParametersDock::valuesChanged);
        r->setValue(1000);
        QCOMPARE(changed.count(), 1);
        QCOMPARE(changed[0][0].toString(), QStringLiteral("R"));
        QCOMPARE(changed[0][1].toDouble(), 1.0);
        QCOMPARE(all.count(), 1);
        QCOMPARE(dock.values().size(), 1u);
        QCOMPARE(dock.values()[0].first, std::string("R"));
        QCOMPARE(dock.values()[0].second, 1.0);

        // The same scene again (after an edit): the value set is kept.
        dock.showScene(*scene);
        r = dock.findChild<QSlider*>(QStringLiteral("param-R"));
        QVERIFY(r);
        QCOMPARE(r->value(), 1000);
        QCOMPARE(dock.values().size(), 1u);

        // A scene without parameters: no sliders, a word why, nothing kept.
        const auto plain = read("#X3D V3.3 utf8\nPROFILE Immersive\nShape { geometry Box {} }\n");
        QVERIFY(plain);
        dock.showScene(*plain);
        QVERIFY(!dock.findChild<QSlider*>(QStringLiteral("param-R")));
        QVERIFY(dock.values().empty());
        bool said = false;
        for (QLabel* l : dock.findChildren<QLabel*>())
            said = said || l->text().contains(QStringLiteral("no `param`"));
        QVERIFY(said);
    }

    void theSceneTreeListsNodesByTypeAndDefName() {
        const auto scene = read(kScene);
        QVERIFY(scene);
        suite::SceneTreeDock dock;
        dock.showScene(*scene);
        QTreeWidget* tree = dock.tree();
        QCOMPARE(tree->topLevelItemCount(), 3);
        QCOMPARE(tree->topLevelItem(0)->text(0), QStringLiteral("Transform"));
        QCOMPARE(tree->topLevelItem(0)->text(1), QStringLiteral("BALL"));
        QCOMPARE(tree->topLevelItem(1)->text(1), QStringLiteral("AGAIN"));
        QCOMPARE(tree->topLevelItem(2)->text(0), QStringLiteral("FShape"));
        QStringList defs, types;
        for (QTreeWidgetItem* item : allItems(tree)) {
            defs << item->text(1);
            types << item->text(0);
        }
        QVERIFY(types.contains(QStringLiteral("Sphere")));
        QVERIFY(types.contains(QStringLiteral("FGeometry")));
        QVERIFY2(types.contains(QStringLiteral("USE BALL")), qPrintable(types.join(',')));

        // Clicking a node says where it is written.
        QSignalSpy activated(&dock, &suite::SceneTreeDock::nodeActivated);
        Q_EMIT tree->itemClicked(tree->topLevelItem(1), 0);
        QCOMPARE(activated.count(), 1);
        QCOMPARE(activated[0][0].toInt(), 7); // <Transform DEF='AGAIN'> is on line 7
        QVERIFY(activated[0][1].toInt() >= 1);
    }

    void theIssuesDockListsDiagnosticsAndSaysWhereOneIs() {
        suite::IssuesDock dock;
        std::vector<scene::SceneDiagnostic> diagnostics(2);
        diagnostics[0].file = "a.x3d";
        diagnostics[0].pos = {3, 5};
        diagnostics[0].message = "unknown function 'sine'";
        diagnostics[0].suggestion = "did you mean 'sin'?";
        diagnostics[1].severity = scene::Severity::Warning;
        diagnostics[1].file = "a.x3d";
        diagnostics[1].pos = {7, 1};
        diagnostics[1].message = "unused";
        dock.showDiagnostics(diagnostics);
        QListWidget* list = dock.list();
        QCOMPARE(list->count(), 2);
        QVERIFY(
            list->item(0)->text().startsWith(QStringLiteral("a.x3d:3:5: error: unknown function")));
        QCOMPARE(list->item(0)->foreground().color(), QColor(Qt::red));
        QVERIFY(list->item(1)->foreground().color() != QColor(Qt::red));

        QSignalSpy activated(&dock, &suite::IssuesDock::issueActivated);
        Q_EMIT list->itemActivated(list->item(1));
        Q_EMIT list->itemClicked(list->item(0));
        QCOMPARE(activated.count(), 2);
        QCOMPARE(activated[0][0].toInt(), 7);
        QCOMPARE(activated[0][1].toInt(), 1);
        QCOMPARE(activated[1][0].toInt(), 3);
        QCOMPARE(activated[1][1].toInt(), 5);

        dock.showDiagnostics({});
        QCOMPARE(list->count(), 0);
    }

    void theExamplesDockListsTheExamplesAndSaysWhichIsChosen() {
        suite::ExamplesDock dock(nullptr, QStringLiteral(FUNCTIONLAB_EXAMPLES_DIR));
        QListWidget* list = dock.list();
        QVERIFY(list->count() >= 8);
        int melon = -1;
        for (int i = 0; i < list->count(); ++i) {
            QVERIFY(QFileInfo::exists(list->item(i)->data(Qt::UserRole).toString()));
            if (list->item(i)
                    ->data(Qt::UserRole)
                    .toString()
                    .endsWith(QStringLiteral("watermelon.x3d")))
                melon = i;
        }
        QVERIFY(melon >= 0);
        QSignalSpy chosen(&dock, &suite::ExamplesDock::exampleChosen);
        Q_EMIT list->itemActivated(list->item(melon));
        QCOMPARE(chosen.count(), 1);
        QVERIFY(chosen[0][0].toString().endsWith(QStringLiteral("watermelon.x3d")));
    }

    void theViewpointBoxListsViewpointsThenTheWholeScene() {
        suite::ViewpointBox box;
        box.showViewpoints({QStringLiteral("Front"), QStringLiteral("Top")});
        QCOMPARE(box.count(), 3);
        QCOMPARE(box.itemText(2), QStringLiteral("Whole scene"));
        QSignalSpy chosen(&box, &suite::ViewpointBox::viewpointChosen);
        Q_EMIT box.activated(1);
        Q_EMIT box.activated(2);
        QCOMPARE(chosen.count(), 2);
        QCOMPARE(chosen[0][0].toInt(), 1);
        QCOMPARE(chosen[1][0].toInt(), -1);
        // The same names again leave the list (and the choice) alone.
        box.setCurrentIndex(1);
        box.showViewpoints({QStringLiteral("Front"), QStringLiteral("Top")});
        QCOMPARE(box.currentIndex(), 1);
        box.showViewpoints({QStringLiteral("Side")});
        QCOMPARE(box.count(), 2);
    }
};

QTEST_MAIN(DocksTest)
#include "docks_test.moc"
