"""JetbotVecEnv: one or several jetbot_env nodes (lockstep mode) as one gymnasium-style vector env.

    from jetbot_rl import JetbotVecEnv
    with JetbotVecEnv("/jetbot_env") as env:
        obs, infos = env.reset(seed=0)
        obs, rewards, terminations, truncations, infos = env.step(env.action_space.sample())

The node resets an env that ends within the same step (gymnasium's same-step auto-reset):
the returned observation is the new episode's first, the last one is in infos["final_obs"], and
how the episode ended in infos["outcome"] (masks "_final_obs", "_outcome").

With a camera (docs/camera.md), `observation="image"` makes the observation the camera's rgb8
image, a uint8 Box (H, W, 3) per env (channels last, in R, G, B order, rows from the top):
Stable-Baselines3's CnnPolicy takes it as is. `observation="dict"` gives a Dict of the vector
observation and every image the node sends (SB3's MultiInputPolicy).
"""
import numbers
import time

import numpy as np
import rospy

from jetbot_rl.msg import EnvSpec
from jetbot_rl.node_link import EnvRejectedError, NodeLink, call_bounded
from jetbot_rl.observations import OBSERVATIONS, Observations, scatter
from jetbot_rl.spaces import make_box
from jetbot_rl.srv import ResetRequest

try:  # optional: subclass gymnasium's VectorEnv and name its auto-reset mode when installed
    from gymnasium.vector import VectorEnv as _Base
    try:
        from gymnasium.vector import AutoresetMode as _AutoresetMode
        SAME_STEP = _AutoresetMode.SAME_STEP
    except ImportError:  # gymnasium 1.0 has no AutoresetMode
        SAME_STEP = 'SameStep'
except ImportError:
    _Base = object
    SAME_STEP = 'SameStep'  # the value of gymnasium.vector.AutoresetMode.SAME_STEP

#: reset(seed=s) reseeds node k (in list order) with s + k * NODE_SEED_STRIDE (2**32, the constant
#: of srv/Reset.srv that the C++ client shares).
NODE_SEED_STRIDE = ResetRequest.NODE_SEED_STRIDE
#: ~spec fields every node of one JetbotVecEnv must agree on: every EnvSpec field but num_envs
#: (read from the message, so that a field added to EnvSpec.msg is checked too).
SHARED_SPEC_FIELDS = tuple(f for f in EnvSpec.__slots__ if f != 'num_envs')
_INT64_MAX = 2 ** 63 - 1



