#!/usr/bin/python3
"""The Python client on the navigation task (two nodes of 4 envs, jetbot_env.launch
task:=navigation): how each episode ended (infos["outcome"] with its own mask "_outcome") is what
the node published; JetbotSB3VecEnv gives it to Stable-Baselines3 as info["is_success"], which
SB3's rollout/success_rate and EvalCallback read; seeding through a gymnasium vector wrapper
(RescaleAction, as PPO(seed=0) does it) reaches every node with its own seed; time-outs truncate
at episode step 399 of max_episode_length 400. Where gymnasium and SB3 are not installed, their
behaviour is reproduced by jetbot_rl_test.sb3_stand_ins."""
import collections
import unittest

import numpy as np
import rospy
import rostest

from jetbot_rl import NODE_SEED_STRIDE, JetbotSB3VecEnv, JetbotVecEnv
from jetbot_rl.msg import EnvSpec, EnvStep, WheelTargets
from jetbot_rl.srv import Step
from jetbot_rl_test.py_test_util import EventList, spec_bounds
from jetbot_rl_test.sb3_stand_ins import (InfoRecorder, StandInRescaleAction, evaluate_successes,
                                          rescale_action, set_random_seed, update_info_buffer)

A, B = '/nav_a/jetbot_env', '/nav_b/jetbot_env'
NUM_ENVS = 4  # per node
TIMEOUT = 30.0
MAX_STEPS = 2000  # bound of the loop that waits for both a success and a collision


def uint8s(data):
    """A uint8[] field as numpy (bytes from a plain message, an array from a numpy_msg one)."""
    if isinstance(data, (bytes, bytearray)):
        return np.frombuffer(data, dtype=np.uint8)
    return np.asarray(data, dtype=np.uint8)


class Policy(object):
    """Twist actions (v [m/s], omega [rad/s]): envs in `seekers` steer to their goal (reached
    mostly), the others drive straight ahead at full speed (into a wall or an obstacle, mostly)."""

    def __init__(self, env, seekers):
        names = env.observation_names
        self.cos, self.sin = names.index('goal_cos'), names.index('goal_sin')
        self.high = env.action_high
        self.seekers = np.asarray(seekers)

    def __call__(self, obs):
        angle = np.arctan2(obs[:, self.sin], obs[:, self.cos])
        v = self.high[0] * np.maximum(obs[:, self.cos], 0.0) ** 4
        omega = np.clip(4.0 * angle, -self.high[1], self.high[1])
        seek = np.stack([v, omega], axis=1)
        straight = np.tile([self.high[0], 0.0], (len(obs), 1))
        return np.where(self.seekers[:, None], seek, straight).astype(np.float32)


class NodeSteps(object):
    """Every EnvStep node `node` publishes, by step id, received on a subscription of our own."""

    def __init__(self, node):
        self.node = node
        self.messages = EventList()
        self.sub = rospy.Subscriber(node + '/env_step', EnvStep, self.messages.append,
                                    queue_size=1000, tcp_nodelay=True)
        self.probe = rospy.ServiceProxy(node + '/step', Step)

    def current(self):
        """The node's current step id (a ~step call for no step is refused with the state)."""
        res = self.probe(actions=WheelTargets(step=2 ** 64 - 1))
        assert not res.success
        return res.state.step

    def outcomes(self, step, num_envs):
        """(ended mask, outcome per env) of EnvStep `step`, once it has arrived here."""
        self.messages.wait_for(lambda: any(m.step == step for m in self.messages),
                               'EnvStep %d of %s' % (step, self.node), TIMEOUT)
        msg = next(m for m in self.messages if m.step == step)
        ended = np.zeros(num_envs, dtype=bool)
        outcome = np.zeros(num_envs, dtype=np.uint8)
        ids = np.asarray(msg.reset_env_ids, dtype=np.int64)
        ended[ids] = True
        outcome[ids] = uint8s(msg.outcomes)
        return ended, outcome

    def close(self):
        self.sub.unregister()


# The node's spec, read before the tests are defined: whether it sends observation bounds decides
# whether test_navigation_observation_bounds runs.
rospy.init_node('test_python_navigation', disable_signals=True)
NAV_SPEC = rospy.wait_for_message(A + '/spec', EnvSpec, timeout=60.0)
NO_BOUNDS = len(NAV_SPEC.observation_low) == 0


