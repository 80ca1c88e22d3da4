"""One jetbot_env node seen by a lockstep learner: its spec, its targets out, its EnvSteps in.

The protocol is docs/training.md's "Writing your own learner" (and the C++ RosVecEnv's): wait for the
latched `~spec`; advertise `~wheel_targets` and wait until the env subscribes; subscribe to
`~env_step` with TCP_NODELAY; call `~reset` and wait until its state also arrives on `~env_step`;
then each step publish WheelTargets with `step` = the current EnvStep.step and wait for the
EnvStep with step + 1. Arrays travel as numpy arrays (rospy.numpy_msg): no per-element Python
work.
"""
import threading
import time
import warnings

import numpy as np
import rospy
from rospy.numpy_msg import numpy_msg

from jetbot_rl.msg import EnvSpec, EnvStep, WheelTargets
from jetbot_rl.srv import Reset, SetCommand, Step

# Lockstep: when the answer to our targets is late, NodeLink.wait() asks the node through ~step
# after WheelTargets.RESEND_AFTER [s, wall], a constant of the protocol (msg/WheelTargets.msg) that
# the C++ client shares.
# After ~reset: call it again when its state has not arrived on ~env_step within this [s].
RESET_CONFIRM = 1.0

_NumpyEnvStep = numpy_msg(EnvStep)
_NumpyWheelTargets = numpy_msg(WheelTargets)


class EnvRejectedError(RuntimeError):
    """The env node refused a request; `node` is its name, `reason` its own words."""

    def __init__(self, node, reason, hint=''):
        self.node = node
        self.reason = reason
        super(EnvRejectedError, self).__init__(
            '%s rejected the request: %s%s' % (node, reason, (' (%s)' % hint) if hint else ''))


#: Per image kind of EnvSpec.image_kinds: its EnvStep fields, numpy dtype and channels.
IMAGE_KINDS = {'rgb': ('images_rgb', 'final_images_rgb', np.uint8, 3),
               'depth': ('images_depth', 'final_images_depth', np.float32, 1),
               'label': ('images_label', 'final_images_label', np.uint8, 1)}


class ImageLayout(object):
    """The images a node's EnvSteps carry (EnvSpec image_kinds, image_height, image_width)."""

    def __init__(self, spec):
        self.kinds = list(spec.image_kinds)
        self.height = int(spec.image_height)
        self.width = int(spec.image_width)

    def shape(self, kind):
        """(height, width, channels) of one image of `kind`."""
        return (self.height, self.width, IMAGE_KINDS[kind][3])

    def read(self, msg, count, final, node):
        """{kind: array (count, height, width, channels)} of `msg`'s images (final: the ended
        episodes' ones); RuntimeError naming the node and field when a size does not fit."""
        out = {}
        for kind in self.kinds:
            field = IMAGE_KINDS[kind][1 if final else 0]
            dtype = IMAGE_KINDS[kind][2]
            data = getattr(msg, field)
            values = (np.frombuffer(data, dtype=dtype) if isinstance(data, (bytes, bytearray))
                      else np.asarray(data, dtype=dtype))
            shape = (count,) + self.shape(kind)
            if values.size != int(np.prod(shape)):
                raise RuntimeError('%s: EnvStep %d: %s has %d values, expected %d (%d images of '
                                   '%s)' % (node, msg.step, field, values.size,
                                            int(np.prod(shape)), count, shape[1:]))
            out[kind] = values.reshape(shape)
        return out


