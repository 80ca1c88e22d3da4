#!/usr/bin/env python3
"""Writes the parameter tables of docs/ from the C++ field lists.

    rosrun jetbot_rl generate_param_docs.py          # rewrite the tables in docs/*.md
    rosrun jetbot_rl generate_param_docs.py --check  # exit 1 when a table is stale

A table sits between `<!-- BEGIN GENERATED PARAMS: ID -->` and `<!-- END GENERATED PARAMS: ID -->`;
its rows come from `jetbot_rl_param_docs tables` (run once; `table ID` gives one) (name, type, default, rule, meaning of every
field, as the nodes validate and echo them).
"""
import argparse
import os
import re
import subprocess
import sys

MARKER = re.compile(r'(<!-- BEGIN GENERATED PARAMS: (\w+) -->\n)(.*?)(<!-- END GENERATED PARAMS: \2 -->)',
                    re.S)


def docs_dir():
    return os.path.join(os.path.dirname(os.path.dirname(os.path.realpath(__file__))), 'docs')


def all_tables(program):
    """{ID: table} from one run of the program (`tables`: "## ID" and its table, for each)."""
    out = subprocess.run(program + ['tables'], check=True, stdout=subprocess.PIPE,
                         universal_newlines=True).stdout
    parts = re.split(r'^## (\w+)\n', out, flags=re.M)
    return dict(zip(parts[1::2], parts[2::2]))


def regenerate(text, tables):
    """`text` with every marked table rewritten from `tables` ({ID: table}), and the IDs found."""
    ids = []

    def replace(match):
        ids.append(match.group(2))
        if match.group(2) not in tables:
            sys.exit('unknown parameter table %s (not among jetbot_rl_param_docs tables)'
                     % match.group(2))
        return match.group(1) + tables[match.group(2)] + match.group(4)

    return MARKER.sub(replace, text), ids


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--check', action='store_true', help='only check; exit 1 when stale')
    parser.add_argument('--docs', default=docs_dir(), help='folder of the pages (default: docs/)')
    parser.add_argument('--program', nargs='+', default=['rosrun', 'jetbot_rl', 'jetbot_rl_param_docs'],
                        help='the table program and its leading arguments')
    args = parser.parse_args()
    stale, seen = [], []
    tables = all_tables(args.program)
    for name in sorted(os.listdir(args.docs)):
        if not name.endswith('.md'):
            continue
        path = os.path.join(args.docs, name)
        with open(path) as f:
            text = f.read()
        new, ids = regenerate(text, tables)
        seen += ids
        if new != text:
            stale.append(name)
            if not args.check:
                with open(path, 'w') as f:
                    f.write(new)
    if not seen:
        sys.exit('generate_param_docs.py: no table markers in %s' % args.docs)
    if args.check and stale:
        print('stale parameter tables in: %s (run rosrun jetbot_rl generate_param_docs.py)'
              % ', '.join(stale))
        sys.exit(1)
    print('%s %d tables in %s' % ('checked' if args.check else 'wrote', len(seen), args.docs))


if __name__ == '__main__':
    main()
