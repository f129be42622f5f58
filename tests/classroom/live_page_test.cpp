// The class's live web page on the class server's own port (issue 32 §2):
// the request head a stranger sends, read and refused as it should be; the
// page, its files and nothing else; the baked scene following an edit; the
// class code guard; --no-web; and WebSocket members on the same port.
#include "classroom/client.h"
#include "classroom/http_request.h"
#include "classroom/server.h"

#include "scenes.h"

#include <QTcpSocket>
#include <QTest>

#include <gtest/gtest.h>

#include <memory>

namespace fl::classroom {
namespace {

using test::classScene;

constexpr int kWaitMs = 10'000;

std::optional<HttpRequest> parse(const std::string& head) {
    std::string why;
    return parseRequestHead(head, why);
}

TEST(HttpRequestHead, AGetWithQueryAndHeadersReadsBack) {
    const auto r = parse("GET /scene.json?class=MATH%201&x=a+b HTTP/1.1\r\nHost: h\r\n"
                         "Accept-Encoding: br, GZIP;q=0.5\r\n\r\n");
    ASSERT_TRUE(r);
    EXPECT_EQ(r->method, "GET");
    EXPECT_EQ(r->path, "/scene.json");
    EXPECT_EQ(r->queryValue("class"), "MATH 1");
    EXPECT_EQ(r->queryValue("x"), "a b");
    EXPECT_EQ(r->header("host"), "h");
    EXPECT_TRUE(r->acceptsGzip());
    EXPECT_FALSE(r->wantsWebSocket());
}

TEST(HttpRequestHead, AWebSocketUpgradeIsTold) {
    const auto r =
        parse("GET / HTTP/1.1\r\nUpgrade: WebSocket\r\nConnection: keep-alive, Upgrade\r\n"
              "Sec-WebSocket-Key: x\r\n\r\n");
    ASSERT_TRUE(r);
    EXPECT_TRUE(r->wantsWebSocket());
}

TEST(HttpRequestHead, HostileHeadsAreRefusedWithAReason) {
    for (const char* head :
         {"GET /viewer/../../etc/passwd HTTP/1.1\r\n\r\n",
          "GET /viewer/%2e%2e/secret HTTP/1.1\r\n\r\n", "GET /a%00b HTTP/1.1\r\n\r\n",
          "GET /a%zz HTTP/1.1\r\n\r\n", "GET /%1b[2J HTTP/1.1\r\n\r\n",
          "GET http://evil/ HTTP/1.1\r\n\r\n", "get / HTTP/1.1\r\n\r\n", "GET / HTTP/2\r\n\r\n",
          "GET  / HTTP/1.1\r\n\r\n", "GET / HTTP/1.1\r\nNoColon\r\n\r\n",
          "GET / HTTP/1.1\r\nX: a\x01z\r\n\r\n", "GET /\r\n\r\n", ""}) {
        std::string why;
        EXPECT_FALSE(parseRequestHead(head, why)) << head;
        EXPECT_FALSE(why.empty()) << head;
    }
}

TEST(HttpRequestHead, TheHeadIsBounded) {
    std::size_t length = 0;
    EXPECT_EQ(findHeadEnd("GET / HTTP/1.1\r\nHost: x\r\n", length), HeadStatus::Incomplete);
    EXPECT_EQ(findHeadEnd("GET / HTTP/1.1\r\n\r\nbody", length), HeadStatus::Complete);
    EXPECT_EQ(length, 18u);
    EXPECT_EQ(findHeadEnd(std::string(kMaxRequestHeadBytes, 'a'), length), HeadStatus::Invalid);
}

// One request, one answer (the server closes after each): status line,
// headers and body as the bytes came.
struct Answer {
    int status = 0;
    QByteArray head, body;
};

Answer get(quint16 port, const QByteArray& request, int waitMs = kWaitMs) {
    QTcpSocket s;
    s.connectToHost(QHostAddress::LocalHost, port);
    if (!s.waitForConnected(waitMs)) return {};
    s.write(request);
    QByteArray all;
    QElapsedTimer t;
    t.start();
    while (s.state() == QAbstractSocket::ConnectedState && t.elapsed() < waitMs) {
        QTest::qWait(10);
        all += s.readAll();
    }
    all += s.readAll();
    Answer a;
    const auto end = all.indexOf("\r\n\r\n");
    a.head = all.left(end);
    a.body = end < 0 ? QByteArray() : all.mid(end + 4);
    const QList<QByteArray> words = a.head.split(' ');
    if (words.size() > 1) a.status = words[1].toInt();
    return a;
}

class LivePageTest : public ::testing::Test {
  protected:
    void start(ServerOptions options) {
        ClassConfig c;
        c.classCode = "C1";
        c.initialScene = classScene("sphere(0, 0, 0, 1)");
        session = std::make_unique<ClassSession>(c, clock, nullptr);
        options.livePage.classCode = "C1";
        server = std::make_unique<ClassroomServer>(*session, options);
        ASSERT_TRUE(server->listen(QHostAddress::LocalHost, 0));
    }
    static ServerOptions withWeb() {
        ServerOptions o;
        o.web = true;
        return o;
    }
    quint16 port() const { return server->port(); }
    // The page's event stream, asked for once the first version is shown.
    bool opensEvents(QTcpSocket& s) {
        if (!QTest::qWaitFor([&] { return server->livePage()->shownVersion() >= 1; }, kWaitMs))
            return false;
        s.connectToHost(QHostAddress::LocalHost, port());
        if (!s.waitForConnected(kWaitMs)) return false;
        s.write("GET /events HTTP/1.1\r\n\r\n");
        return true;
    }
    // Reads `s` into `got` until it holds `wanted`.
    static bool readsUntil(QTcpSocket& s, QByteArray& got, const char* wanted) {
        return QTest::qWaitFor(
            [&] {
                got += s.readAll();
                return got.contains(wanted);
            },
            kWaitMs);
    }
    // A member joins the class over WebSocket on the page's own port.
    bool joins(ClassroomClient& client, const QString& name) const {
        ClassroomClient::JoinOptions o;
        o.url = QUrl(QStringLiteral("ws://127.0.0.1:%1").arg(port()));
        o.classCode = "C1";
        o.name = name;
        client.join(o);
        return QTest::qWaitFor([&] { return client.state() == ClassroomClient::State::Joined; },
                               kWaitMs);
    }

