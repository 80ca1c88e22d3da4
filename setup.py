# Installs the Python package `jetbot_rl` (src/jetbot_rl: JetbotVecEnv and friends) through
# catkin_python_setup(); catkin merges it with the generated jetbot_rl.msg and jetbot_rl.srv.
# Do not run it by hand: catkin_make does.
from catkin_pkg.python_setup import generate_distutils_setup
from setuptools import setup

setup(**generate_distutils_setup(packages=['jetbot_rl'], package_dir={'': 'src'}))
