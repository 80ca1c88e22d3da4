"""JetbotSB3VecEnv: a JetbotVecEnv behind Stable-Baselines3's VecEnv interface.

    from jetbot_rl import JetbotVecEnv, JetbotSB3VecEnv
    venv = JetbotSB3VecEnv(JetbotVecEnv("/jetbot_env"))   # then e.g. VecMonitor(venv), PPO(...)

It subclasses stable_baselines3.common.vec_env.VecEnv when SB3 is importable and is a plain
class with the same methods otherwise. SB3's conventions: reset() -> obs; step() -> (obs,
rewards, dones, infos) with infos a list of one dict per env holding "TimeLimit.truncated" (every
env) and "terminal_observation" (envs that ended in this step; obs already holds the next
episode's first observation).
"""
import numpy as np

try:  # optional
    from stable_baselines3.common.vec_env import VecEnv as _Base
except ImportError:
    _Base = object

HAVE_SB3 = _Base is not object


class JetbotSB3VecEnv(_Base):
    """SB3 VecEnv over `vec_env` (a JetbotVecEnv). Spaces are the per-env ones, as SB3 expects.

    The envs of a batch share one JetbotVecEnv: get_attr/set_attr/env_method act on it once and
    report the result for each index; env_is_wrapped is False for every env.
    """

    def __init__(self, vec_env):
        self.venv = vec_env
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
                out[i]['terminal_observation'] = final_obs[i]
        return obs, rewards, dones, out

    def step(self, actions):
        self.step_async(actions)
        return self.step_wait()

    def seed(self, seed=None):
        """Seeds the next reset(); returns, per env, the seed its node's ~reset gets."""
        if seed is None:
            seed = int(np.random.randint(0, 2 ** 31 - 1))
        self.venv._node_seeds(seed)  # ValueError now rather than at reset()
        self._seed = seed
        return [seed + k * 2 ** 32 for k, n in enumerate(self.venv.node_num_envs)
                for _ in range(n)]

    def close(self):
        self.venv.close()

    def get_attr(self, attr_name, indices=None):
        return [getattr(self.venv, attr_name)] * len(self._indices(indices))

    def set_attr(self, attr_name, value, indices=None):
        self._indices(indices)
        setattr(self.venv, attr_name, value)

    def env_method(self, method_name, *method_args, indices=None, **method_kwargs):
        result = getattr(self.venv, method_name)(*method_args, **method_kwargs)
        return [result] * len(self._indices(indices))

    def env_is_wrapped(self, wrapper_class, indices=None):
        return [False] * len(self._indices(indices))

    def get_images(self):
        raise NotImplementedError('jetbot_env renders nothing: watch it in RViz')

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
