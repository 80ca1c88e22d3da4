#!/usr/bin/python3
"""JetbotVecEnv and JetbotSB3VecEnv against a real jetbot_env node (3 envs, velocity task)."""
import unittest

import numpy as np
import rosgraph
import rospy
import rostest

NUM_ENVS = 3
NODE = '/jetbot_env'
LIMIT = 20.0  # rad/s: the URDF's wheel velocity limit
DRIVE = 10.0  # rad/s: forward at 10 rad/s x 0.03 m = 0.3 m/s


def forward(n=NUM_ENVS):
    return np.full((n, 2), DRIVE, dtype=np.float32)


class TargetsSeen(object):
    """The WheelTargets a client publishes to NODE/wheel_targets, on a subscription of our own
    (connected before it returns)."""

    def __init__(self):
        from jetbot_rl.msg import WheelTargets
        from jetbot_rl_test.env_client import UNREPORTED_RECHECK, wait_for
        from jetbot_rl_test.py_test_util import EventList
        self.messages = EventList()
        topic = NODE + '/wheel_targets'
        self.sub = rospy.Subscriber(topic, WheelTargets, self.messages.append, tcp_nodelay=True)
        # Connected to every client's publisher: the one that publishes next may be the newest
        # (a connection to an older client's alone once lost the first message under load).
        publishers = [p for t, p in rosgraph.Master(rospy.get_name()).getSystemState()[0]
                      if t == topic][0]
        wait_for(lambda: self.sub.get_num_connections() >= len(publishers),
                 what='wheel_targets to connect to %s' % publishers, recheck=UNREPORTED_RECHECK)

    def next(self, count):
        """The velocities of the message after the first `count`, as float32 (NUM_ENVS, 2)."""
        self.messages.wait_for(lambda: len(self.messages) > count, 'WheelTargets %d' % count)
        return np.asarray(self.messages[count].velocities, dtype=np.float32).reshape(-1, 2)


