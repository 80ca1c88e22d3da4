"""What gymnasium's vector wrappers and Stable-Baselines3 do with a JetbotVecEnv and a
JetbotSB3VecEnv, for the Python client's rostests: the real libraries when they are importable,
else stand-ins that reproduce the behaviour the tests rely on, each naming the library version it
mirrors (gymnasium 1.2.3, stable-baselines3 2.4.1; neither is a Debian 12 package).

    rescale_action(env, low, high)      gymnasium.wrappers.vector.RescaleAction
    set_random_seed(venv, seed)         what PPO(..., seed=seed) does to its env
    update_info_buffer(infos, dones)    BaseAlgorithm._update_info_buffer: rollout/success_rate
    evaluate_successes(venv, policy, n) evaluate_policy with EvalCallback's success callback
"""
import collections
import types

import numpy as np

try:
    import gymnasium
    from gymnasium.wrappers.vector import RescaleAction as _GymRescaleAction
except ImportError:
    gymnasium = None
try:
    from stable_baselines3.common.base_class import BaseAlgorithm as _BaseAlgorithm
    from stable_baselines3.common.callbacks import EvalCallback as _EvalCallback
    from stable_baselines3.common.evaluation import evaluate_policy as _evaluate_policy
except ImportError:
    _BaseAlgorithm = None

HAVE_GYMNASIUM = gymnasium is not None
HAVE_SB3 = _BaseAlgorithm is not None


class StandInVectorWrapper(object):
    """gymnasium 1.2.3's gymnasium.vector.VectorWrapper, as far as a wrapped env sees it: reset()
    and step() forward to `env` (reset with seed= and options= only), the spaces, num_envs,
    metadata, render_mode, closed and `unwrapped` are properties of its own; there is no
    __getattr__ (gymnasium 1.0's releases removed the forwarding of other names, which its 1.0
    alphas still did for public names while refusing private ones), so any other attribute,
    e.g. `_node_seeds` or `node_num_envs`, raises AttributeError."""

    def __init__(self, env):
        self.env = env
        self._single_action_space = None
        self._action_space = None

    def reset(self, *, seed=None, options=None):
        return self.env.reset(seed=seed, options=options)

    def step(self, actions):
        return self.env.step(actions)

    def close(self, **kwargs):
        return self.env.close(**kwargs)

    @property
    def unwrapped(self):
        return self.env.unwrapped

    @property
    def num_envs(self):
        return self.env.num_envs

    @property
    def observation_space(self):
        return self.env.observation_space

    @property
    def single_observation_space(self):
        return self.env.single_observation_space

    @property
    def action_space(self):
        return self._action_space if self._action_space is not None else self.env.action_space

    @property
    def single_action_space(self):
        if self._single_action_space is not None:
            return self._single_action_space
        return self.env.single_action_space

    @property
    def metadata(self):
        return self.env.metadata

    @property
    def render_mode(self):
        return self.env.render_mode

    @property
    def closed(self):
        return self.env.closed

    def __repr__(self):
        return '<%s, %r>' % (type(self).__name__, self.env)


class StandInRescaleAction(StandInVectorWrapper):
    """gymnasium 1.2.3's gymnasium.wrappers.vector.RescaleAction(env, min_action, max_action):
    its action spaces are [min_action, max_action] per component, and it maps actions affinely
    onto env's single_action_space bounds (gymnasium.wrappers.RescaleAction's transform) before
    stepping env."""

    def __init__(self, env, min_action, max_action):
        super(StandInRescaleAction, self).__init__(env)
        from jetbot_rl.spaces import make_box
        inner = env.single_action_space
        shape = inner.shape
        self._min = np.broadcast_to(np.asarray(min_action, dtype=np.float32), shape)
        self._max = np.broadcast_to(np.asarray(max_action, dtype=np.float32), shape)
        self._low, self._high = inner.low, inner.high
        self._single_action_space = make_box(self._min, self._max, shape)
        self._action_space = make_box(np.tile(self._min, (env.num_envs, 1)),
                                      np.tile(self._max, (env.num_envs, 1)),
                                      (env.num_envs,) + shape)

    def step(self, actions):
        # gymnasium.wrappers.RescaleAction: low + (high - low) * ((a - min) / (max - min)),
        # clipped to [low, high]
        a = np.asarray(actions, dtype=np.float32)
        mapped = self._low + (self._high - self._low) * ((a - self._min) / (self._max - self._min))
        return self.env.step(np.clip(mapped, self._low, self._high))


