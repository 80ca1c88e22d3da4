# Installs two Python packages through catkin_python_setup(): `jetbot_rl` (src/jetbot_rl:
# JetbotVecEnv and friends; catkin merges it with the generated jetbot_rl.msg and jetbot_rl.srv)
# and, beside it, `jetbot_rl_test` (test/jetbot_rl_test: the helpers the rostests import).
# Do not run it by hand: catkin_make does.
from catkin_pkg.python_setup import generate_distutils_setup
from setuptools import setup

setup(**generate_distutils_setup(
    packages=['jetbot_rl', 'jetbot_rl_test'],
    package_dir={'jetbot_rl': 'src/jetbot_rl', 'jetbot_rl_test': 'test/jetbot_rl_test'}))