class Batch(object):
    """One node's EnvStep as numpy arrays (shapes from the spec)."""
    __slots__ = ('step', 'obs', 'rewards', 'terminated', 'truncated', 'episode_steps',
                 'reset_env_ids', 'final_obs', 'outcomes', 'images', 'final_images',
                 'image_fresh')

    def __init__(self, msg, num_envs, obs_dim, node, images=None):
        # np.asarray is free for numpy_msg arrays; a plain message (a service answer, or a
        # subscriber of this process created with the plain class first) is converted.
        self.step = msg.step
        self.obs = np.asarray(msg.observations, dtype=np.float32).reshape(-1, obs_dim)
        self.rewards = np.asarray(msg.rewards, dtype=np.float32)
        self.terminated = _flags(msg.terminated)
        self.truncated = _flags(msg.truncated)
        self.episode_steps = np.asarray(msg.episode_steps, dtype=np.uint32)
        self.reset_env_ids = np.asarray(msg.reset_env_ids, dtype=np.uint32)
        self.final_obs = np.asarray(msg.final_observations, dtype=np.float32).reshape(-1, obs_dim)
        outcomes = msg.outcomes
        self.outcomes = (np.frombuffer(outcomes, dtype=np.uint8) if isinstance(outcomes, (bytes, bytearray))
                         else np.asarray(outcomes, dtype=np.uint8))
        if (self.obs.shape[0] != num_envs or self.rewards.shape != (num_envs,)
                or self.terminated.shape != (num_envs,) or self.truncated.shape != (num_envs,)
                or self.episode_steps.shape != (num_envs,)
                or self.final_obs.shape[0] != self.reset_env_ids.shape[0]
                or self.outcomes.shape[0] != self.reset_env_ids.shape[0]
                or np.any(self.outcomes > EnvStep.OUTCOME_OFF_TRACK)):
            raise RuntimeError('%s: EnvStep %d does not match its spec (%d envs, obs_dim %d)'
                               % (node, msg.step, num_envs, obs_dim))
        # The images (ImageLayout `images`): {kind: (n, height, width, channels)}, views of the
        # message's buffers (read-only), and the ended episodes' last ones.
        self.images = images.read(msg, num_envs, False, node) if images else {}
        self.final_images = (images.read(msg, self.reset_env_ids.shape[0], True, node)
                             if images else {})
        self.image_fresh = _flags(msg.images_fresh)


def _flags(data):
    if isinstance(data, (bytes, bytearray)):
        return np.frombuffer(data, dtype=np.uint8).astype(bool)
    return np.asarray(data, dtype=np.uint8).astype(bool)


def call_bounded(calls, timeout, what):
    """Runs the callables `calls` concurrently, each on its own thread, and returns their results
    in order; re-raises the first exception; TimeoutError(`what(i)`) for the first not done after
    `timeout` [s]. rospy service calls have no time-out of their own: this bounds a hung node."""
    results = [None] * len(calls)
    errors = [None] * len(calls)
    done = [threading.Event() for _ in calls]

    def run(i):
        try:
            results[i] = calls[i]()
        except BaseException as e:  # handed to the caller
            errors[i] = e
        finally:
            done[i].set()

    for i in range(len(calls)):
        threading.Thread(target=run, args=(i,), daemon=True).start()
    deadline = time.monotonic() + timeout
    for i in range(len(calls)):
        if not done[i].wait(max(0.0, deadline - time.monotonic())):
            raise TimeoutError(what(i))
    for e in errors:
        if e is not None:
            raise e
    return results


class _TargetsListener(rospy.SubscribeListener):
    """Wakes waits when the env node connects to our ~wheel_targets publisher."""

    def __init__(self, events):
        super(_TargetsListener, self).__init__()
        self._events = events

    def peer_subscribe(self, topic_name, topic_publish, peer_publish):
        with self._events:
            self._events.notify_all()


