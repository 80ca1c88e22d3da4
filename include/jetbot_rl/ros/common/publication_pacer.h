#pragma once

#include <boost/signals2/connection.hpp>
#include <cstdint>
#include <memory>

namespace jetbot_rl {

/**
 * Keeps a node from handing roscpp more messages per topic than a subscriber connection's queue
 * holds between two passes of roscpp's network thread (docs/reliability.md).
 *
 * roscpp's publish() only queues the message; at its next pass the network thread hands all that
 * were queued to every subscriber connection, whose queue keeps the newest `queue_size` of them.
 * A burst of more publications than that between two passes therefore loses the oldest for every
 * subscriber, fast or slow, without a word (issue 49: back-to-back ~step calls lost up to 87 % of
 * ~env_step under load). A node that publishes one message per topic per state calls wait()
 * before each state's publications: after `limit` states it waits for the network thread's next
 * pass, so that no pass ever gets more than twice `limit` (a state published while a pass hands
 * over counts in the next).
 */
class PublicationPacer {
 public:
  /// `limit`: states per pass, at most half the publishers' queue size; `timeout` [s, wall]: the
  /// longest one wait lasts (a network thread that makes no pass for that long).
  PublicationPacer(int limit, double timeout);
  ~PublicationPacer();
  PublicationPacer(const PublicationPacer&) = delete;
  PublicationPacer& operator=(const PublicationPacer&) = delete;

  /// Call before publishing a state: returns at once while fewer than `limit` states went out
  /// since the network thread's last pass, else when it has made one (true) or after the time-out
  /// (false: this state may push older messages out of subscriber queues). Inside an
  /// InlineCallbackQueue's callback it never waits (no pass can come meanwhile: the thread is the
  /// network thread, or an in-process publisher's holding the lock a pass needs).
  bool wait();
  /// States that waited for a pass, and waits that timed out, so far.
  std::uint64_t waits() const;
  std::uint64_t timeouts() const;

 private:
  struct Shared;
  std::shared_ptr<Shared> shared_;  // shared with the listener, which may run once after we go
  int limit_;
  double timeout_;
  boost::signals2::connection listener_;
};

}  // namespace jetbot_rl
