#pragma once

namespace jetbot_rl {

/**
 * Waits until roscpp's network thread has written what was published before the call to every
 * subscriber connection that accepts it, or `timeout` [s, wall]; true when it has.
 *
 * roscpp publishes by queueing the message for its network (poll) thread, and ros::shutdown()
 * closes the connections with whatever is still queued: call this between the last publish of a
 * node and its shutdown. It waits for two passes of that thread (each writes the queued messages
 * that the sockets take); a stalled subscriber, whose socket takes nothing, holds it up only until
 * `timeout`. Never call it from a callback that runs in the network thread.
 */
bool flushPublications(double timeout);

}  // namespace jetbot_rl
