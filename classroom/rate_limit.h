#pragma once
// Throttles: a token bucket per member for edits and chat, token buckets per
// peer address (joins), a count of wrong class codes per address, and one
// growing delay for the instructor key, whoever guesses it.
#include "class_clock.h"

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
    // Whether the bucket is full again at `now` (nothing to remember).
    bool full(Millis now) const;

  private:
    double burst_;
    double perSecond_;
    double tokens_;
    Millis last_;
};

// A token bucket per peer address, in bounded memory: past kMaxAddresses
// the full buckets are forgotten (a full bucket is what a new one is).
class AddressBuckets {
  public:
    AddressBuckets(double burst, double perSecond) : burst_(burst), perSecond_(perSecond) {}
    bool take(const std::string& address, Millis now);

  private:
    static constexpr std::size_t kMaxAddresses = 10'000;
    double burst_;
    double perSecond_;
    std::map<std::string, TokenBucket> buckets_;
};

// The instructor key, guessed from anywhere: after `freeTries` wrong keys in
// a row, every instructor join waits a delay that doubles with each further
// wrong key (1 s, 2 s, 4 s ... up to `maxDelay`) — the right key too, or the
// answer would tell a guesser which key was right. The right key resets it.
class KeyThrottle {
  public:
    KeyThrottle(int freeTries, Millis maxDelay) : freeTries_(freeTries), maxDelay_(maxDelay) {}
    // Milliseconds an instructor join must still wait (0: it may try now).
    Millis waiting(Millis now) const { return now < until_ ? until_ - now : 0; }
    void failed(Millis now);
    void succeeded() { failures_ = 0; }

  private:
    int freeTries_;
    Millis maxDelay_;
    int failures_ = 0;
    Millis until_ = 0;
};

// Wrong class codes per peer address within a window. A blocked address may
// still join with the right code (a NAT or a TLS proxy is a whole class
// behind one address): only its wrong guesses are cut short.
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
