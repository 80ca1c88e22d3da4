#!/usr/bin/python3
"""What a new user meets in RViz (issue 50): for every launch file that opens RViz (an rviz node
with `-d .../config/NAME.rviz`), the config's "2D Nav Goal" tools publish where a node of that
launch file listens (a deploy node's goal_topic, from `roslaunch --dump-params`), so that
world_view.launch, view.launch and play.launch offer none; and every MarkerArray display of an
env node's ~markers leaves out the half-transparent body boxes (namespace body), which painted
the robot models' own colours over; view.launch with the camera Jetbot shows env_0's camera where
its Gazebo block publishes it, stereo_view.launch the stereo Jetbot's two."""
import glob
import os
import re
import subprocess
import unittest
import xml.etree.ElementTree as ET

import rospkg
import rostest
import yaml

PKG = rospkg.RosPack().get_path('jetbot_rl')
CONFIG = re.compile(r'-d \$\(find jetbot_rl\)/(config/[\w.]+\.rviz)')


def rviz_launches():
    """{launch file name: (config path, the arguments it requires)} for each file opening RViz."""
    found = {}
    for path in sorted(glob.glob(os.path.join(PKG, 'launch', '*.launch'))):
        root = ET.parse(path).getroot()
        for node in root.iter('node'):
            match = CONFIG.search(node.get('args', ''))
            if node.get('pkg') == 'rviz' and match:
                required = [a.get('name') for a in root.findall('arg')
                            if a.get('default') is None and a.get('value') is None]
                found[os.path.basename(path)] = (os.path.join(PKG, match.group(1)), required)
    return found


def dump(launch_file, *args):
    out = subprocess.run(['roslaunch', '--dump-params', 'jetbot_rl', launch_file] + list(args),
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, universal_newlines=True,
                         timeout=60)
    assert out.returncode == 0, 'roslaunch --dump-params %s failed:\n%s' % (launch_file, out.stderr)
    return yaml.safe_load(out.stdout)


class TestRvizConfigs(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.launches = rviz_launches()

    def test_the_robot_views_are_found(self):
        self.assertEqual(sorted(self.launches), ['navigate_sim.launch', 'play.launch',
                                                 'stereo_view.launch', 'view.launch',
                                                 'world_view.launch'])

    def test_goal_tools_publish_where_a_node_listens(self):
        offered = {}
        for name, (config, required) in self.launches.items():
            tools = yaml.safe_load(open(config))['Visualization Manager']['Tools']
            goals = [t['Topic'] for t in tools if t['Class'] == 'rviz/SetGoal']
            offered[name] = goals
            if not goals:
                continue
            params = dump(name, 'rviz:=true', *['%s:=/tmp/none' % a for a in required])
            listened = {v for k, v in params.items() if k.endswith('/goal_topic')}
            for topic in goals:
                self.assertIn(topic, listened, '%s (%s): "2D Nav Goal" publishes on %s, where no '
                              'node of it listens' % (name, os.path.basename(config), topic))
        print('FIGURE: rviz configs: 2D Nav Goal tools: %s' % offered)
        self.assertEqual(offered['navigate_sim.launch'], ['/move_base_simple/goal'])

    def test_env_markers_leave_out_the_body_boxes(self):
        checked = 0
        for name, (config, _) in self.launches.items():
            displays = yaml.safe_load(open(config))['Visualization Manager']['Displays']
            for d in displays:
                if d['Class'] == 'rviz/MarkerArray' and d['Marker Topic'].endswith('_env/markers'):
                    namespaces = d.get('Namespaces') or {}
                    self.assertIs(namespaces.get('body'), False,
                                  '%s: display %r shows the body boxes' % (config, d['Name']))
                    checked += 1
        self.assertGreaterEqual(checked, 3)

    def test_the_navigator_goal_is_a_marker_rviz_can_delete(self):
        """RViz's Pose display keeps the last pose it could place; a Marker display takes the
        deploy node's DELETE of an ended goal off the screen."""
        config = os.path.join(rospkg.RosPack().get_path('jetbot_rl'), 'config', 'navigate.rviz')
        displays = yaml.safe_load(open(config))['Visualization Manager']['Displays']
        topics = {d['Class']: d.get('Marker Topic', d.get('Topic')) for d in displays
                  if 'current_goal' in str(d.get('Marker Topic', d.get('Topic', '')))}
        self.assertEqual(topics, {'rviz/Marker': '/navigate/current_goal_marker'})

    def test_view_launch_shows_the_cameras_image(self):
        urdf = os.path.join(PKG, 'urdf', 'jetbot_camera.urdf')
        params = dump('view.launch', 'rviz:=true', 'urdf:=' + urdf)
        self.assertIn('imx219_160', params['/robot_description'])
        # The topic the camera block's plugin gives (cameraName/imageTopicName) under env_0/.
        plugin = ET.parse(urdf).getroot().find('.//sensor/plugin')
        topic = '/env_0/%s/%s' % (plugin.findtext('cameraName'), plugin.findtext('imageTopicName'))
        config = self.launches['view.launch'][0]
        displays = yaml.safe_load(open(config))['Visualization Manager']['Displays']
        images = [d['Image Topic'] for d in displays if d['Class'] == 'rviz/Image']
        self.assertEqual(images, [topic])

    def test_stereo_view_launch_shows_both_cameras_images(self):
        urdf = os.path.join(PKG, 'urdf', 'jetbot_stereo.urdf')
        params = dump('stereo_view.launch', 'rviz:=true')
        self.assertIn('imx219_83_stereo', params['/robot_description'])
        # A multicamera block's plugin publishes cameraName/left|right/imageTopicName.
        plugin = ET.parse(urdf).getroot().find('.//sensor/plugin')
        topics = ['/env_0/%s/%s/%s' % (plugin.findtext('cameraName'), side,
                                       plugin.findtext('imageTopicName'))
                  for side in ('left', 'right')]
        config = self.launches['stereo_view.launch'][0]
        displays = yaml.safe_load(open(config))['Visualization Manager']['Displays']
        images = [d['Image Topic'] for d in displays if d['Class'] == 'rviz/Image']
        self.assertEqual(images, topics)


if __name__ == '__main__':
    rostest.rosrun('jetbot_rl', 'test_rviz_configs', TestRvizConfigs)