class NodeLink(object):
    """The lockstep connection to one jetbot_env node (`name`, resolved)."""

    def __init__(self, name, timeout):
        self.name = rospy.resolve_name(name)
        self.timeout = float(timeout)
        self._events = threading.Condition(threading.Lock())
        self.spec = self._wait_spec()
        self.num_envs = int(self.spec.num_envs)
        self.obs_dim = int(self.spec.obs_dim)
        self.action_dim = int(self.spec.action_dim)
        self.images = ImageLayout(self.spec)
        mode = rospy.get_param(self.name + '/mode', 'lockstep')
        if mode != 'lockstep':
            raise ValueError("%s runs in mode '%s': JetbotVecEnv needs lockstep mode (launch it "
                             "with mode:=lockstep)" % (self.name, mode))

        self._step = 0          # EnvStep.step of the current state
        self._answer = None     # newest EnvStep with step > self._step (guarded by _events)
        self._connected = False  # an EnvStep has arrived: the subscription works
        self.state = None       # the current state (Batch)
        self._targets = _NumpyWheelTargets()
        self._sent_at = 0.0
        # queue_size None: publish() writes to the socket itself (no hand-off to a queue thread,
        # which costs a thread switch per step); rospy warns about it, on purpose here.
        with warnings.catch_warnings():
            warnings.simplefilter('ignore', SyntaxWarning)
            self._pub = rospy.Publisher(self.name + '/wheel_targets', _NumpyWheelTargets,
                                        queue_size=None, tcp_nodelay=True,
                                        subscriber_listener=_TargetsListener(self._events))
        image_bytes = sum(np.dtype(IMAGE_KINDS[k][2]).itemsize * int(np.prod(self.images.shape(k)))
                          for k in self.images.kinds)
        message_bytes = 64 + self.num_envs * (4 * (2 * self.obs_dim + 3) + 3 + 2 * image_bytes)
        self._sub = rospy.Subscriber(self.name + '/env_step', _NumpyEnvStep, self._on_env_step,
                                     queue_size=4, tcp_nodelay=True,
                                     buff_size=max(65536, 2 * message_bytes))
        self._reset_srv = rospy.ServiceProxy(self.name + '/reset', Reset)
        self._step_srv = rospy.ServiceProxy(self.name + '/step', Step)
        self._command_srv = rospy.ServiceProxy(self.name + '/set_command', SetCommand)
        try:
            self._wait(lambda: self._pub.get_num_connections() > 0, self.timeout,
                       'subscription of the node to %s/wheel_targets' % self.name)
            try:
                rospy.wait_for_service(self.name + '/reset', self.timeout)
            except rospy.ROSException:
                raise TimeoutError('%s: service %s/reset did not appear within %.1f s'
                                   % (self.name, self.name, self.timeout))
        except BaseException:
            self.close()
            raise

    # ---- set-up ----

    def _wait_spec(self):
        specs = []

        def on_spec(msg):
            with self._events:
                specs.append(msg)
                self._events.notify_all()

        sub = rospy.Subscriber(self.name + '/spec', EnvSpec, on_spec)
        try:
            self._wait(lambda: specs, self.timeout, 'latched spec on %s/spec' % self.name,
                       ': is jetbot_env running there (in lockstep mode)?')
        finally:
            sub.unregister()
        spec = specs[0]
        if (spec.num_envs < 1 or spec.obs_dim < 1 or spec.action_dim < 1
                or len(spec.action_low) != spec.action_dim
                or len(spec.action_high) != spec.action_dim
                or len(spec.observation_low) not in (0, spec.obs_dim)
                or len(spec.observation_high) != len(spec.observation_low)):
            raise ValueError('%s: inconsistent spec (num_envs %d, obs_dim %d, action_dim %d, '
                             '%d action_low, %d action_high, %d observation_low, %d '
                             'observation_high)'
                             % (self.name, spec.num_envs, spec.obs_dim, spec.action_dim,
                                len(spec.action_low), len(spec.action_high),
                                len(spec.observation_low), len(spec.observation_high)))
        for field in ('action', 'observation'):
            low = np.array(getattr(spec, field + '_low'), dtype=np.float64)
            high = np.array(getattr(spec, field + '_high'), dtype=np.float64)
            if not np.all(low <= high):  # also NaN
                raise ValueError('%s: inconsistent spec: %s_low %s is not <= %s_high %s'
                                 % (self.name, field, low.tolist(), field, high.tolist()))
        return spec

    def _wait(self, condition, timeout, what, hint=''):
        """Waits until condition() (woken by our callbacks); TimeoutError naming the node."""
        deadline = time.monotonic() + timeout
        with self._events:
            while not condition():
                left = deadline - time.monotonic()
                if rospy.is_shutdown():
                    raise RuntimeError('%s: ROS shut down while waiting for %s' % (self.name, what))
                if left <= 0:
                    raise TimeoutError('%s: no %s within %.1f s%s'
                                       % (self.name, what, timeout, hint))
                # Woken by our callbacks; the periodic re-check only notices a ROS shutdown.
                self._events.wait(min(left, 0.1))

    def _on_env_step(self, msg):
        with self._events:
            self._connected = True
            if msg.step > self._step and (self._answer is None or msg.step > self._answer.step):
                self._answer = msg
            self._events.notify_all()

    def close(self):
        self._pub.unregister()
        self._sub.unregister()
        for srv in (self._reset_srv, self._step_srv, self._command_srv):
            srv.close()

    # ---- reset ----

    def reset_call(self, env_ids, seed):
        """Calls ~reset (env_ids empty: all envs; seed < 0: keep the random streams); returns the
        answer's state. Raises EnvRejectedError with the node's reason, TimeoutError when the
        service stays unreachable for the timeout."""
        deadline = time.monotonic() + self.timeout
        while True:
            try:
                res = self._reset_srv(env_ids=env_ids, seed=seed)
                break
            except (rospy.ServiceException, rospy.ROSException, OSError) as e:
                # e.g. a restarted node whose ~reset is not registered yet: wait for it
                error = e
            if rospy.is_shutdown():
                raise RuntimeError('%s: ROS shut down while calling ~reset' % self.name)
            try:
                rospy.wait_for_service(self.name + '/reset', max(0.0, deadline - time.monotonic()))
            except rospy.ROSException:
                raise TimeoutError('%s: ~reset unreachable for %.1f s: %s'
                                   % (self.name, self.timeout, error))
        if not res.success:
            raise EnvRejectedError(self.name, res.message)
        return res.state

    def adopt_reset(self, state):
        """Makes the answer of a ~reset the current state, once our subscription is known to
        work (the reset's state arrived on ~env_step): otherwise a step's answer could be lost.
        Returns False when it has not arrived within RESET_CONFIRM: reset again."""
        batch = Batch(state, self.num_envs, self.obs_dim, self.name, self.images)
        with self._events:
            self._step = state.step
            self._answer = None  # anything older, or this reset's own publication
        try:
            self._wait(lambda: self._connected, RESET_CONFIRM, 'reset state on ~env_step')
        except TimeoutError:
            return False
        self.state = batch
        return True

    # ---- lockstep step ----

    def send(self, flat_actions):
        """Publishes the targets for the current step (float32, num_envs x action_dim)."""
        self._targets.step = self._step
        self._targets.velocities = flat_actions
        self._sent_at = time.monotonic()
        with self._events:
            unsolicited = self._answer is not None
        if unsolicited:
            return False  # someone else stepped the node: wait() asks it for the reason
        self._pub.publish(self._targets)
        return True

    def wait(self, sent):
        """Waits for the EnvStep answering the targets of send() and makes it the current state.

        Without an answer after WheelTargets.RESEND_AFTER [s], calls ~step with the same targets:
        it applies them when the topic message was lost (while the env's subscription was still
        connecting), answers "stale" with the new state when they were applied and the answer is
        late, or gives the node's reason for refusing them (raised as EnvRejectedError).
        TimeoutError naming the node when nothing comes within the timeout.
        """
        expected = self._step + 1
        deadline = self._sent_at + self.timeout
        unreachable = ''
        if sent:
            msg = self._take_answer(min(deadline, self._sent_at + WheelTargets.RESEND_AFTER))
        else:
            msg = None
        while msg is None:
            left = deadline - time.monotonic()
            if rospy.is_shutdown():
                raise RuntimeError('ROS shut down while waiting for %s to answer step %d'
                                   % (self.name, self._step))
            if left <= 0:
                raise TimeoutError('%s did not answer step %d within %.1f s%s'
                                   % (self.name, self._step, self.timeout, unreachable))
            try:
                res = call_bounded(
                    [lambda: self._step_srv(actions=self._targets)], left,
                    lambda i: '%s did not answer step %d within %.1f s (its ~step service '
                    'hangs)' % (self.name, self._step, self.timeout))[0]
            except (rospy.ServiceException, rospy.ROSException, OSError) as e:
                if not sent:  # the EnvStep waiting for us is someone else's: never take it
                    raise EnvRejectedError(
                        self.name, 'it stepped to EnvStep %d before our targets for step %d went '
                        'out (its ~step service: %s)' % (self._answer.step, self._step, e),
                        'is another client stepping %s? reset() re-synchronises' % self.name)
                unreachable = ' (its ~step service: %s)' % e
                msg = self._take_answer(min(deadline,
                                            time.monotonic() + WheelTargets.RESEND_AFTER))
                continue
            if res.success or (sent and res.state.step == expected and 'stale' in res.message):
                msg = res.state
                break
            raise EnvRejectedError(self.name, res.message,
                                   'is another client stepping %s, or was it restarted? reset() '
                                   're-synchronises' % self.name)
        if msg.step != expected:
            raise EnvRejectedError(
                self.name, 'expected EnvStep %d, got %d' % (expected, msg.step),
                'is another client stepping %s? reset() re-synchronises' % self.name)
        batch = Batch(msg, self.num_envs, self.obs_dim, self.name, self.images)
        with self._events:
            self._step = msg.step
            if self._answer is not None and self._answer.step <= msg.step:
                self._answer = None
        self.state = batch
        return batch

    def _take_answer(self, until):
        """The answer received so far, waiting for it until `until` (monotonic time)."""
        with self._events:
            while self._answer is None:
                left = until - time.monotonic()
                if left <= 0 or rospy.is_shutdown():
                    break
                self._events.wait(left)
            msg, self._answer = self._answer, None
            return msg

    # ---- command task ----

    def set_command(self, env, x, y, hold):
        try:
            res = call_bounded(
                [lambda: self._command_srv(env_id=env, x=x, y=y, hold=hold)], self.timeout,
                lambda i: '%s did not answer set_command within %.1f s'
                % (self.name, self.timeout))[0]
        except (rospy.ServiceException, rospy.ROSException, OSError) as e:
            raise RuntimeError('%s: call of %s/set_command failed: %s' % (self.name, self.name, e))
        if not res.success:
            raise EnvRejectedError(self.name, res.message)
