#!/usr/bin/python3
"""Closed loop with an image policy, as on a Jetbot: the shipped road follower
(policies/road_following, trained on 32 x 32 renderings) drives the env node's camera Jetbot
through jetbot_deploy_node, which takes the robot's 128 x 128 camera images over ROS
(sensor_msgs/Image), resizes them as trained and publishes cmd_vel. Laps complete one after
another (the env node's episodes: a lap is OUTCOME_SUCCESS), none off the tape, at >= 90 % of the
lap rate the same policy drives in simulation on the same track (jetbot_rl_evaluate, in-process);
without images the deploy node stops the robot and its diagnostics name the image topic; an
image_transport it cannot load ends its start-up naming the parameter."""
import os
import signal
import subprocess
import tempfile
import unittest

import rospkg
import rospy
import rostest
import yaml
from diagnostic_msgs.msg import DiagnosticArray, DiagnosticStatus

from jetbot_rl.msg import EnvSpec, EnvStep
from jetbot_rl_test.env_client import TIMEOUT, EventList, wait_for

LAPS = 1            # whole laps timed, after the first (its start waits for the node)
RATE_SHARE = 0.9    # of the simulated lap rate
IMAGE_TOPIC = '/env_0/camera/image_raw'


class TestClosedLoopRoad(unittest.TestCase):
    def setUp(self):
        self.pkg = rospkg.RosPack().get_path('jetbot_rl')
        self.policy = os.path.join(self.pkg, 'policies', 'road_following')
        self.ends = EventList()      # (stamp, outcome) of env 0's episodes
        self.statuses = EventList()  # the deploy node's diagnostics
        rospy.Subscriber('/jetbot_env/env_step', EnvStep, self.on_step, queue_size=100)
        rospy.Subscriber('/diagnostics', DiagnosticArray, self.on_diagnostics)

    def on_step(self, msg):
        for env, outcome in zip(msg.reset_env_ids, bytearray(msg.outcomes)):
            if env == 0:
                self.ends.append((msg.header.stamp.to_sec(), outcome))

    def on_diagnostics(self, msg):
        self.statuses.extend(s for s in msg.status if s.name == '/deploy: deploy')

    def deploy(self, image_topic):
        return subprocess.Popen([
            'rosrun', 'jetbot_rl', 'jetbot_deploy_node', '__name:=deploy',
            '_checkpoint:=' + self.policy, '_odom_topic:=/env_0/odom',
            '_cmd_vel_topic:=/env_0/cmd_vel', '_image_topic:=' + image_topic])

    def stop(self, proc):
        proc.send_signal(signal.SIGINT)
        self.assertEqual(proc.wait(timeout=TIMEOUT), 0)

    def simulated_lap_rate(self):
        """Laps per second of simulation time of the policy on the env node's track, in-process
        (its own 32 x 32 renderings, no transport)."""
        with tempfile.NamedTemporaryFile('w', suffix='.yaml', delete=False) as track:
            yaml.safe_dump({'road': rospy.get_param('/jetbot_env/road')}, track)
        try:
            done = subprocess.run(
                ['rosrun', 'jetbot_rl', 'jetbot_rl_evaluate', '--checkpoint', self.policy,
                 '--task', 'road_following',
                 '--urdf', os.path.join(self.pkg, 'urdf', 'jetbot_camera.urdf'),
                 '--config', os.path.join(self.pkg, 'config', 'jetbot_env.yaml'),
                 '--config', os.path.join(self.pkg, 'config', 'road_following_env.yaml'),
                 '--config', track.name, '--num-envs', '2', '--episodes', '6', '--steps', '1100',
                 '--seed', '777',
                 '--threads', '1'],
                capture_output=True, text=True, timeout=10 * TIMEOUT,
                # at nice 10: in the suite's driving lane, beside the foreground's rate checks
                preexec_fn=lambda: os.nice(10))
        finally:
            os.unlink(track.name)
        self.assertEqual(done.returncode, 0, done.stderr)
        figures = dict(line.split('=', 1) for line in done.stdout.split() if '=' in line)
        dt = rospy.wait_for_message('/jetbot_env/spec', EnvSpec, timeout=TIMEOUT).control_dt
        rate = float(figures['success_rate']) / (float(figures['mean_episode_steps']) * dt)
        print('FIGURE: road following in simulation on the test track: %s episodes, %.3f laps, '
              '%.3f off the tape, %.3f laps/s' % (figures['episodes'], float(figures['success_rate']),
                                                  float(figures['off_track_rate']), rate))
        return rate

    def test_0_a_transport_it_cannot_load_ends_start_up_naming_it(self):
        done = subprocess.run(
            ['rosrun', 'jetbot_rl', 'jetbot_deploy_node', '__name:=deploy_bad_transport',
             '_checkpoint:=' + self.policy, '_image_transport:=no_such_transport'],
            capture_output=True, text=True, timeout=TIMEOUT)
        self.assertEqual(done.returncode, 1, done.stderr)
        self.assertIn("image_transport: 'no_such_transport' cannot be loaded", done.stderr)

    def test_1_without_images_the_robot_stands_and_the_diagnostics_say_why(self):
        proc = self.deploy('/no_camera/image_raw')
        try:
            wait_for(lambda: any('no fresh image on /no_camera/image_raw' in s.message
                                 for s in self.statuses), what='a status naming the image')
            status = next(s for s in self.statuses if 'image' in s.message)
        finally:
            self.stop(proc)
        self.assertEqual(status.level, DiagnosticStatus.WARN)
        ages = {kv.key: kv.value for kv in status.values}
        self.assertEqual(float(ages['image age [s]']), float('inf'))

    def test_2_laps_at_the_simulated_rate_from_images_over_ros(self):
        sim_rate = self.simulated_lap_rate()
        ended = len(self.ends)
        proc = self.deploy(IMAGE_TOPIC)
        try:
            wait_for(lambda: sum(o == EnvStep.OUTCOME_SUCCESS for _, o in self.ends[ended:])
                     >= LAPS + 1 or any(o != EnvStep.OUTCOME_SUCCESS
                                        for _, o in self.ends[ended:]),
                     timeout=6 * TIMEOUT, what='%d laps' % (LAPS + 1))
        finally:
            self.stop(proc)
        ends = self.ends[ended:]
        print('closed loop, road following: episode ends (stamp, outcome): %r' % ends)
        self.assertTrue(all(o == EnvStep.OUTCOME_SUCCESS for _, o in ends[:LAPS + 1]),
                        'an episode ended other than by a lap: %r' % ends)
        rate = LAPS / (ends[LAPS][0] - ends[0][0])
        print('FIGURE: road following closed loop (128 x 128 images over ROS, resized to 32 x 32 '
              'by jetbot_deploy_node): %.3f laps/s = %.1f %% of the simulated %.3f laps/s'
              % (rate, 100.0 * rate / sim_rate, sim_rate))
        self.assertGreaterEqual(rate, RATE_SHARE * sim_rate)


if __name__ == '__main__':
    rospy.init_node('test_closed_loop_road')
    rostest.rosrun('jetbot_rl', 'test_closed_loop_road', TestClosedLoopRoad)
