#!/usr/bin/python3
"""Code and docs cannot disagree: the parameter tables of docs/ are the generated ones, and every
default written outside the C++ field lists (config/*.yaml, the launch files' arguments and their
documented defaults) is the C++ default; every key of a parameter file is a parameter."""
import functools
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
PROGRAM = ['rosrun', 'jetbot_rl', 'jetbot_rl_param_docs']

# The nodes whose parameters each launch file sets through its arguments, in lookup order.
LAUNCH_NODES = {
    'jetbot_env.launch': ['jetbot_env_node'],
    'env_nodes.launch': ['jetbot_env_node'],
    'env_host.launch': ['jetbot_env_node'],
    'view.launch': ['jetbot_env_node'],
    'train.launch': ['jetbot_ppo_trainer', 'jetbot_env_node'],
    'play.launch': ['jetbot_policy_node', 'jetbot_env_node'],
    'bench_nodelets.launch': ['lockstep_bench_nodelet', 'jetbot_env_node'],
    'world_view.launch': ['jetbot_env_node'],
    'navigate.launch': ['jetbot_deploy_node', 'jetbot_depth_scan'],
    'deploy.launch': ['jetbot_deploy_node', 'jetbot_depth_scan'],
}
# Parameter files that hold a node's defaults (every value set or commented out must be it).
DEFAULTS_FILES = {'config/jetbot_env.yaml': 'jetbot_env_node', 'config/ppo.yaml': 'jetbot_ppo_trainer'}
# A documented default in a launch argument's doc: "(empty: YAML, 100)", "(empty: the YAML's, exp)".
DOCUMENTED = re.compile(r'\(empty: [^,()]*, ([^()]+)\)')


@functools.lru_cache(maxsize=None)
def run(*args):
    return subprocess.run(PROGRAM + list(args), check=True, stdout=subprocess.PIPE,
                          universal_newlines=True).stdout


def number_or_text(value):
    """YAML 1.1 reads 1e-05 (no dot) as text: the C++ writes doubles as their shortest form; an
    empty string is written as nothing."""
    if value is None:
        return ''
    if isinstance(value, str):
        try:
            return float(value)
        except ValueError:
            return value
    return value


def defaults(node):
    return {k: number_or_text(v) for k, v in yaml.safe_load(run('defaults', node)).items()}


def flatten(tree, prefix=''):
    """{'world': {'map': x}} -> {'world/map': x}: parameter names as the nodes read them."""
    out = {}
    for key, value in (tree or {}).items():
        if isinstance(value, dict):
            out.update(flatten(value, prefix + key + '/'))
        else:
            out[prefix + key] = value
    return out


def settings(path, commented=False):
    """The parameters a file sets; with `commented`, also the defaults it shows commented out
    ("# drive_gain: 10.0", "# world:" and its indented "#   map: ''")."""
    lines = []
    for line in open(path):
        shown = re.match(r'^# ( *\w+:.*)$', line.rstrip('\n')) if commented else None
        if shown:
            lines.append(shown.group(1))
        elif not line.startswith('#'):
            lines.append(line.rstrip('\n'))
    return flatten(yaml.safe_load('\n'.join(lines)))


def same(a, b):
    if isinstance(a, list) != isinstance(b, list):  # one value stands for a list of one
        a, b = (a if isinstance(a, list) else [a]), (b if isinstance(b, list) else [b])
    if isinstance(a, (int, float)) and isinstance(b, (int, float)) and not isinstance(a, bool):
        return float(a) == float(b)
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
    return a == b