class TestNavigation(unittest.TestCase):
    def test_outcomes_and_is_success_are_the_nodes(self):
        """Goal seekers and straight drivers until both a success and a collision ended: at every
        step, infos["outcome"] and "_outcome" are the node's EnvStep.outcomes for exactly the envs
        that ended, and SB3's info["is_success"] is outcome == OUTCOME_SUCCESS for exactly
        those; SB3's success buffer and EvalCallback's read them."""
        steps = NodeSteps(A)
        with JetbotVecEnv(A, timeout=TIMEOUT) as env:
            self.assertTrue(env.has_goals)
            recorder = InfoRecorder(env)
            venv = JetbotSB3VecEnv(recorder)
            policy = Policy(env, seekers=[True, True, False, False])
            venv.seed(3)
            obs = venv.reset()
            step = steps.current()
            seen = np.zeros(3, dtype=np.int64)  # ended episodes: time-out, success, collision
            success_buffer = collections.deque(maxlen=100)  # SB3's ep_success_buffer
            expected_successes = []
            for t in range(MAX_STEPS):
                obs, rewards, dones, infos = venv.step(policy(obs))
                step += 1
                ended, outcome = steps.outcomes(step, NUM_ENVS)
                gym_infos = recorder.last_infos
                np.testing.assert_array_equal(dones, ended, 'step %d' % t)
                if ended.any():
                    np.testing.assert_array_equal(gym_infos['_outcome'], ended)
                    np.testing.assert_array_equal(gym_infos['outcome'], outcome)
                    self.assertIsNot(gym_infos['_outcome'], gym_infos['_final_obs'])
                    np.testing.assert_array_equal(gym_infos['_final_obs'], ended)
                else:
                    self.assertNotIn('outcome', gym_infos)
                    self.assertNotIn('_outcome', gym_infos)
                for i, info in enumerate(infos):
                    if ended[i]:
                        self.assertIs(info['is_success'], bool(outcome[i] == EnvStep.OUTCOME_SUCCESS),
                                      'step %d env %d outcome %d' % (t, i, outcome[i]))
                        expected_successes.append(info['is_success'])
                    else:
                        self.assertNotIn('is_success', info, 'step %d env %d' % (t, i))
                seen += np.bincount(outcome[ended], minlength=3)
                update_info_buffer(infos, dones, success_buffer)
                if seen[EnvStep.OUTCOME_SUCCESS] and seen[EnvStep.OUTCOME_COLLISION]:
                    break
            steps.close()
            print('ended episodes in %d steps: %d time-outs, %d successes, %d collisions'
                  % (t + 1, seen[0], seen[1], seen[2]))
            self.assertGreater(seen[EnvStep.OUTCOME_SUCCESS], 0, 'no episode reached its goal')
            self.assertGreater(seen[EnvStep.OUTCOME_COLLISION], 0, 'no episode collided')
            # SB3's rollout/success_rate: the mean of the done envs' is_success
            self.assertEqual(len(expected_successes), seen.sum())
            self.assertEqual(sum(expected_successes), seen[EnvStep.OUTCOME_SUCCESS])
            self.assertEqual(list(success_buffer), expected_successes[-100:])
            print('SB3 rollout/success_rate would log %.3f' % np.mean(success_buffer))
            # EvalCallback: evaluate_policy's callback collects one is_success per episode
            successes = evaluate_successes(venv, policy, n_eval_episodes=8)
            self.assertEqual(len(successes), 8)
            self.assertTrue(all(isinstance(s, bool) for s in successes))

    def test_time_out_at_step_399(self):
        """Robots that stand still: no goal, no collision; every episode is truncated at episode
        step 399 (max_episode_length 400 - 1, Isaac Lab's time-out), outcome time-out, and SB3
        sees TimeLimit.truncated and is_success False."""
        with JetbotVecEnv(A, timeout=TIMEOUT) as env:
            self.assertEqual(env.max_episode_length, 400)
            self.assertAlmostEqual(env.control_dt, 0.05)
            venv = JetbotSB3VecEnv(env)
            venv.reset()
            still = np.zeros((NUM_ENVS, 2), dtype=np.float32)
            for t in range(1, 399):
                obs, rewards, dones, infos = venv.step(still)
                self.assertFalse(dones.any(), 'episode step %d' % t)
            obs, _, terminations, truncations, infos = env.step(still)  # episode step 399
            np.testing.assert_array_equal(truncations, [True] * NUM_ENVS)
            np.testing.assert_array_equal(terminations, [False] * NUM_ENVS)
            np.testing.assert_array_equal(infos['_outcome'], [True] * NUM_ENVS)
            np.testing.assert_array_equal(infos['outcome'], [EnvStep.OUTCOME_TIME_OUT] * NUM_ENVS)
            np.testing.assert_array_equal(infos['episode_steps'], [0] * NUM_ENVS)
            for t in range(1, 399):
                venv.step(still)
            obs, rewards, dones, infos = venv.step(still)
            self.assertTrue(dones.all())
            for info in infos:
                self.assertIs(info['TimeLimit.truncated'], True)
                self.assertIs(info['is_success'], False)
            self.assertEqual(list(update_info_buffer(infos, dones)), [False] * NUM_ENVS)

    def test_seeding_through_a_vector_wrapper(self):
        """JetbotSB3VecEnv(RescaleAction(JetbotVecEnv([A, B]))): seed() and PPO(seed=...) reach
        node k with seed + k * NODE_SEED_STRIDE through the wrapper's public API (it forwards no
        private attribute): the first observations are those of each node reset alone with its
        seed."""
        wrapped = rescale_action(JetbotVecEnv([A, B], timeout=TIMEOUT), -1.0, 1.0)
        self.assertFalse(hasattr(wrapped, '_node_seeds'))
        venv = JetbotSB3VecEnv(wrapped)
        self.assertEqual(venv.seed(7), [7] * NUM_ENVS + [7 + NODE_SEED_STRIDE] * NUM_ENVS)
        with self.assertRaisesRegex(ValueError, 'seed'):
            venv.seed(-1)
        seeded_7 = venv.reset()
        set_random_seed(venv, 0)  # PPO(seed=0)
        seeded_0 = venv.reset()
        unseeded = venv.reset()  # the seed is used once
        obs, _, _, _ = venv.step(np.zeros((2 * NUM_ENVS, 2), dtype=np.float32))
        self.assertEqual(obs.shape, (2 * NUM_ENVS, wrapped.single_observation_space.shape[0]))
        self.assertEqual(venv.get_attr('task', indices=[0]), ['navigation'])  # past the wrapper
        venv.close()
        alone = {}
        for node, k in ((A, 0), (B, 1)):
            with JetbotVecEnv(node, timeout=TIMEOUT) as env:
                for seed in (0, 7):
                    alone[node, seed] = env.reset(seed=seed + k * NODE_SEED_STRIDE)[0]
        for seed, obs in ((7, seeded_7), (0, seeded_0)):
            np.testing.assert_array_equal(obs, np.concatenate([alone[A, seed], alone[B, seed]]),
                                          'seed %d' % seed)
        self.assertFalse(np.array_equal(seeded_0, seeded_7))
        self.assertFalse(np.array_equal(unseeded, seeded_0))
        # node B was not reseeded with the plain seed
        self.assertFalse(np.array_equal(seeded_7[NUM_ENVS:], alone[A, 7]))

    def test_normalized_twist_actions(self):
        """normalize_actions=True on the twist action space (v in [0, 0.6] m/s forwards only,
        omega in +-10.67 rad/s): -1 is the lower bound, 1 the upper, 0 the middle, as the node
        receives them; through JetbotSB3VecEnv too."""
        from jetbot_rl_test.env_client import UNREPORTED_RECHECK, wait_for
        with JetbotVecEnv(A, timeout=TIMEOUT, normalize_actions=True) as env:
            seen = EventList()  # what env publishes
            sub = rospy.Subscriber(A + '/wheel_targets', WheelTargets, seen.append,
                                   tcp_nodelay=True)
            wait_for(lambda: sub.get_num_connections() > 0, what='wheel_targets to connect',
                     recheck=UNREPORTED_RECHECK)
            self.assertEqual(env.action_names, ['linear_x', 'angular_z'])
            low, high = env.action_low, env.action_high
            self.assertEqual(low[0], 0.0)
            np.testing.assert_allclose(high, [0.6, 10.67], atol=0.01)
            np.testing.assert_array_equal(env.single_action_space.low, [-1.0, -1.0])
            np.testing.assert_array_equal(env.single_action_space.high, [1.0, 1.0])
            venv = JetbotSB3VecEnv(env)
            venv.reset()
            venv.step(np.array([[-1.0, 0.0], [1.0, 1.0], [0.0, -1.0], [-5.0, 5.0]]))
            seen.wait_for(lambda: len(seen) > 0, 'WheelTargets')
            sent = np.asarray(seen[0].velocities, dtype=np.float32).reshape(NUM_ENVS, 2)
            np.testing.assert_array_equal(sent, [[low[0], 0.0], [high[0], high[1]],
                                                 [np.float32(0.5) * high[0], low[1]],
                                                 [low[0], high[1]]])
            sub.unregister()

    def test_spaces_are_the_spec(self):
        """The observation spaces hold ~spec's observation bounds element-wise, infinities
        included (none sent: +-inf); the twist action's lower bound forwards only is 0, not the
        negated zero -0. it printed as."""
        with JetbotVecEnv([A, B], timeout=TIMEOUT) as env:
            low, high = spec_bounds(env.specs[0])
            self.assertEqual(low.shape, (env.obs_dim,))
            for space, rows in ((env.single_observation_space, None),
                                (env.observation_space, 2 * NUM_ENVS)):
                self.assertEqual(space.dtype, np.float32)
                np.testing.assert_array_equal(space.low, low if rows is None else np.tile(low, (rows, 1)))
                np.testing.assert_array_equal(space.high,
                                              high if rows is None else np.tile(high, (rows, 1)))
            np.testing.assert_array_equal(env.observation_low, low)
            np.testing.assert_array_equal(env.observation_high, high)
            obs, _ = env.reset(seed=1)
            self.assertTrue(env.observation_space.contains(obs))
            self.assertEqual(env.action_low[0], 0.0)
            self.assertFalse(np.signbit(env.action_low[0]), 'action_low is %r' % env.action_low)
            self.assertFalse(np.signbit(env.single_action_space.low[0]))
            self.assertFalse(np.signbit(env.action_space.low[:, 0]).any())
            self.assertNotIn('-0.', str(env.action_low))

    @unittest.skipIf(NO_BOUNDS, 'the node sends no observation bounds (EnvSpec.observation_low '
                     'empty): runs once the C++ side fills them')
    def test_navigation_observation_bounds(self):
        """Once the node fills them, config/navigation_env.yaml's bounds (24 beams on a log
        scale, no observation noise, a path): beams in [0, 1], goal_distance and path_remaining
        in [0, inf), goal_cos, goal_sin, path_cos and path_sin in [-1, 1], the speeds and last
        actions unbounded."""
        with JetbotVecEnv(A, timeout=TIMEOUT) as env:
            names = env.observation_names
            expected = {}
            for k in range(24):
                expected['beam_log_%d' % k] = (0.0, 1.0)
            expected.update(goal_distance=(0.0, np.inf), goal_cos=(-1.0, 1.0),
                            goal_sin=(-1.0, 1.0), path_remaining=(0.0, np.inf),
                            path_cos=(-1.0, 1.0), path_sin=(-1.0, 1.0),
                            lin_vel_b_x=(-np.inf, np.inf),
                            ang_vel_z=(-np.inf, np.inf), last_action_0=(-np.inf, np.inf),
                            last_action_1=(-np.inf, np.inf))
            self.assertEqual(sorted(names), sorted(expected))
            low = np.array([expected[n][0] for n in names])
            high = np.array([expected[n][1] for n in names])
            np.testing.assert_allclose(env.single_observation_space.low, low, rtol=1e-6)
            np.testing.assert_allclose(env.single_observation_space.high, high, rtol=1e-6)

    def test_stand_in_wrapper_mirrors_gymnasium(self):
        """The stand-in (used without gymnasium) refuses what gymnasium 1.2.3's wrappers refuse:
        JetbotSB3VecEnv used to read `_node_seeds` of the env it was given."""
        with JetbotVecEnv(A, timeout=TIMEOUT) as env:
            wrapped = StandInRescaleAction(env, -1.0, 1.0)
            for name in ('_node_seeds', 'node_num_envs', 'task'):
                with self.assertRaises(AttributeError):
                    getattr(wrapped, name)
            self.assertIs(wrapped.unwrapped, env)
            np.testing.assert_array_equal(wrapped.single_action_space.low, [-1.0, -1.0])
            with self.assertRaisesRegex(TypeError, 'JetbotVecEnv or a gymnasium vector wrapper'):
                JetbotSB3VecEnv(object())


if __name__ == '__main__':
    rostest.rosrun('jetbot_rl', 'test_python_navigation', TestNavigation)
