#pragma once
// Throttles: a token bucket per member for edits and chat, and a count of
// failed joins per peer address (a guessed class code or key costs a slot).
#include "clock.h"

#include <deque>
#include <map>
#include <string>

namespace fl::classroom {

class TokenBucket {
  public:
    TokenBucket(double burst, double perSecond, Millis now)
        : burst_(burst), perSecond_(perSecond), tokens_(burst), last_(now) {}
    // Takes one token if there is one.
    bool take(Millis now);

  private:
    double burst_;
    double perSecond_;
    double tokens_;
    Millis last_;
};

class FailedJoinThrottle {
  public:
    FailedJoinThrottle(int maxFailures, Millis window) : max_(maxFailures), window_(window) {}
    bool blocked(const std::string& address, Millis now);
    void failed(const std::string& address, Millis now);

  private:
    static constexpr std::size_t kMaxAddresses = 10'000;
    void forgetOld(std::deque<Millis>& times, Millis now) const;
    int max_;
    Millis window_;
    std::map<std::string, std::deque<Millis>> failures_;
};

} // namespace fl::classroom