    SteadyClock clock;
    std::unique_ptr<ClassSession> session;
    std::unique_ptr<ClassroomServer> server;
};

TEST_F(LivePageTest, ThePageItsScriptAndNothingElseAreServed) {
    start(withWeb());
    const Answer page = get(port(), "GET / HTTP/1.1\r\nHost: x\r\n\r\n");
    EXPECT_EQ(page.status, 200);
    EXPECT_TRUE(page.head.contains("Content-Security-Policy: default-src 'self'"));
    EXPECT_TRUE(page.body.contains("<x3d-canvas"));
    EXPECT_EQ(get(port(), "GET /live.js HTTP/1.1\r\n\r\n").status, 200);
    EXPECT_EQ(get(port(), "GET /viewer/ HTTP/1.1\r\n\r\n").status, 404);
    EXPECT_EQ(get(port(), "GET /etc/passwd HTTP/1.1\r\n\r\n").status, 404);
    EXPECT_EQ(get(port(), "GET /viewer/../live.js HTTP/1.1\r\n\r\n").status, 400);
    EXPECT_EQ(get(port(), "POST / HTTP/1.1\r\nContent-Length: 0\r\n\r\n").status, 405);
    EXPECT_EQ(get(port(), "NONSENSE\r\n\r\n").status, 400);
    // A head that never ends is not waited for past the limit.
    EXPECT_EQ(get(port(), QByteArray(9000, 'a')).status, 400);
}

TEST_F(LivePageTest, TheBakedSceneFollowsAnEditAndMembersShareThePort) {
    start(withWeb());
    ASSERT_TRUE(QTest::qWaitFor([&] { return server->livePage()->shownVersion() >= 1; }, kWaitMs));
    const Answer first = get(port(), "GET /scene.json HTTP/1.1\r\n\r\n");
    ASSERT_EQ(first.status, 200);
    EXPECT_TRUE(first.body.contains("\"version\":1"));
    EXPECT_TRUE(first.body.contains("IndexedFaceSet")) << first.body.left(300).toStdString();
    EXPECT_FALSE(first.body.contains("FShape"));

    ClassroomClient ana;
    ASSERT_TRUE(joins(ana, "Ana"));
    ana.submitEdit(QString::fromStdString(classScene("sphere(1, 0, 0, 0.5)")));
    ASSERT_TRUE(QTest::qWaitFor([&] { return server->livePage()->shownVersion() >= 2; }, kWaitMs));
    const Answer second = get(port(), "GET /scene.json HTTP/1.1\r\nAccept-Encoding: gzip\r\n\r\n");
    EXPECT_EQ(second.status, 200);
    EXPECT_TRUE(second.head.contains("Content-Encoding: gzip"));
}

TEST_F(LivePageTest, TheEventStreamSaysWhichVersionIsReady) {
    start(withWeb());
    QTcpSocket s;
    ASSERT_TRUE(opensEvents(s));
    QByteArray got;
    ASSERT_TRUE(readsUntil(s, got, "event: version\ndata: 1\n\n")) << got.toStdString();
    EXPECT_TRUE(got.startsWith("HTTP/1.1 200"));
    EXPECT_TRUE(got.contains("text/event-stream"));
    EXPECT_TRUE(QTest::qWaitFor([&] { return server->livePage()->streamCount() == 1; }, kWaitMs));
}

TEST_F(LivePageTest, AChatLineCannotForgeAnEventOfTheStream) {
    start(withWeb());
    QTcpSocket s;
    ASSERT_TRUE(opensEvents(s));
    ClassroomClient eve;
    ASSERT_TRUE(joins(eve, "Eve"));
    eve.sendChat("<b>hi</b>\n\nevent: version\ndata: 999");
    QByteArray got;
    ASSERT_TRUE(readsUntil(s, got, "event: chat")) << got.toStdString();
    QTest::qWait(200);
    got += s.readAll();
    // The line breaks stay inside the chat line's JSON: no line of the
    // stream is the forged one, and exactly one chat event came.
    EXPECT_FALSE(got.contains("\ndata: 999")) << got.toStdString();
    EXPECT_EQ(got.count("event: chat\n"), 1) << got.toStdString();
    EXPECT_TRUE(got.contains("\\n\\nevent: version")) << got.toStdString();
    EXPECT_TRUE(got.contains("<b>hi</b>")); // as text in JSON; the page shows it as text
}

TEST_F(LivePageTest, WithTheClassCodeGuardThePageNeedsIt) {
    ServerOptions o = withWeb();
    o.livePage.needsClassCode = true;
    start(o);
    EXPECT_EQ(get(port(), "GET / HTTP/1.1\r\n\r\n").status, 403);
    EXPECT_EQ(get(port(), "GET /?class=WRONG HTTP/1.1\r\n\r\n").status, 403);
    EXPECT_EQ(get(port(), "GET /scene.json HTTP/1.1\r\n\r\n").status, 403);
    EXPECT_EQ(get(port(), "GET /events HTTP/1.1\r\n\r\n").status, 403);
    EXPECT_EQ(get(port(), "GET /?class=C1 HTTP/1.1\r\n\r\n").status, 200);
}

TEST_F(LivePageTest, WithoutTheWebThePortStillServesTheClass) {
    start(ServerOptions{});
    const Answer a = get(port(), "GET / HTTP/1.1\r\n\r\n");
    EXPECT_EQ(a.status, 404);
    EXPECT_TRUE(a.body.contains("--no-web"));
    ClassroomClient ana;
    EXPECT_TRUE(joins(ana, "Ana"));
}

TEST_F(LivePageTest, StrangersWhoNeverFinishTheirHeadsCannotHoardThePort) {
    ServerOptions o = withWeb();
    o.maxUnreadPerAddress = 4;
    o.headMillis = 300;
    start(o);
    std::vector<std::unique_ptr<QTcpSocket>> idle;
    for (int i = 0; i < 8; ++i) {
        idle.push_back(std::make_unique<QTcpSocket>());
        idle.back()->connectToHost(QHostAddress::LocalHost, port());
        ASSERT_TRUE(idle.back()->waitForConnected(kWaitMs));
        idle.back()->write("GET / HTTP/1.1\r\n"); // never ends
    }
    // Past the limit they are closed, and the rest after headMillis: the
    // page answers again.
    EXPECT_TRUE(QTest::qWaitFor(
        [&] {
            return std::all_of(idle.begin(), idle.end(), [](const auto& s) {
                return s->state() == QAbstractSocket::UnconnectedState;
            });
        },
        kWaitMs));
    EXPECT_EQ(get(port(), "GET / HTTP/1.1\r\n\r\n").status, 200);
}

TEST_F(LivePageTest, OneAddressAskingTooOftenIsToldToWait) {
    ServerOptions o = withWeb();
    o.webBurst = 5;
    o.webPerSecond = 0.5;
    start(o);
    int refused = 0;
    for (int i = 0; i < 8; ++i)
        refused += get(port(), "GET /live.js HTTP/1.1\r\n\r\n").status == 429;
    EXPECT_GE(refused, 2);
    // The class itself is not rate-limited by the page's buckets.
    ClassroomClient ana;
    EXPECT_TRUE(joins(ana, "Ana"));
}

} // namespace
} // namespace fl::classroom
