#!/usr/bin/python3
"""JetbotVecEnv with a camera (python_camera.test): the rgb image as a uint8 Box (H, W, 3)
observation and a Dict of the vector and every image, the same for the same seed, the ended
episodes' last images in infos["final_obs"] and SB3's terminal_observation, the image of env 0
equal to what the robot view publishes for the same step, and clear refusals."""
import threading
import unittest

import numpy as np
import rospy
import rostest
from sensor_msgs.msg import Image

from jetbot_rl import JetbotSB3VecEnv, JetbotVecEnv
from jetbot_rl_test.env_client import notify, wait_for

NODE, BLIND = '/jetbot_env', '/blind_env'
N, H, W = 3, 24, 32
EPISODE = 30  # control steps: episode_length_s 0.5 at 1/60 s
DRIVE = np.full((N, 2), 8.0, dtype=np.float32)


def turning(step):
    """Actions that turn the robots, different per env and step."""
    return np.array([[8.0, 8.0 - 4.0 * ((step + e) % 3)] for e in range(N)], dtype=np.float32)


class TestPythonCamera(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('test_python_camera')
        cls.lock = threading.Lock()
        cls.robot_view = []
        rospy.Subscriber('/env_0/camera/image_raw', Image, cls.on_image, queue_size=10)

    @classmethod
    def on_image(cls, msg):
        with cls.lock:
            cls.robot_view.append(msg)
        notify()

    def test_image_observation_and_the_robot_views_image(self):
        with JetbotVecEnv(NODE, timeout=30.0, observation='image') as env:
            self.assertEqual(env.image_kinds, ['rgb', 'depth', 'label'])
            self.assertEqual((env.image_width, env.image_height), (W, H))
            space = env.single_observation_space
            self.assertEqual((space.shape, space.dtype), ((H, W, 3), np.uint8))
            self.assertTrue(np.all(space.low == 0) and np.all(space.high == 255))
            self.assertEqual(env.observation_space.shape, (N, H, W, 3))
            obs, infos = env.reset(seed=4)
            self.assertEqual((obs.shape, obs.dtype), ((N, H, W, 3), np.uint8))
            self.assertTrue(all(space.contains(o) for o in obs))
            self.assertTrue(np.all(infos['image_fresh']))  # made at the reset
            # Random starts: every env sees its own scene.
            self.assertFalse(np.array_equal(obs[0], obs[1]))
            fresh = []
            for step in range(4):
                obs, _, _, _, infos = env.step(turning(step))
                fresh.append(bool(infos['image_fresh'][0]))
                if fresh[-1]:
                    # The robot view publishes env 0's image of this step: the same bytes.
                    expected = obs[0].tobytes()
                    wait_for(lambda: self.last_robot_view() == expected, what='the robot view '
                             'publishing the image of step %d' % (step + 1))
            self.assertEqual(fresh, [False, True, False, True])  # the block's 30 Hz: every 2nd

    def last_robot_view(self):
        with self.lock:
            if not self.robot_view:
                return None
            msg = self.robot_view[-1]
        self.assertEqual((msg.encoding, msg.width, msg.height), ('rgb8', W, H))
        return bytes(msg.data)

    def test_final_images_and_sb3s_terminal_observation(self):
        with JetbotVecEnv(NODE, timeout=30.0, observation='image') as env:
            env.reset(seed=1)
            venv = JetbotSB3VecEnv(env)
            self.assertEqual(venv.observation_space.shape, (H, W, 3))
            # Env 0 starts anew 10 steps in: envs 1 and 2 end alone at step EPISODE - 1.
            ended_at = None
            for step in range(EPISODE + 5):
                if step == 10:
                    env.reset(options={'reset_mask': np.array([True, False, False])})
                obs, rewards, terminations, truncations, infos = env.step(DRIVE)
                if '_final_obs' in infos and ended_at is None:
                    ended_at = step
                    mask, final = infos['_final_obs'], infos['final_obs']
                    self.assertEqual(mask.tolist(), [False, True, True])
                    self.assertEqual((final.shape, final.dtype), ((N, H, W, 3), np.uint8))
                    self.assertFalse(np.any(final[0]))  # not ended: nothing
                    for e in (1, 2):
                        self.assertGreater(int(final[e].max()), 0)
                        self.assertFalse(np.array_equal(final[e], obs[e]))
                    break
            self.assertEqual(ended_at, EPISODE - 2)  # episode step 29 at the 29th step after reset
            # SB3's adapter hands the same images on as terminal_observation.
            venv.reset()
            for step in range(EPISODE):
                obs, rewards, dones, info = venv.step(DRIVE)
                if dones.any():
                    break
            self.assertTrue(dones.all())
            for i in range(N):
                terminal = info[i]['terminal_observation']
                self.assertEqual((terminal.shape, terminal.dtype), ((H, W, 3), np.uint8))
                self.assertGreater(int(terminal.max()), 0)

    def test_dict_observation_and_the_same_images_for_the_same_seed(self):
        actions = [turning(s) for s in range(6)]
        with JetbotVecEnv(NODE, timeout=30.0, observation='dict') as env:
            space = env.single_observation_space
            self.assertEqual(list(space.spaces), ['vector', 'rgb', 'depth', 'label'])
            self.assertEqual(space['vector'].shape, (env.obs_dim,))
            self.assertEqual((space['depth'].shape, space['depth'].dtype), ((H, W, 1), np.float32))
            self.assertEqual((space['label'].shape, space['label'].dtype), ((H, W, 1), np.uint8))
            obs, _ = env.reset(seed=9)
            for a in actions:
                obs, _, _, _, _ = env.step(a)
            self.assertEqual(obs['vector'].shape, (N, env.obs_dim))
            depth = obs['depth']
            # REP 118: metres where a surface lies within the clip, +-inf beyond it, no NaN.
            self.assertFalse(np.any(np.isnan(depth)))
            finite = depth[np.isfinite(depth)]
            self.assertGreater(finite.size, 0)
            self.assertTrue(np.all((finite > 0.02) & (finite < 20.0)))
            self.assertGreater(len(np.unique(obs['label'])), 1)  # ground and more
            dict_rgb = obs['rgb'].copy()
        with JetbotVecEnv(NODE, timeout=30.0, observation='image') as env:
            obs, _ = env.reset(seed=9)
            for a in actions:
                obs, _, _, _, _ = env.step(a)
            np.testing.assert_array_equal(obs, dict_rgb)

    def test_refusals_name_what_is_missing(self):
        with self.assertRaisesRegex(ValueError, "observation must be one of vector, image, dict"):
            JetbotVecEnv(NODE, timeout=30.0, observation='pixels')
        with self.assertRaisesRegex(ValueError, r"observation='image' needs the camera's rgb "
                                    r"images, but /blind_env sends image_kinds \[\]"):
            JetbotVecEnv(BLIND, timeout=30.0, observation='image')
        with self.assertRaisesRegex(ValueError, 'spec field image_kinds'):
            JetbotVecEnv([NODE, BLIND], timeout=30.0)
        # Without images asked for, the blind node serves the vector as before.
        with JetbotVecEnv(BLIND, timeout=30.0) as env:
            obs, _ = env.reset(seed=0)
            self.assertEqual(obs.shape, (N, env.obs_dim))


if __name__ == '__main__':
    rostest.rosrun('jetbot_rl', 'python_camera', TestPythonCamera)
