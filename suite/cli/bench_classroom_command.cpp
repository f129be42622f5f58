// `functionlab bench classroom [--clients N] [--rate R] [--seconds S]
// [--json]`: a class on loopback, measured from outside. Starts `functionlab
// serve` as a child process, joins N WebSocket clients at once (the join
// storm), lets an instructor edit R times a second, and records when each
// scene reaches each client: the edit-to-everyone latency (p50, p99), first
// with every client reading, then with one more client that stops reading
// (it must not raise the others' p99). The server's CPU and peak memory come
// from /proc. Bounded in count and time; loopback only.
#include "cli/commands.h"
#include "cli/json.h"
#include "measure/percentiles.h"
#include "platform/exit_codes.h"

#include "classroom/protocol.h"
#include "classroom/server_message.h"
#include "classroom/starter_scene.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QTcpSocket>
#include <QTimer>
#include <QWebSocket>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <unistd.h>
#include <vector>

namespace fl::cli {

namespace {

constexpr const char* kClass = "BENCH";
constexpr const char* kKey = "bench-key";

QString joinFrame(std::string name, classroom::Role role) {
    classroom::JoinMessage join{kClass, std::move(name), role, {}, {}, {}};
    if (role == classroom::Role::Instructor) join.key = kKey;
    return QString::fromStdString(
        classroom::encodeClientMessage({classroom::MessageType::Join, join}));
}

struct Phase {
    std::vector<double> everyoneMs; // per applied edit: until the last reader had it
    std::vector<double> eachMs;     // per delivery
    int sent = 0, applied = 0, refused = 0, skipped = 0;
    double serverCpuPercent = 0;
};

// utime + stime of a process, in seconds.
double cpuSeconds(qint64 pid) {
    QFile f(QStringLiteral("/proc/%1/stat").arg(pid));
    if (!f.open(QIODevice::ReadOnly)) return 0;
    const QString stat = QString::fromLatin1(f.readAll());
    const QStringList fields = stat.mid(stat.lastIndexOf(')') + 2).split(' ');
    if (fields.size() < 13) return 0;
    return (fields[11].toDouble() + fields[12].toDouble()) /
           static_cast<double>(sysconf(_SC_CLK_TCK));
}

double peakMegabytes(qint64 pid) {
    QFile f(QStringLiteral("/proc/%1/status").arg(pid));
    if (!f.open(QIODevice::ReadOnly)) return 0;
    for (const QByteArray& line : f.readAll().split('\n'))
        if (line.startsWith("VmHWM:"))
            return line.mid(6).trimmed().split(' ').value(0).toDouble() / 1024.0;
    return 0;
}

// Waits in the event loop until `done` or `ms` pass.
template <class F>
bool waitFor(F done, int ms) {
    QElapsedTimer t;
    t.start();
    while (!done()) {
        if (t.elapsed() > ms) return false;
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
    }
    return true;
}

QByteArray maskedTextFrame(const QByteArray& payload) {
    QByteArray f;
    f.append(char(0x81));
    if (payload.size() < 126) {
        f.append(char(0x80 | payload.size()));
    } else {
        f.append(char(0x80 | 126));
        f.append(char((payload.size() >> 8) & 0xff));
        f.append(char(payload.size() & 0xff));
    }
    const char mask[4] = {0x12, 0x34, 0x56, 0x78};
    f.append(mask, 4);
    for (qsizetype i = 0; i < payload.size(); ++i)
        f.append(char(payload[i] ^ mask[i % 4]));
    return f;
}

// A member that joins and then stops reading: its TCP window fills and the
// server's unsent bytes for it grow.
std::unique_ptr<QTcpSocket> slowReader(quint16 port) {
    auto s = std::make_unique<QTcpSocket>();
    s->setSocketOption(QAbstractSocket::ReceiveBufferSizeSocketOption, 4096);
    s->setReadBufferSize(4096);
    s->connectToHost(QHostAddress::LocalHost, port);
    if (!s->waitForConnected(5000)) return nullptr;
    s->write("GET / HTTP/1.1\r\nHost: 127.0.0.1\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
             "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n\r\n");
    if (!waitFor([&] { return s->bytesAvailable() > 0 || s->waitForReadyRead(10); }, 5000))
        return nullptr;
    s->write(maskedTextFrame(R"({"type":"join","class":"BENCH","name":"slow"})"));
    s->flush();
    return s;
}

} // namespace

const CommandSpec& benchClassroomSpec() {
    static const CommandSpec spec{
        .name = "bench classroom",
        .summary = "a class on loopback: join storm, edit fan-out latency, server CPU and memory",
        .synopsis = {"bench classroom [--clients N] [--rate R] [--seconds S] [--json]"},
        .description =
            "Starts `functionlab serve` on a free loopback port, joins N clients at once and\n"
            "times the storm, then lets an instructor edit the scene R times a second for S\n"
            "seconds while every client reads: the time from each edit until every client\n"
            "has the new scene (p50, p99). The same again with one more member that stops\n"
            "reading. The server's CPU (per cent of one core) and peak resident memory are\n"
            "read from /proc.\n",
        .options = {{.name = "clients",
                     .kind = OptionKind::Integer,
                     .valueName = "N",
                     .help = "members reading the scene",
                     .defaultValue = "200",
                     .min = 1,
                     .max = 1000},
                    {.name = "rate",
                     .kind = OptionKind::Number,
                     .valueName = "R",
                     .help = "edits per second",
                     .defaultValue = "50",
                     .min = 1,
                     .max = 500},
                    {.name = "seconds",
                     .kind = OptionKind::Number,
                     .valueName = "S",
                     .help = "how long each phase edits",
                     .defaultValue = "5",
                     .min = 1,
                     .max = 60},
                    {.name = "json", .help = "print one JSON object instead of the table"}},
        .exitStatus = "0 measured, 1 the server did not start or the clients could not join, 2 "
                      "usage error",
    };
    return spec;
}

int benchClassroomCommand(const Args& args) {
    int exit = 0;
    const auto a = parseOrExplain(benchClassroomSpec(), args, exit, std::cout, std::cerr);
    if (!a) return exit;
    const int clients = static_cast<int>(a->integer("clients", 200));
    const double rate = a->number("rate", 50);
    const double seconds = a->number("seconds", 5);

    int argc = 1;
    char name[] = "functionlab";
    char* argv[] = {name, nullptr};
    QCoreApplication app(argc, argv);

    QProcess server;
    server.setProgram(QCoreApplication::applicationFilePath());
    server.setArguments({"serve", "--port", "0", "--class", kClass, "--instructor-key", kKey});
    server.setProcessChannelMode(QProcess::SeparateChannels);
    server.start();
    QString out;
    QRegularExpressionMatch listening;
    waitFor(
        [&] {
            out += QString::fromUtf8(server.readAllStandardOutput());
            listening = QRegularExpression(R"(listening on ws://[0-9.]+:([0-9]+))").match(out);
            return listening.hasMatch() || server.state() == QProcess::NotRunning;
        },
        15'000);
    if (!listening.hasMatch()) {
        std::cerr << "functionlab bench classroom: the server did not start: "
                  << server.readAllStandardError().toStdString() << "\n";
        return kExitDiagnostic;
    }
    const quint16 port = static_cast<quint16>(listening.captured(1).toUInt());
    const QUrl url(QStringLiteral("ws://127.0.0.1:%1").arg(port));
    const qint64 pid = server.processId();

    // Receive times per version, per reader.
    QElapsedTimer clock;
    clock.start();
    std::map<qint64, double> sentAt;           // version expected -> ms
    std::map<qint64, std::vector<double>> got; // version -> each reader's receive ms
    Phase* phase = nullptr;

    std::vector<std::unique_ptr<QWebSocket>> readers;
    int welcomed = 0;
    const double stormStart = static_cast<double>(clock.nsecsElapsed()) / 1e6;
    for (int i = 0; i < clients; ++i) {
        auto ws = std::make_unique<QWebSocket>();
        QWebSocket* raw = ws.get();
        QObject::connect(raw, &QWebSocket::connected, raw, [raw, i] {
            raw->sendTextMessage(joinFrame("s" + std::to_string(i), classroom::Role::Student));
        });
        QObject::connect(raw, &QWebSocket::textMessageReceived, raw, [&](const QString& m) {
            const double now = static_cast<double>(clock.nsecsElapsed()) / 1e6;
            // JSON-escaped text cannot hold an unescaped `"type":"...` inside a string.
            if (m.contains(QLatin1String(R"("type":"welcome")"))) ++welcomed;
            if (!phase || !m.contains(QLatin1String(R"("type":"scene")"))) return;
            const auto parsed = classroom::parseServerMessage(m.toStdString());
            if (const auto* message = std::get_if<classroom::ServerMessage>(&parsed))
                if (const auto* scene = std::get_if<classroom::SceneMessage>(message))
                    got[scene->version].push_back(now);
        });
        QObject::connect(raw, qOverload<QAbstractSocket::SocketError>(&QWebSocket::error), raw,
                         [raw](QAbstractSocket::SocketError) {
                             std::cerr << "bench client: " << raw->errorString().toStdString()
                                       << "\n";
                         });
        raw->open(url);
        readers.push_back(std::move(ws));
    }
    const bool allJoined = waitFor([&] { return welcomed == clients; }, 30'000);
    const double stormMs = static_cast<double>(clock.nsecsElapsed()) / 1e6 - stormStart;
    if (!allJoined) {
        std::cerr << "functionlab bench classroom: " << welcomed << " of " << clients
                  << " clients joined in 30 s\n";
        return kExitDiagnostic;
    }

    // The instructor edits; each edit is based on the newest version it has seen.
    QWebSocket teacher;
    qint64 version = -1;
    bool inFlight = false; // one edit at a time, each on the newest version
    QObject::connect(&teacher, &QWebSocket::connected,
                     [&] { teacher.sendTextMessage(joinFrame("T", classroom::Role::Instructor)); });
    QObject::connect(&teacher, &QWebSocket::textMessageReceived, [&](const QString& m) {
        const auto parsed = classroom::parseServerMessage(m.toStdString());
        const auto* message = std::get_if<classroom::ServerMessage>(&parsed);
        if (!message) return;
        if (const auto* w = std::get_if<classroom::WelcomeMessage>(message))
            version = std::max<qint64>(version, w->version);
        if (const auto* scene = std::get_if<classroom::SceneMessage>(message)) {
            version = std::max<qint64>(version, scene->version);
            if (phase) ++phase->applied;
            inFlight = false;
        }
        if (std::holds_alternative<classroom::RefusedMessage>(*message)) {
            if (phase) ++phase->refused;
            inFlight = false;
        }
    });
    teacher.open(url);
    if (!waitFor([&] { return version >= 0; }, 10'000)) {
        std::cerr << "functionlab bench classroom: the instructor could not join\n";
        return kExitDiagnostic;
    }

    const std::string base = classroom::starterScene();
    const std::string marker = "sphere(0, 0, 0, 1)";
    auto runPhase = [&](Phase& p) {
        phase = &p;
        sentAt.clear();
        got.clear();
        int n = 0;
        QTimer timer;
        timer.setTimerType(Qt::PreciseTimer);
        QObject::connect(&timer, &QTimer::timeout, [&] {
            if (inFlight) {
                ++p.skipped; // the previous edit has not come back yet
                return;
            }
            inFlight = true;
            std::string scene = base;
            scene.replace(scene.find(marker), marker.size(),
                          "sphere(0, 0, 0, " + std::to_string(1.0 + 0.001 * (++n % 500)) + ")");
            sentAt[version + 1] = static_cast<double>(clock.nsecsElapsed()) / 1e6;
            teacher.sendTextMessage(QString::fromStdString(classroom::encodeClientMessage(
                {classroom::MessageType::Edit, classroom::EditMessage{version, scene}})));
            ++p.sent;
        });
        const double cpu0 = cpuSeconds(pid);
        QElapsedTimer wall;
        wall.start();
        timer.start(static_cast<int>(1000.0 / rate));
        waitFor([&] { return false; }, static_cast<int>(seconds * 1000));
        timer.stop();
        waitFor([&] { return false; }, 1000); // let the last edits arrive
        p.serverCpuPercent =
            100.0 * (cpuSeconds(pid) - cpu0) / (static_cast<double>(wall.elapsed()) / 1000.0);
        for (const auto& [v, times] : got) {
            const auto s = sentAt.find(v);
            if (s == sentAt.end()) continue;
            for (double t : times)
                p.eachMs.push_back(t - s->second);
            if (static_cast<int>(times.size()) == clients)
                p.everyoneMs.push_back(*std::max_element(times.begin(), times.end()) - s->second);
        }
        phase = nullptr;
    };

    // Members send heartbeats, as ClassroomClient does; a silent one is closed
    // after 30 s. The slow reader too: it writes, it only stops reading.
    std::unique_ptr<QTcpSocket> slow;
    QTimer heartbeats;
    QObject::connect(&heartbeats, &QTimer::timeout, [&] {
        for (const auto& r : readers)
            r->sendTextMessage(QStringLiteral(R"({"type":"heartbeat"})"));
        teacher.sendTextMessage(QStringLiteral(R"({"type":"heartbeat"})"));
        if (slow) slow->write(maskedTextFrame(R"({"type":"heartbeat"})"));
    });
    heartbeats.start(3000);

    Phase reading, withSlow;
    waitFor([&] { return false; }, 1500); // the storm's presence lists settle first
    runPhase(reading);
    slow = slowReader(port);
    waitFor([&] { return false; }, 500);
    runPhase(withSlow);
    const double peakMb = peakMegabytes(pid);
    server.terminate();
    server.waitForFinished(10'000);

    if (a->flag("json")) {
        auto phaseJson = [](const Phase& p) {
            return "{\"sent\":" + std::to_string(p.sent) +
                   ",\"applied\":" + std::to_string(p.applied) +
                   ",\"refused\":" + std::to_string(p.refused) +
                   ",\"skipped\":" + std::to_string(p.skipped) +
                   ",\"editsReachingEveryone\":" + std::to_string(p.everyoneMs.size()) +
                   ",\"deliveries\":" + std::to_string(p.eachMs.size()) +
                   ",\"everyoneP50Ms\":" + jsonNumber(measure::percentile(p.everyoneMs, 0.5)) +
                   ",\"everyoneP99Ms\":" + jsonNumber(measure::percentile(p.everyoneMs, 0.99)) +
                   ",\"deliveryP50Ms\":" + jsonNumber(measure::percentile(p.eachMs, 0.5)) +
                   ",\"deliveryP99Ms\":" + jsonNumber(measure::percentile(p.eachMs, 0.99)) +
                   ",\"serverCpuPercent\":" + jsonNumber(p.serverCpuPercent) + "}";
        };
        std::cout << "{\"clients\":" << clients << ",\"rate\":" << jsonNumber(rate)
                  << ",\"seconds\":" << jsonNumber(seconds)
                  << ",\"joinStormMs\":" << jsonNumber(stormMs)
                  << ",\"reading\":" << phaseJson(reading)
                  << ",\"withSlowReader\":" << phaseJson(withSlow)
                  << ",\"slowReaderJoined\":" << (slow ? "true" : "false")
                  << ",\"serverPeakMB\":" << jsonNumber(peakMb) << "}\n";
        return kExitOk;
    }
    char line[300];
    std::printf("join storm: %d clients welcomed in %.0f ms\n", clients, stormMs);
    for (const auto& [label, p] :
         {std::pair{"all reading", &reading}, std::pair{"one slow reader", &withSlow}}) {
        std::snprintf(
            line, sizeof line,
            "%-16s edits %d sent, %d applied, %d refused, %d skipped; to everyone p50 %.1f ms, p99 "
            "%.1f ms (%zu edits, %zu of %zu deliveries); server CPU %.0f%%\n",
            label, p->sent, p->applied, p->refused, p->skipped,
            measure::percentile(p->everyoneMs, 0.5), measure::percentile(p->everyoneMs, 0.99),
            p->everyoneMs.size(), p->eachMs.size(),
            static_cast<std::size_t>(p->applied) * static_cast<std::size_t>(clients),
            p->serverCpuPercent);
        std::cout << line;
    }
    std::snprintf(line, sizeof line, "server peak memory: %.1f MB\n", peakMb);
    std::cout << line;
    return kExitOk;
}

} // namespace fl::cli
