#pragma once
// Running an outside program from a test (functionlab itself, view3dscene,
// node, chromium ...) with a time limit, keeping what it printed.
#include <QProcess>
#include <QProcessEnvironment>
#include <QString>
#include <QStringList>

#include <string>

namespace fl::test {

struct ToolRun {
    bool started = false;
    bool finished = false;
    int exitCode = -1;
    QString out, err;

    std::string describe() const {
        return "exit " + std::to_string(exitCode) + "\nstdout: " + out.left(2000).toStdString() +
               "\nstderr: " + err.left(2000).toStdString();
    }
};

inline ToolRun
run(const QString& program, const QStringList& arguments,
    const QProcessEnvironment& environment = QProcessEnvironment::systemEnvironment(),
    int timeoutMs = 120000) {
    QProcess p;
    p.setProcessEnvironment(environment);
    p.start(program, arguments);
    ToolRun r;
    r.started = p.waitForStarted(10000);
    if (!r.started) return r;
    r.finished = p.waitForFinished(timeoutMs);
    if (!r.finished) {
        p.kill();
        p.waitForFinished(5000);
    }
    r.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
    r.out = QString::fromUtf8(p.readAllStandardOutput());
    r.err = QString::fromUtf8(p.readAllStandardError());
    return r;
}

} // namespace fl::test