class TestVecEnv(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        from jetbot_rl import JetbotVecEnv
        cls.env = JetbotVecEnv(NODE, timeout=30.0)

    def test_imports(self):
        # the client and the generated messages share the package jetbot_rl
        import jetbot_rl
        from jetbot_rl import Box, EnvRejectedError, JetbotSB3VecEnv, JetbotVecEnv
        from jetbot_rl.msg import EnvSpec, EnvStep, WheelTargets
        from jetbot_rl.srv import Reset, SetCommand, Step
        self.assertIsInstance(self.env, JetbotVecEnv)
        self.assertIs(jetbot_rl.JetbotSB3VecEnv, JetbotSB3VecEnv)
        self.assertTrue(issubclass(EnvRejectedError, RuntimeError))
        self.assertEqual(Box([-1.0], [1.0]).shape, (1,))
        for cls in (EnvSpec, EnvStep, WheelTargets):
            self.assertTrue(cls._type.startswith('jetbot_rl/'))
        for srv in (Reset, SetCommand, Step):
            self.assertTrue(srv._type.startswith('jetbot_rl/'))
        with self.assertRaises(AttributeError):
            jetbot_rl.NoSuchName
        # the shared constants come from the messages, not typed again
        from jetbot_rl.srv import ResetRequest
        from jetbot_rl.vec_env import SHARED_SPEC_FIELDS
        self.assertEqual(jetbot_rl.NODE_SEED_STRIDE, ResetRequest.NODE_SEED_STRIDE)
        self.assertEqual(jetbot_rl.NODE_SEED_STRIDE, 2 ** 32)
        self.assertEqual(SHARED_SPEC_FIELDS,
                         tuple(f for f in EnvSpec.__slots__ if f != 'num_envs'))
        for field in ('task', 'action_low', 'observation_low', 'observation_high', 'scan_range'):
            self.assertIn(field, SHARED_SPEC_FIELDS)

    def test_attributes_from_spec(self):
        env = self.env
        self.assertEqual(env.num_envs, NUM_ENVS)
        self.assertEqual(env.nodes, [NODE])
        self.assertEqual(env.node_num_envs, [NUM_ENVS])
        self.assertEqual((env.obs_dim, env.action_dim), (3, 2))
        self.assertEqual(env.task, 'velocity')
        self.assertEqual(env.observation_names, ['lin_vel_b_x', 'lin_vel_b_y', 'lin_vel_b_z'])
        self.assertEqual(env.action_names, ['left_wheel_joint', 'right_wheel_joint'])
        np.testing.assert_array_equal(env.action_low, [-LIMIT, -LIMIT])
        np.testing.assert_array_equal(env.action_high, [LIMIT, LIMIT])
        self.assertEqual(env.action_low.dtype, np.float32)
        self.assertAlmostEqual(env.control_dt, 1.0 / 60.0, places=12)
        self.assertEqual(env.max_episode_length, 300)
        self.assertFalse(env.has_goals)  # every episode ends as a time-out
        self.assertIs(env.unwrapped, env)
        self.assertEqual((len(env.scan_beam_angles), len(env.scan_range)), (0, 0))  # no scan
        self.assertEqual(str(getattr(env.metadata['autoreset_mode'], 'value',
                                     env.metadata['autoreset_mode'])), 'SameStep')
        self.assertEqual(len(env.specs), 1)

    def test_spaces(self):
        from jetbot_rl.spaces import HAVE_GYMNASIUM, Box
        env = self.env
        if not HAVE_GYMNASIUM:  # gymnasium is not installed here: the stand-in
            for space in (env.single_observation_space, env.single_action_space,
                          env.observation_space, env.action_space):
                self.assertIsInstance(space, Box)
        self.assertEqual(env.single_observation_space.shape, (3,))
        self.assertEqual(env.observation_space.shape, (NUM_ENVS, 3))
        self.assertEqual(env.single_action_space.shape, (2,))
        self.assertEqual(env.action_space.shape, (NUM_ENVS, 2))
        for space in (env.single_observation_space, env.observation_space,
                      env.single_action_space, env.action_space):
            self.assertEqual(space.dtype, np.float32)
        # the observation bounds are what ~spec says (none: +-inf); the velocity task's are
        # unbounded either way
        from jetbot_rl_test.py_test_util import spec_bounds
        low, high = spec_bounds(env.specs[0])
        np.testing.assert_array_equal(env.observation_low, low)
        np.testing.assert_array_equal(env.observation_high, high)
        np.testing.assert_array_equal(env.single_observation_space.low, low)
        np.testing.assert_array_equal(env.single_observation_space.high, high)
        np.testing.assert_array_equal(env.observation_space.low, np.tile(low, (NUM_ENVS, 1)))
        np.testing.assert_array_equal(env.observation_space.high, np.tile(high, (NUM_ENVS, 1)))
        self.assertTrue(np.all(np.isinf(env.observation_space.low)))
        self.assertTrue(np.all(np.isinf(env.observation_space.high)))
        np.testing.assert_array_equal(env.action_space.low, np.full((NUM_ENVS, 2), -LIMIT))
        np.testing.assert_array_equal(env.action_space.high, np.full((NUM_ENVS, 2), LIMIT))
        env.action_space.seed(3)
        samples = [env.action_space.sample() for _ in range(50)]
        for s in samples:
            self.assertEqual((s.shape, s.dtype), ((NUM_ENVS, 2), np.float32))
            self.assertTrue(env.action_space.contains(s))
        self.assertGreater(np.std(samples), 5.0)  # spread over the box, not a constant
        env.action_space.seed(3)
        np.testing.assert_array_equal(env.action_space.sample(), samples[0])
        obs = env.single_observation_space.sample()
        self.assertEqual((obs.shape, obs.dtype), ((3,), np.float32))
        env.reset()
        env.step(samples[1])

    def test_normalized_actions(self):
        """normalize_actions=True: Box(-1, 1) action spaces; [-1, 1] reaches the node mapped
        linearly onto [action_low, action_high] (here +-20 rad/s), outside it clipped."""
        from jetbot_rl import JetbotSB3VecEnv, JetbotVecEnv
        env = JetbotVecEnv(NODE, timeout=30.0, normalize_actions=True)
        try:
            self.assertTrue(env.normalize_actions)
            self.assertFalse(self.env.normalize_actions)
            for space, shape in ((env.single_action_space, (2,)),
                                 (env.action_space, (NUM_ENVS, 2))):
                self.assertEqual((space.shape, space.dtype), (shape, np.float32))
                np.testing.assert_array_equal(space.low, np.full(shape, -1.0))
                np.testing.assert_array_equal(space.high, np.full(shape, 1.0))
            np.testing.assert_array_equal(env.action_low, [-LIMIT, -LIMIT])  # the node's units
            self.assertEqual(JetbotSB3VecEnv(env).action_space, env.single_action_space)
            seen = TargetsSeen()
            env.reset()
            actions = np.array([[-1.0, 1.0], [0.0, 0.5], [2.0, -3.0]], dtype=np.float32)
            obs, _, _, _, infos = env.step(actions)
            np.testing.assert_array_equal(seen.next(0), [[-LIMIT, LIMIT], [0.0, 0.5 * LIMIT],
                                                         [LIMIT, -LIMIT]])
            np.testing.assert_array_equal(infos['episode_steps'], [1] * NUM_ENVS)
            env.step(np.full((NUM_ENVS, 2), -0.25).tolist())  # a list of float64 is converted
            np.testing.assert_array_equal(seen.next(1), np.full((NUM_ENVS, 2), -0.25 * LIMIT))
            with self.assertRaisesRegex(ValueError, r'actions\[0, 1\] = nan'):
                env.step([[0.0, np.nan]] + [[0.0, 0.0]] * (NUM_ENVS - 1))
            seen.sub.unregister()
        finally:
            env.close()
        self.env.reset()  # the class's client goes on after a reset

    def test_reset_step_shapes_and_dtypes(self):
        env = self.env
        obs, infos = env.reset(seed=0)
        self.assertEqual((obs.shape, obs.dtype), ((NUM_ENVS, 3), np.float32))
        self.assertTrue(obs.flags.writeable)
        np.testing.assert_array_equal(infos['episode_steps'], [0] * NUM_ENVS)
        np.testing.assert_array_equal(infos['_episode_steps'], [True] * NUM_ENVS)
        obs, rewards, terminations, truncations, infos = env.step(forward().tolist())  # a list
        self.assertEqual((obs.shape, obs.dtype), ((NUM_ENVS, 3), np.float32))
        self.assertEqual((rewards.shape, rewards.dtype), ((NUM_ENVS,), np.float32))
        self.assertEqual((terminations.shape, terminations.dtype), ((NUM_ENVS,), np.bool_))
        self.assertEqual((truncations.shape, truncations.dtype), ((NUM_ENVS,), np.bool_))
        np.testing.assert_array_equal(infos['episode_steps'], [1] * NUM_ENVS)
        self.assertNotIn('final_obs', infos)
        self.assertNotIn('_final_obs', infos)
        # velocity task: reward = |observation| [m/s]
        np.testing.assert_allclose(rewards, np.linalg.norm(obs, axis=1), rtol=1e-5, atol=1e-7)
        # float64 actions are accepted and converted
        obs, rewards, _, _, infos = env.step(forward().astype(np.float64))
        np.testing.assert_array_equal(infos['episode_steps'], [2] * NUM_ENVS)

    def test_same_step_auto_reset_at_time_out(self):
        env = self.env
        env.reset(seed=0)
        # each env at its own speed: the final observations must land in the right rows
        actions = forward() * np.array([[-1.0], [1.0], [0.5]], dtype=np.float32)
        for t in range(1, 299):
            obs, rewards, terminations, truncations, infos = env.step(actions)
            self.assertNotIn('final_obs', infos, 'step %d' % t)
            self.assertFalse(truncations.any() or terminations.any(), 'step %d' % t)
            np.testing.assert_array_equal(infos['episode_steps'], [t] * NUM_ENVS)
        last_obs = obs
        obs, rewards, terminations, truncations, infos = env.step(actions)  # step 299: time-out
        np.testing.assert_array_equal(truncations, [True] * NUM_ENVS)
        np.testing.assert_array_equal(terminations, [False] * NUM_ENVS)
        np.testing.assert_array_equal(infos['_final_obs'], [True] * NUM_ENVS)
        # how they ended: a time-out, in a mask of its own (gymnasium's "_key" convention)
        np.testing.assert_array_equal(infos['outcome'], [0] * NUM_ENVS)
        np.testing.assert_array_equal(infos['_outcome'], [True] * NUM_ENVS)
        self.assertIsNot(infos['_outcome'], infos['_final_obs'])
        final = infos['final_obs']
        self.assertEqual((final.shape, final.dtype), ((NUM_ENVS, 3), np.float32))
        # the final observation: still driving (env 0 backwards, env 2 at half speed), and the
        # reward of the last step is its norm; the returned observation is the new episode's
        # (at rest)
        np.testing.assert_allclose(final[:, 0], [-0.3, 0.3, 0.15], atol=0.01)
        np.testing.assert_allclose(final, last_obs, atol=1e-3)
        np.testing.assert_allclose(rewards, np.linalg.norm(final, axis=1), rtol=1e-5)
        np.testing.assert_allclose(obs, np.zeros((NUM_ENVS, 3)), atol=1e-6)
        np.testing.assert_array_equal(infos['episode_steps'], [0] * NUM_ENVS)
        obs, rewards, terminations, truncations, infos = env.step(actions)
        self.assertNotIn('final_obs', infos)
        self.assertNotIn('_outcome', infos)
        self.assertFalse(truncations.any())
        np.testing.assert_array_equal(infos['episode_steps'], [1] * NUM_ENVS)

    def test_sb3_adapter(self):
        from jetbot_rl import JetbotSB3VecEnv
        from jetbot_rl.sb3 import HAVE_SB3
        from jetbot_rl_test.sb3_stand_ins import update_info_buffer
        venv = JetbotSB3VecEnv(self.env)
        if not HAVE_SB3:
            self.assertIs(type(venv).__mro__[1], object)
        self.assertEqual(venv.num_envs, NUM_ENVS)
        self.assertEqual(venv.observation_space.shape, (3,))  # per env, as SB3 expects
        self.assertEqual(venv.action_space.shape, (2,))
        self.assertEqual(venv.seed(4), [4] * NUM_ENVS)
        obs = venv.reset()
        self.assertEqual((obs.shape, obs.dtype), ((NUM_ENVS, 3), np.float32))
        self.assertEqual(venv.reset_infos, [{}] * NUM_ENVS)
        actions = forward() * np.array([[0.5], [1.0], [-1.0]], dtype=np.float32)
        for t in range(1, 299):
            obs, rewards, dones, infos = venv.step(actions)
            self.assertEqual(infos, [{'TimeLimit.truncated': False}] * NUM_ENVS, 'step %d' % t)
            self.assertFalse(dones.any())
        venv.step_async(actions)
        obs, rewards, dones, infos = venv.step_wait()  # the time-out
        self.assertEqual((dones.shape, dones.dtype), ((NUM_ENVS,), np.bool_))
        self.assertTrue(dones.all())
        self.assertEqual(len(infos), NUM_ENVS)
        # a task without goals: no is_success, so SB3 logs no rollout/success_rate
        self.assertEqual(len(update_info_buffer(infos, dones)), 0)
        for i, info in enumerate(infos):
            self.assertEqual(sorted(info), ['TimeLimit.truncated', 'terminal_observation'])
            self.assertIs(info['TimeLimit.truncated'], True)
            terminal = info['terminal_observation']
            self.assertEqual((terminal.shape, terminal.dtype), ((3,), np.float32))
            self.assertAlmostEqual(float(terminal[0]), [0.15, 0.3, -0.3][i], delta=0.01)
            self.assertAlmostEqual(float(rewards[i]), float(np.linalg.norm(terminal)), places=5)
        np.testing.assert_allclose(obs, np.zeros((NUM_ENVS, 3)), atol=1e-6)
        with self.assertRaises(RuntimeError):
            venv.step_wait()  # no step_async
        self.assertEqual(venv.get_attr('task'), ['velocity'] * NUM_ENVS)
        self.assertEqual(venv.get_attr('control_dt', indices=[0, 2]), [self.env.control_dt] * 2)
        self.assertEqual(venv.get_attr('render_mode', indices=1), [None])
        venv.set_attr('custom_value', 7)
        self.assertEqual(venv.get_attr('custom_value', indices=[2]), [7])
        self.assertEqual(venv.env_method('__repr__', indices=[1, 2]), [repr(self.env)] * 2)
        self.assertEqual(venv.env_is_wrapped(object), [False] * NUM_ENVS)
        with self.assertRaises(ValueError):
            venv.get_attr('task', indices=[NUM_ENVS])
        with self.assertRaises(NotImplementedError):
            venv.get_images()
        with self.assertRaisesRegex(TypeError, 'JetbotVecEnv or a gymnasium vector wrapper'):
            JetbotSB3VecEnv(np.zeros(3))

    def test_z_context_manager_and_close(self):  # last: a second client of the same node
        from jetbot_rl import JetbotVecEnv
        with JetbotVecEnv(NODE, timeout=30.0) as env:
            obs, _ = env.reset()
            env.step(forward())
        self.assertTrue(env.closed)
        env.close()  # idempotent
        with self.assertRaisesRegex(RuntimeError, 'closed'):
            env.step(forward())
        with self.assertRaisesRegex(RuntimeError, 'closed'):
            env.reset()
        # the first client goes on after a reset (the other one stepped the node meanwhile)
        self.env.reset()
        self.env.step(forward())


if __name__ == '__main__':
    rospy.init_node('test_python_vec_env', disable_signals=True)
    rostest.rosrun('jetbot_rl', 'test_python_vec_env', TestVecEnv)
