"""JetbotSB3VecEnv: a JetbotVecEnv behind Stable-Baselines3's VecEnv interface.

    from jetbot_rl import JetbotVecEnv, JetbotSB3VecEnv
    venv = JetbotSB3VecEnv(JetbotVecEnv("/jetbot_env"))   # then e.g. VecMonitor(venv), PPO(...)

It subclasses stable_baselines3.common.vec_env.VecEnv when SB3 is importable and is a plain
class with the same methods otherwise. SB3's conventions: reset() -> obs; step() -> (obs,
rewards, dones, infos) with infos a list of one dict per env holding "TimeLimit.truncated" (every
env), "terminal_observation" (envs that ended in this step; obs already holds the next episode's
first observation; an image or a dict as the observation is, see JetbotVecEnv's
`observation`) and, for a task with goals, "is_success" (envs that ended in this step), which
SB3's rollout/success_rate, EvalCallback and evaluate_policy's callbacks read.
"""
import numpy as np

from jetbot_rl.msg import EnvStep
from jetbot_rl.vec_env import JetbotVecEnv

try:  # optional
    from stable_baselines3.common.vec_env import VecEnv as _Base
except ImportError:
    _Base = object

HAVE_SB3 = _Base is not object


class JetbotSB3VecEnv(_Base):
    """SB3 VecEnv over `vec_env`: a JetbotVecEnv, or a gymnasium vector wrapper of one (e.g.
    gymnasium.wrappers.vector.RescaleAction); only its public API is used (reset(seed=...),
    step(), the spaces, `unwrapped`). Spaces are the per-env ones, as SB3 expects.

    The envs of a batch share one JetbotVecEnv: get_attr/set_attr/env_method act on `vec_env`
    once (get_attr and env_method fall back to the JetbotVecEnv under the wrappers for a name
    the outermost wrapper lacks) and report the result for each index; env_is_wrapped is False
    for every env.
    """

    def __init__(self, vec_env):
        jetbot = getattr(vec_env, 'unwrapped', None)
        if not isinstance(jetbot, JetbotVecEnv):
            raise TypeError('JetbotSB3VecEnv: vec_env must be a JetbotVecEnv or a gymnasium '
                            'vector wrapper of one, got %r' % (vec_env,))
        self.venv = vec_env
        self._jetbot = jetbot
        self._actions = None
        self._seed = None
        if HAVE_SB3:
            super(JetbotSB3VecEnv, self).__init__(vec_env.num_envs,
                                                  vec_env.single_observation_space,
                                                  vec_env.single_action_space)
        else:
            self.num_envs = vec_env.num_envs
            self.observation_space = vec_env.single_observation_space
            self.action_space = vec_env.single_action_space
            self.reset_infos = [{} for _ in range(self.num_envs)]
            self.render_mode = None

    def reset(self):
        """Resets every env (with the seed of seed(), once) and returns the observations."""
        obs, _ = self.venv.reset(seed=self._seed)
        self._seed = None
        self.reset_infos = [{} for _ in range(self.num_envs)]
        return obs

    def step_async(self, actions):
        self._actions = actions

    def step_wait(self):
        if self._actions is None:
            raise RuntimeError('JetbotSB3VecEnv.step_wait without step_async')
        actions, self._actions = self._actions, None
        obs, rewards, terminations, truncations, infos = self.venv.step(actions)
        dones = terminations | truncations
        time_limit = (truncations & ~terminations).tolist()
        out = [{'TimeLimit.truncated': t} for t in time_limit]
        if 'final_obs' in infos:
            final_obs = infos['final_obs']
            for i in np.flatnonzero(infos['_final_obs']):
                out[i]['terminal_observation'] = (
                    {k: v[i] for k, v in final_obs.items()} if isinstance(final_obs, dict)
                    else final_obs[i])
        if self._jetbot.has_goals and 'outcome' in infos:
            success = (infos['outcome'] == EnvStep.OUTCOME_SUCCESS).tolist()
            waited = (infos['outcome'] == EnvStep.OUTCOME_WAITED).tolist()
            for i in np.flatnonzero(infos['_outcome']):
                if not waited[i]:  # a round's wait (rounds) is no episode of the task
                    out[i]['is_success'] = success[i]
        return obs, rewards, dones, out

    def step(self, actions):
        self.step_async(actions)
        return self.step_wait()

    def seed(self, seed=None):
        """Seeds the next reset(); returns, per env, the seed its node's ~reset gets (node k of
        the JetbotVecEnv: seed + k * NODE_SEED_STRIDE)."""
        if seed is None:
            seed = int(np.random.randint(0, 2 ** 31 - 1))
        node_seeds = self._jetbot.node_seeds(seed)  # ValueError now rather than at reset()
        self._seed = seed
        return [s for s, n in zip(node_seeds, self._jetbot.node_num_envs) for _ in range(n)]

    def close(self):
        self.venv.close()

    def get_attr(self, attr_name, indices=None):
        return [self._lookup(attr_name)] * len(self._indices(indices))

    def set_attr(self, attr_name, value, indices=None):
        self._indices(indices)
        setattr(self.venv, attr_name, value)

    def env_method(self, method_name, *method_args, indices=None, **method_kwargs):
        result = self._lookup(method_name)(*method_args, **method_kwargs)
        return [result] * len(self._indices(indices))

    def env_is_wrapped(self, wrapper_class, indices=None):
        return [False] * len(self._indices(indices))

    def get_images(self):
        raise NotImplementedError('jetbot_env renders nothing: watch it in RViz')

    def _lookup(self, name):
        """`name` of the outermost wrapper, else of the JetbotVecEnv (gymnasium 1.x's vector
        wrappers forward only their declared attributes)."""
        try:
            return getattr(self.venv, name)
        except AttributeError:
            if self.venv is self._jetbot:
                raise
            return getattr(self._jetbot, name)

    def _indices(self, indices):
        if indices is None:
            return list(range(self.num_envs))
        if isinstance(indices, (int, np.integer)):
            indices = [indices]
        indices = list(indices)
        for i in indices:
            if not 0 <= i < self.num_envs:
                raise ValueError('env index %r is not in [0, %d)' % (i, self.num_envs))
        return indices
