// The instructor's Grading panel driven alone (Qt Test): a gradebook of two
// graded students shows as a table; rubric scores, comments and an override
// (with its reason) are written to the gradebook and change the final score;
// the grades export. A screenshot is saved to look at.
#include "suite/window/grading_panel.h"

#include "courseware/catalogue.h"
#include "grading/checker.h"

#include <QApplication>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QLineEdit>
#include <QTableWidget>
#include <QTest>

using namespace fl;

class GradingPanelTest : public QObject {
    Q_OBJECT
  private Q_SLOTS:
    void initTestCase() {
        const QString dir = QDir::temp().filePath(QStringLiteral("functionlab-grading-panel"));
        QDir(dir).removeRecursively();
        QDir().mkpath(dir);
        path_ = dir + QStringLiteral("/course.sqlite");
        const auto lab = courseware::findAssignment("implicit-fantasies");
        QVERIFY(lab.assignment);
        grading::Gradebook book(path_.toStdString());
        book.importRoster("id,name\nalice,Alice Smith\nbob,Bob Jones\n");
        book.registerAssignment(lab.assignment->record());
        const std::string folder = lab.assignment->folder.string();
        for (const auto& [student, file] :
             {std::pair<std::string, std::string>{"alice", "/solution/fantasy.x3d"},
              {"bob", "/starter.x3d"}}) {
            const grading::CheckReport r =
                grading::checkSubmission(folder + file, lab.assignment->requirements);
            grading::GradeRecord g;
            g.student = student;
            g.assignment = lab.assignment->id;
            g.contentHash = student + "-hash";
            g.submittedAt = "2026-12-01T10:00:00Z";
            g.path = folder + file;
            g.checkerVersion = grading::kCheckerVersion;
            g.rubricHash = lab.assignment->rubricHash();
            g.gradable = r.gradable;
            g.score = r.score;
            g.maxScore = r.maxScore;
            g.gradedAt = "2026-12-01T11:00:00Z";
            g.requirements = r.requirements;
            book.recordGrade(g);
        }
    }

    void showsTheClassAndTakesManualScoresAndOverrides() {
        suite::GradingPanel panel;
        panel.resize(1200, 520);
        QString error;
        QVERIFY2(panel.openGradebook(path_, {}, &error), qPrintable(error));
        QTableWidget* t = panel.table();
        QCOMPARE(t->rowCount(), 2);
        QCOMPARE(t->columnCount(), 2 + 8 + 5); // student, name, 8 requirements, 5 totals
        QCOMPARE(t->item(0, 1)->text(), QStringLiteral("Alice Smith"));
        QCOMPARE(t->item(0, t->columnCount() - 1)->text(), QStringLiteral("100"));
        QVERIFY(t->item(1, 2)->text().startsWith(QStringLiteral("✘"))); // bob: no implicit
        panel.selectStudent(QStringLiteral("alice"));
        QDoubleSpinBox* fantasy = panel.rubricPoints(QStringLiteral("fantasy"));
        QVERIFY(fantasy);
        fantasy->setValue(12);
        panel.rubricComment(QStringLiteral("fantasy"))->setText(QStringLiteral("a lovely world"));
        panel.saveManualScores();
        QCOMPARE(t->item(0, t->columnCount() - 1)->text(), QStringLiteral("112"));
        // Saving keeps the grader's place (issue 29 §6: it cleared the selection).
        QCOMPARE(panel.selectedStudent(), QStringLiteral("alice"));
        QCOMPARE(t->selectionModel()->selectedRows().size(), 1);
        QCOMPARE(t->selectionModel()->selectedRows().front().row(), 0);
        // Kept in the gradebook: a second panel reads it back.
        suite::GradingPanel again;
        QVERIFY(again.openGradebook(path_));
        again.selectStudent(QStringLiteral("alice"));
        QCOMPARE(again.rubricPoints(QStringLiteral("fantasy"))->value(), 12.0);
        QCOMPARE(again.rubricComment(QStringLiteral("fantasy"))->text(),
                 QStringLiteral("a lovely world"));
        // An override needs a reason.
        panel.selectStudent(QStringLiteral("bob"));
        panel.overrideScore()->setValue(55);
        QVERIFY(!panel.saveOverride(&error));
        QVERIFY(error.contains(QStringLiteral("reason")));
        // Said in the panel too, where the grader looks (it was silent).
        QVERIFY(panel.overrideStatus()->text().contains(QStringLiteral("reason")));
        panel.overrideReason()->setText(QStringLiteral("talked it through"));
        QVERIFY(panel.saveOverride());
        QCOMPARE(t->item(1, t->columnCount() - 1)->text(), QStringLiteral("55"));
        QCOMPARE(panel.selectedStudent(), QStringLiteral("bob"));
        QVERIFY(panel.overrideStatus()->text().contains(QStringLiteral("55")));
        QVERIFY2(panel.integrityStatus()->text().startsWith(QStringLiteral("Intact")),
                 qPrintable(panel.integrityStatus()->text()));
        const QString csv = QFileInfo(path_).path() + QStringLiteral("/grades.csv");
        QVERIFY(panel.exportTo(csv, grading::ExportFormat::Csv));
        QFile f(csv);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QVERIFY(f.readAll().contains("bob,Bob Jones"));
        panel.selectStudent(QStringLiteral("alice"));
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        QDir().mkpath(FUNCTIONLAB_SCREENSHOT_DIR);
        QVERIFY(panel.grab().save(FUNCTIONLAB_SCREENSHOT_DIR "/grading-panel.png"));
    }

    // Issue 27 §3: an override changed behind the log's back shows in red.
    void aTamperedGradebookSaysSo() {
        const QString copy = QFileInfo(path_).path() + QStringLiteral("/tampered.sqlite");
        QFile::remove(copy);
        {
            grading::Gradebook book(path_.toStdString()); // its WAL written out on close
        }
        QVERIFY(QFile::copy(path_, copy));
        {
            fl::platform::SqliteDatabase db(copy.toStdString());
            db.execute("UPDATE results SET points = 0");
        }
        suite::GradingPanel panel;
        QVERIFY(panel.openGradebook(copy));
        QVERIFY2(panel.integrityStatus()->text().startsWith(QStringLiteral("NOT INTACT")),
                 qPrintable(panel.integrityStatus()->text()));
        QVERIFY(panel.integrityStatus()->text().contains(QStringLiteral("results")));
        panel.resize(1200, 520);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        QVERIFY(panel.grab().save(FUNCTIONLAB_SCREENSHOT_DIR "/grading-panel-tampered.png"));
    }

    void aMissingOrEmptyGradebookIsExplained() {
        suite::GradingPanel panel;
        QString error;
        QVERIFY(!panel.openGradebook(QStringLiteral("/nonexistent/dir/x.sqlite"), {}, &error));
        QVERIFY(!error.isEmpty());
        const QString empty = QFileInfo(path_).path() + QStringLiteral("/empty.sqlite");
        QFile::remove(empty);
        QVERIFY(!panel.openGradebook(empty, {}, &error));
        QVERIFY(error.contains(QStringLiteral("grade batch")));
    }

  private:
    QString path_;
};

QTEST_MAIN(GradingPanelTest)
#include "grading_panel_test.moc"