def rescale_action(env, min_action, max_action):
    """gymnasium.wrappers.vector.RescaleAction(env, min_action, max_action) when gymnasium is
    installed, else StandInRescaleAction."""
    if HAVE_GYMNASIUM:
        return _GymRescaleAction(env, min_action, max_action)
    return StandInRescaleAction(env, min_action, max_action)


class InfoRecorder(StandInVectorWrapper):
    """A vector wrapper (public API only, as gymnasium's) that keeps the infos of the last step."""

    def __init__(self, env):
        super(InfoRecorder, self).__init__(env)
        self.last_infos = None

    def step(self, actions):
        result = self.env.step(actions)
        self.last_infos = result[4]
        return result


def set_random_seed(venv, seed):
    """What PPO("MlpPolicy", venv, seed=seed) does to venv: the real PPO's constructor when SB3 is
    installed; else SB3 2.4.1's BaseAlgorithm.set_random_seed, which seeds the action space and
    calls venv.seed(seed) (learn() then calls venv.reset())."""
    if HAVE_SB3:
        from stable_baselines3 import PPO
        PPO('MlpPolicy', venv, seed=seed, n_steps=8, batch_size=8, device='cpu')
        return
    venv.action_space.seed(seed)
    venv.seed(seed)


def update_info_buffer(infos, dones, ep_success_buffer=None):
    """SB3's BaseAlgorithm._update_info_buffer(infos, dones) over one step: appends the
    "is_success" of every info whose env is done to `ep_success_buffer` (a deque, returned), which
    rollout/success_rate averages (logged only when it is not empty). The real method when SB3 is
    installed; else a copy of 2.4.1's logic."""
    if ep_success_buffer is None:
        ep_success_buffer = collections.deque(maxlen=100)
    holder = types.SimpleNamespace(ep_info_buffer=collections.deque(maxlen=100),
                                   ep_success_buffer=ep_success_buffer)
    if HAVE_SB3:
        _BaseAlgorithm._update_info_buffer(holder, infos, dones)
        return ep_success_buffer
    if dones is None:
        dones = np.array([False] * len(infos))
    for idx, info in enumerate(infos):
        maybe_ep_info = info.get('episode')
        maybe_is_success = info.get('is_success')
        if maybe_ep_info is not None:
            holder.ep_info_buffer.extend([maybe_ep_info])
        if maybe_is_success is not None and dones[idx]:
            holder.ep_success_buffer.append(maybe_is_success)
    return ep_success_buffer


def evaluate_successes(venv, predict, n_eval_episodes):
    """The "is_success" values EvalCallback collects when it evaluates over n_eval_episodes
    (evaluate_policy with its _log_success_callback): the real functions when SB3 is installed;
    else a copy of 2.4.1's logic: the episodes are divided among the envs (env i runs
    (n + i) // num_envs of them), and after each step the callback reads info["is_success"] of
    every env still counting whose `done` is set. `predict(obs) -> actions`."""
    holder = types.SimpleNamespace(_is_success_buffer=[])

    def callback(locals_, globals_):
        info = locals_['info']
        if locals_['done']:
            maybe_is_success = info.get('is_success')
            if maybe_is_success is not None:
                holder._is_success_buffer.append(maybe_is_success)

    if HAVE_SB3:
        model = types.SimpleNamespace(
            predict=lambda obs, state=None, episode_start=None, deterministic=True:
            (predict(obs), None))
        _evaluate_policy(model, venv, n_eval_episodes=n_eval_episodes, warn=False,
                         callback=lambda l, g: _EvalCallback._log_success_callback(holder, l, g))
        return holder._is_success_buffer
    n_envs = venv.num_envs
    episode_counts = np.zeros(n_envs, dtype='int')
    targets = np.array([(n_eval_episodes + i) // n_envs for i in range(n_envs)], dtype='int')
    observations = venv.reset()
    while (episode_counts < targets).any():
        actions = predict(observations)
        observations, rewards, dones, infos = venv.step(actions)
        for i in range(n_envs):
            if episode_counts[i] < targets[i]:
                done, info = dones[i], infos[i]
                callback({'info': info, 'done': done}, {})
                if dones[i]:
                    episode_counts[i] += 1
    return holder._is_success_buffer