class TestParamDocs(unittest.TestCase):
    def test_tables_are_generated(self):
        result = subprocess.run(['rosrun', 'jetbot_rl', 'generate_param_docs.py', '--check'],
                                stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                universal_newlines=True)
        self.assertEqual(result.returncode, 0, result.stdout)

    def test_every_table_is_in_the_docs(self):
        ids = re.findall(r'^## (\w+)$', run('tables'), re.M)
        self.assertTrue(ids)
        docs = ''.join(open(p).read() for p in glob.glob(os.path.join(PKG, 'docs', '*.md')))
        for table_id in ids:
            self.assertIn('<!-- BEGIN GENERATED PARAMS: %s -->' % table_id, docs, table_id)

    def test_every_message_and_service_field_is_documented(self):
        """docs/ros_interface.md has a section per message and service (its heading names it in
        backticks) that names every field and constant of its definition."""
        with open(os.path.join(PKG, 'docs', 'ros_interface.md')) as f:
            page = f.read()
        sections = re.split(r'^### ', page, flags=re.M)
        checked = 0
        for path in sorted(glob.glob(os.path.join(PKG, 'msg', '*.msg')) +
                           glob.glob(os.path.join(PKG, 'srv', '*.srv'))):
            name = os.path.splitext(os.path.basename(path))[0]
            heading = re.compile(r'^[^\n]*`(jetbot_rl/)?%s`' % name)
            section = [t for t in sections if heading.match(t)]
            self.assertEqual(len(section), 1, '%s: no (or several) sections in ros_interface.md'
                             % name)
            for line in open(path):
                words = line.split('#')[0].replace('=', ' ').split()
                if len(words) < 2 or line.strip() == '---':
                    continue
                field = words[1]
                # A message's table names a field in backticks (`header.stamp` names header); a
                # service's section shows its definition in a code block.
                pattern = (r'`%s[`.]' % field if path.endswith('.msg')
                           else r'(^|\s)%s(\s|=|$)' % field)
                self.assertTrue(re.search(pattern, section[0], re.M),
                                '%s.%s is not documented' % (name, field))
                checked += 1
        self.assertGreater(checked, 40)

    def test_defaults_files_hold_the_cpp_defaults(self):
        checked = 0
        for path, node in DEFAULTS_FILES.items():
            cpp = defaults(node)
            for key, value in settings(os.path.join(PKG, path), commented=True).items():
                if key not in cpp:
                    continue
                self.assertTrue(same(number_or_text(value), cpp[key]),
                                '%s: %s is %r, the C++ default %r' % (path, key, value, cpp[key]))
                checked += 1
        self.assertGreater(checked, 80)

    def test_every_key_of_a_parameter_file_is_a_parameter(self):
        known = {}
        for node in ('jetbot_env_node', 'jetbot_ppo_trainer', 'jetbot_policy_node'):
            known.update(defaults(node))
        files = glob.glob(os.path.join(PKG, 'config', '*.yaml')) + \
            glob.glob(os.path.join(PKG, 'urdf', '**', '*.yaml'), recursive=True)
        self.assertGreater(len(files), 5)
        for path in files:
            for key in settings(path):
                self.assertIn(key, known, '%s: %s is no parameter of the package' % (path, key))

    def test_launch_defaults_are_the_cpp_defaults(self):
        node_defaults = {n: defaults(n) for names in LAUNCH_NODES.values() for n in names}
        checked, wrong = 0, []
        for name, nodes in LAUNCH_NODES.items():
            path = glob.glob(os.path.join(PKG, '**', name), recursive=True)
            self.assertEqual(len(path), 1, name)
            for arg in ET.parse(path[0]).getroot().iter('arg'):
                key, doc = arg.get('name'), arg.get('doc', '')
                cpp = next((node_defaults[n][key] for n in nodes if key in node_defaults[n]), None)
                if cpp is None:
                    continue
                documented = DOCUMENTED.search(doc)
                if documented:
                    value = number_or_text(yaml.safe_load(documented.group(1)))
                    if not same(value, cpp):
                        wrong.append('%s: %s documents the default %r, C++ has %r'
                                     % (name, key, value, cpp))
                    checked += 1
                default = arg.get('default')
                if default and '$(' not in default and 'launch default' not in doc:
                    value = number_or_text(yaml.safe_load(default))
                    if not same(value, cpp):
                        wrong.append('%s: %s defaults to %r, C++ to %r (say "launch default" in '
                                     'its doc when that is meant)' % (name, key, value, cpp))
                    checked += 1
        self.assertEqual(wrong, [], '\n'.join(wrong))
        self.assertGreater(checked, 15)


if __name__ == '__main__':
    rostest.rosrun('jetbot_rl', 'test_param_docs', TestParamDocs)
