#pragma once
// Drives a ClassSession by frames, as a server would, and keeps what each
// connection received as JSON objects.
#include "classroom/class_session.h"

#include <QJsonDocument>
#include <QJsonObject>

#include <map>
#include <string>
#include <vector>

namespace fl::classroom::test {

class Harness {
  public:
    explicit Harness(ClassSession& session) : session_(session) {}

    // 0 when the session refuses the connection (too many unjoined ones).
    ConnectionId connect(const std::string& peer = "127.0.0.1") {
        return session_.connect(peer).value_or(0);
    }

    void send(ConnectionId c, const std::string& frame) { take(session_.receive(c, frame)); }
    void drop(ConnectionId c) { take(session_.disconnected(c)); }
    void tick() { take(session_.tick()); }
    void take(const std::vector<Delivery>& out) {
        for (const Delivery& d : out) {
            inbox_[d.to].push_back(QJsonDocument::fromJson(d.frame.toUtf8()).object());
            if (d.close) closed_[d.to] = true;
        }
    }

    // Joins and returns the connection; the welcome is in its inbox.
    ConnectionId join(const std::string& name, const std::string& role = "student",
                      const std::string& extra = {}) {
        const ConnectionId c = connect();
        send(c, R"({"type":"join","class":"C1","name":")" + name + R"(","role":")" + role + "\"" +
                    extra + "}");
        return c;
    }

    std::vector<QJsonObject>& inbox(ConnectionId c) { return inbox_[c]; }
    // The newest message of `type` to `c`; an empty object when none.
    QJsonObject last(ConnectionId c, const char* type) const {
        const auto it = inbox_.find(c);
        if (it == inbox_.end()) return {};
        for (auto m = it->second.rbegin(); m != it->second.rend(); ++m)
            if ((*m)["type"].toString() == QLatin1String(type)) return *m;
        return {};
    }
    int count(ConnectionId c, const char* type) const {
        int n = 0;
        const auto it = inbox_.find(c);
        if (it != inbox_.end())
            for (const auto& m : it->second)
                n += m["type"].toString() == QLatin1String(type);
        return n;
    }
    bool closed(ConnectionId c) const { return closed_.count(c) > 0; }
    void clear() { inbox_.clear(); }

  private:
    ClassSession& session_;
    std::map<ConnectionId, std::vector<QJsonObject>> inbox_;
    std::map<ConnectionId, bool> closed_;
};

inline std::string editFrame(long long version, const std::string& scene) {
    QJsonObject o{{"type", "edit"},
                  {"version", static_cast<double>(version)},
                  {"scene", QString::fromStdString(scene)}};
    return QJsonDocument(o).toJson(QJsonDocument::Compact).toStdString();
}

inline std::string chatFrame(const std::string& text) {
    QJsonObject o{{"type", "chat"}, {"text", QString::fromStdString(text)}};
    return QJsonDocument(o).toJson(QJsonDocument::Compact).toStdString();
}

} // namespace fl::classroom::test