class JetbotVecEnv(_Base):
    """jetbot_env nodes in lockstep mode as one vector env of `num_envs` envs (gymnasium 1.x API).

    `env_nodes`: an env node's name (e.g. "/jetbot_env", the node's name, not a topic) or a list
    of them, as the trainer's `env_nodes` parameter; relative names resolve in this process's
    namespace. With several nodes the batch is their envs in list order; every step goes out to
    all nodes before any answer is awaited. (The keyword was `envs` before: it is refused with a
    TypeError naming `env_nodes`.)
    `timeout` [s, wall]: how long a node may take to appear or to answer.
    `normalize_actions`: False (default): actions in the nodes' units, within [action_low,
    action_high]; True: every action component in [-1, 1] (the action spaces are Box(-1, 1)),
    mapped linearly onto [action_low, action_high] before it is sent; values outside [-1, 1] are
    clipped to it.
    `observation`: "vector" (default): float32 (num_envs, obs_dim), the task's observation;
    "image": the camera's rgb8 images, uint8 (num_envs, H, W, 3), channels last in R, G, B order
    (the node must send rgb: EnvSpec image_kinds); "dict": {"vector": the task's observation, and
    per image kind the node sends, "rgb" uint8 (H, W, 3), "depth" float32 (H, W, 1) [m] along the
    optical axis (REP 118: +inf beyond the far clip, -inf nearer than the near one), "label" uint8
    (H, W, 1)}. infos["final_obs"] has the observation's structure; with images,
    infos["image_fresh"] (bool, num_envs) says where the camera made them in this step.
    Calls rospy.init_node (anonymous, disable_signals=True) unless this process already did.
    """

    metadata = {'autoreset_mode': SAME_STEP}
    render_mode = None

    def __init__(self, env_nodes='/jetbot_env', timeout=10.0, normalize_actions=False,
                 observation='vector', **renamed):
        self.closed = True  # until every node is connected
        self._links = []
        if 'envs' in renamed:
            raise TypeError('JetbotVecEnv: envs was renamed env_nodes')
        if renamed:
            raise TypeError('JetbotVecEnv() got an unexpected keyword argument %r'
                            % sorted(renamed)[0])
        names = [env_nodes] if isinstance(env_nodes, str) else list(env_nodes)
        if not names or not all(isinstance(n, str) and n for n in names):
            raise ValueError('JetbotVecEnv: env_nodes must be an env node name or a non-empty '
                             'list of them, got %r' % (env_nodes,))
        if (isinstance(timeout, bool) or not isinstance(timeout, numbers.Real)
                or not np.isfinite(timeout) or timeout <= 0):
            raise ValueError('JetbotVecEnv: timeout must be > 0 s, got %r' % (timeout,))
        if not isinstance(normalize_actions, (bool, np.bool_)):
            raise TypeError('JetbotVecEnv: normalize_actions must be True or False, got %r'
                            % (normalize_actions,))
        if observation not in OBSERVATIONS:
            raise ValueError('JetbotVecEnv: observation must be one of %s, got %r'
                             % (', '.join(OBSERVATIONS), observation))
        if not rospy.core.is_initialized():
            rospy.init_node('jetbot_vec_env', anonymous=True, disable_signals=True)
        try:
            for name in names:
                link = NodeLink(name, timeout)
                if any(link.name == other.name for other in self._links):
                    raise ValueError('JetbotVecEnv: node %s is listed twice' % link.name)
                self._links.append(link)
                self._check_same_spec(self._links[0], link)
        except BaseException:
            for link in self._links:
                link.close()
            raise
        self.timeout = float(timeout)
        self.normalize_actions = bool(normalize_actions)
        self.closed = False
        self._needs_reset = True  # no current state: until a reset succeeds
        first = self._links[0].spec
        self.specs = [link.spec for link in self._links]
        self.nodes = [link.name for link in self._links]
        self.node_num_envs = [link.num_envs for link in self._links]
        self.num_envs = sum(self.node_num_envs)
        self._offsets = np.cumsum([0] + self.node_num_envs)
        # Every shared ~spec field as an attribute of its Python type (numbers as numpy arrays),
        # read from the message: a field added to EnvSpec.msg is here too.
        for field, slot_type in zip(EnvSpec.__slots__, EnvSpec._slot_types):
            if field in SHARED_SPEC_FIELDS:
                setattr(self, field, _spec_value(getattr(first, field), slot_type))
        # The bounds: float32 arrays of their sizes, unbounded where the spec gives none.
        self.action_low = _bound(first.action_low, self.action_dim, -np.inf)
        self.action_high = _bound(first.action_high, self.action_dim, np.inf)
        self.observation_low = _bound(first.observation_low, self.obs_dim, -np.inf)
        self.observation_high = _bound(first.observation_high, self.obs_dim, np.inf)
        n = self.num_envs
        if self.normalize_actions:
            if not (np.all(np.isfinite(self.action_low)) and np.all(np.isfinite(self.action_high))):
                self.close()
                raise ValueError('JetbotVecEnv: normalize_actions=True needs finite action bounds; '
                                 '%s has action_low %s, action_high %s'
                                 % (self.nodes[0], self.action_low, self.action_high))
            low = np.full(self.action_dim, -1.0, dtype=np.float32)
            high = np.full(self.action_dim, 1.0, dtype=np.float32)
        else:
            low, high = self.action_low, self.action_high
        self.observation = observation
        layout = self._links[0].images
        if observation == 'image' and 'rgb' not in layout.kinds:
            self.close()
            raise ValueError("JetbotVecEnv: observation='image' needs the camera's rgb images, "
                             "but %s sends image_kinds %s (set camera/images to include rgb, "
                             "camera/batch_images true, and give the robot a camera: "
                             "docs/camera.md)" % (self.nodes[0], layout.kinds))
        self._observations = Observations(observation, self.observation_low,
                                          self.observation_high, layout)
        self.single_observation_space = self._observations.space(())
        self.single_action_space = make_box(low, high, (self.action_dim,))
        self.observation_space = self._observations.space((n,))
        self.action_space = make_box(np.tile(low, (n, 1)), np.tile(high, (n, 1)),
                                     (n, self.action_dim))
        # float64: the ends of [-1, 1] map exactly onto the float32 bounds
        self._action_offset = self.action_low.astype(np.float64)
        self._action_scale = (self.action_high.astype(np.float64) - self._action_offset) / 2.0
        self._all_envs = np.ones(n, dtype=bool)

    @staticmethod
    def _check_same_spec(first, link):
        for field in SHARED_SPEC_FIELDS:
            a, b = getattr(first.spec, field), getattr(link.spec, field)
            if isinstance(a, (list, tuple, np.ndarray)):
                a, b = list(a), list(b)
            if a != b:
                raise ValueError('JetbotVecEnv: %s has spec field %s = %r, but %s has %r: all '
                                 'nodes of one JetbotVecEnv must agree'
                                 % (link.name, field, b, first.name, a))

    # ---- the gymnasium VectorEnv API ----

    def reset(self, seed=None, options=None):
        """Resets every env (or those in options["reset_mask"]) and returns (obs, infos).

        `seed`: None keeps the envs' random streams; an int >= 0 reseeds them, node k of the list
        with seed + k * NODE_SEED_STRIDE (one node: exactly `seed`). `options`: None or
        {"reset_mask": bool array (num_envs,)} to reset only those envs (the others keep their
        state; needs a full reset after an interrupted step). Also re-synchronises after an
        interrupted, timed-out or rejected step.
        """
        self._check_open()
        seeds = self.node_seeds(seed)
        mask = self._reset_mask(options)
        if mask is not None and self._needs_reset:
            raise RuntimeError('JetbotVecEnv: no current state (after an interrupted, timed-out '
                               'or rejected step, or before the first reset): call reset() '
                               'without reset_mask first')
        todo = []  # (link, env_ids, seed)
        for k, link in enumerate(self._links):
            if mask is None:
                todo.append((link, [], seeds[k]))
            else:
                ids = np.flatnonzero(mask[self._offsets[k]:self._offsets[k + 1]])
                if ids.size:  # an empty list would mean all envs
                    todo.append((link, ids.astype(np.uint32).tolist(), seeds[k]))
        self._needs_reset = True
        # A node whose reset state has not arrived on ~env_step within a second (the
        # subscription still connecting) is reset again, as RosVecEnv does.
        deadline = time.monotonic() + self.timeout
        while todo:
            # (+1 s: a node whose service is unreachable is reported by reset_call itself)
            states = call_bounded(
                [lambda t=t: t[0].reset_call(t[1], t[2]) for t in todo], self.timeout + 1.0,
                lambda i: '%s did not answer ~reset within %.1f s' % (todo[i][0].name,
                                                                      self.timeout))
            todo = [t for t, state in zip(todo, states) if not t[0].adopt_reset(state)]
            if todo and time.monotonic() > deadline:
                raise TimeoutError('%s: the state of ~reset did not arrive on %s/env_step '
                                   'within %.1f s' % (todo[0][0].name, todo[0][0].name,
                                                      self.timeout))
        self._needs_reset = False
        batches = [link.state for link in self._links]
        obs = self._observations.of(batches)
        return obs, self._episode_infos(batches)

    def step(self, actions):
        """One control step of every env with `actions`, shape (num_envs, action_dim): in the
        nodes' units ([rad/s]; twist: [m/s, rad/s]), or in [-1, 1] with normalize_actions; returns
        (obs, rewards, terminations, truncations, infos), see the class doc and docs/python.md."""
        self._check_open()
        a = self._check_actions(actions)
        if self.normalize_actions:
            a = self._from_normalized(a)
        if self._needs_reset:
            raise RuntimeError('JetbotVecEnv: no current state of %s (after an interrupted, '
                               'timed-out or rejected step, or before the first reset): call '
                               'reset() to re-synchronise' % ', '.join(self.nodes))
        self._needs_reset = True  # until every answer is in
        links, offsets = self._links, self._offsets
        if len(links) == 1:
            sent = [links[0].send(a.reshape(-1))]
        else:  # all targets out before any answer is awaited: the nodes step concurrently
            sent = [link.send(a[offsets[k]:offsets[k + 1]].reshape(-1))
                    for k, link in enumerate(links)]
        batches = [link.wait(s) for link, s in zip(links, sent)]
        self._needs_reset = False

        obs = self._observations.of(batches)
        rewards = np.concatenate([b.rewards for b in batches])
        terminations = np.concatenate([b.terminated for b in batches])
        truncations = np.concatenate([b.truncated for b in batches])
        infos = self._episode_infos(batches)
        ended = [b.reset_env_ids.astype(np.int64) + offsets[k]
                 for k, b in enumerate(batches) if b.reset_env_ids.size]
        if ended:
            ids = np.concatenate(ended)
            final_obs = scatter(self._observations.of(batches, final=True), ids, self.num_envs)
            final_mask = np.zeros(self.num_envs, dtype=bool)
            final_mask[ids] = True
            infos['final_obs'] = final_obs
            infos['_final_obs'] = final_mask
            # How each ended episode ended (EnvStep.OUTCOME_*: 0 time-out, 1 success, 2-4 a
            # collision with the world, a mover or a robot, 5 a round's wait that is no episode,
            # 6 off the tape), for the envs in _outcome (the same envs as _final_obs; a mask of its
            # own, as gymnasium's "_key" convention has one per key).
            outcome = np.zeros(self.num_envs, dtype=np.uint8)
            outcome[ids] = np.concatenate([b.outcomes for b in batches])
            infos['outcome'] = outcome
            infos['_outcome'] = final_mask.copy()
        return obs, rewards, terminations, truncations, infos

    def close(self, **kwargs):
        """Unregisters from every node (idempotent); the nodes keep running."""
        if self.closed:
            return
        self.closed = True
        for link in self._links:
            link.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
        return False

    def __del__(self):
        try:
            self.close()
        except Exception:  # at interpreter exit rospy may be gone already
            pass

    def __repr__(self):
        return 'JetbotVecEnv(%r, num_envs=%d)' % (getattr(self, 'nodes', []),
                                                  getattr(self, 'num_envs', 0))

    @property
    def unwrapped(self):
        """This env: what gymnasium's vector wrappers return as their `unwrapped`."""
        return self

    def node_seeds(self, seed):
        """The seed each node's ~reset gets from reset(seed=seed), in list order: -1 (keep the
        random streams) for None, else seed + k * NODE_SEED_STRIDE for node k. ValueError for a
        seed that is not None or an int >= 0, or one whose last node's seed exceeds 2**63 - 1."""
        if seed is None:
            return [-1] * len(self._links)
        if isinstance(seed, bool) or not isinstance(seed, numbers.Integral) or seed < 0:
            raise ValueError('reset: seed must be None or an int >= 0, got %r' % (seed,))
        seeds = [int(seed) + k * NODE_SEED_STRIDE for k in range(len(self._links))]
        if seeds[-1] > _INT64_MAX:
            raise ValueError('reset: seed %d too large: node %s would get %d > 2**63 - 1'
                             % (seed, self.nodes[-1], seeds[-1]))
        return seeds

    # ---- the command task ----

    def set_command(self, env, x, y, hold=False):
        """Task `command`: sets env `env`'s command to the unit vector along (x, y) in its ground
        plane, observed from the next step (the node's ~set_command). `hold`: keep it across the
        env's resets. ValueError for a bad env or value; EnvRejectedError with the node's reason
        (e.g. another task)."""
        self._check_open()
        link, local = self._locate_env(env, 'set_command: env')
        for label, v in (('x', x), ('y', y)):
            if isinstance(v, bool) or not isinstance(v, numbers.Real) or not np.isfinite(v):
                raise ValueError('set_command: %s = %r for env %d (%s env %d) is not a finite '
                                 'number' % (label, v, env, link.name, local))
        link.set_command(local, float(x), float(y), bool(hold))

    # ---- helpers ----

    def _check_open(self):
        if self.closed:
            raise RuntimeError('JetbotVecEnv of %s is closed' % ', '.join(self.nodes))

    def _reset_mask(self, options):
        if options is None:
            return None
        if not isinstance(options, dict) or set(options) - {'reset_mask'}:
            raise ValueError("reset: options must be None or {'reset_mask': bool array of shape "
                             "(%d,)}, got %r" % (self.num_envs, options))
        if 'reset_mask' not in options:
            return None
        mask = np.asarray(options['reset_mask'])
        if mask.dtype != np.bool_ or mask.shape != (self.num_envs,):
            raise ValueError("reset: options['reset_mask'] must be a bool array of shape (%d,), "
                             "got dtype %s shape %s" % (self.num_envs, mask.dtype, mask.shape))
        return mask

    def _check_actions(self, actions):
        try:
            if isinstance(actions, np.ndarray) and actions.dtype == np.float32:
                a = actions
            else:
                with np.errstate(over='ignore', invalid='ignore'):  # reported below
                    a = np.asarray(actions, dtype=np.float32)
        except (TypeError, ValueError) as e:
            raise ValueError('step: actions for %s are not numbers: %s'
                             % (', '.join(self.nodes), e))
        if a.shape != (self.num_envs, self.action_dim):
            raise ValueError('step: actions have shape %s, expected (num_envs, action_dim) = '
                             '(%d, %d) for %s' % (a.shape, self.num_envs, self.action_dim,
                                                  ', '.join(self.nodes)))
        finite = np.isfinite(a)
        if not finite.all():
            env, dim = (int(i) for i in np.argwhere(~finite)[0])
            link, local = self._locate_env(env, 'env')
            raise ValueError('step: actions[%d, %d] = %r (env %d: %s env %d, %s) is not a '
                             'finite float32; nothing was sent'
                             % (env, dim, np.asarray(actions)[env, dim].item(), env, link.name,
                                local, self.action_names[dim]))
        return np.ascontiguousarray(a)

    def _from_normalized(self, a):
        """Actions in [-1, 1] (clipped to it) -> [action_low, action_high], float32."""
        a = np.clip(a.astype(np.float64), -1.0, 1.0)
        out = (self._action_offset + (a + 1.0) * self._action_scale).astype(np.float32)
        return np.clip(out, self.action_low, self.action_high)

    def _locate_env(self, env, what):
        if (isinstance(env, bool) or not isinstance(env, numbers.Integral)
                or not 0 <= env < self.num_envs):
            raise ValueError('%s = %r is not in [0, %d)' % (what, env, self.num_envs))
        k = int(np.searchsorted(self._offsets, env, side='right')) - 1
        return self._links[k], int(env - self._offsets[k])

    def _episode_infos(self, batches):
        steps = np.concatenate([b.episode_steps for b in batches]).astype(np.int64)
        infos = {'episode_steps': steps, '_episode_steps': self._all_envs.copy()}
        if self.observation != 'vector' and self._observations.layout.kinds:
            infos['image_fresh'] = np.concatenate([b.image_fresh for b in batches])
            infos['_image_fresh'] = self._all_envs.copy()
        return infos


def _spec_value(value, slot_type):
    """A ~spec field's value as Python holds it: lists of numbers as numpy arrays of their width,
    lists of names as lists, integers as int, floats as float, bool as bool."""
    if slot_type.endswith('[]'):
        if slot_type.startswith('string'):
            return list(value)
        return np.array(value, dtype=np.float32 if slot_type.startswith('float32') else np.float64)
    if slot_type == 'bool':
        return bool(value)
    if slot_type.startswith(('int', 'uint')):
        return int(value)
    if slot_type.startswith('float'):
        return float(value)
    return value


def _bound(values, size, unbounded):
    """A float32 array of `size` bounds from a spec field: `unbounded` (+-inf) everywhere when the
    field is empty; a negated zero (-0., e.g. a twist action's lower bound forwards only) is 0."""
    if len(values) == 0:
        return np.full(size, unbounded, dtype=np.float32)
    return np.array(values, dtype=np.float32) + np.float32(0.0)


__all__ = ['JetbotVecEnv', 'EnvRejectedError', 'NODE_SEED_STRIDE', 'SHARED_SPEC_FIELDS',
           'SAME_STEP', 'OBSERVATIONS']
