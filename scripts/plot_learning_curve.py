#!/usr/bin/python3
"""Turns a training run's progress.csv into a learning-curve PNG and prints the final figures.

    rosrun jetbot_rl plot_learning_curve.py RUN_DIR_OR_CSV [-o OUT.png] [--target 0.54]
        [--obs-target NAME=VALUE ...]

Writes RUN_DIR/learning_curve.png by default (the CSV's directory). Uses matplotlib's Agg
backend, so no display is needed. When the CSV has obs_mean_<name> columns (the mean of each
observation component over the late steps of episodes), a third panel shows them; observation
targets (--obs-target, and for the command task by default forward_dot_command=0.9 and
lin_vel_b_x=0.3) are drawn there, and the figures say when all of them were first reached.
"""
import argparse
import csv
import math
import os
import sys

import matplotlib

matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402 (after the backend is chosen)

REQUIRED = ['iteration', 'env_steps', 'mean_reward_per_step', 'mean_episode_return',
            'env_steps_per_s', 'elapsed_s']


def read_progress(path):
    with open(path, newline='') as f:
        reader = csv.DictReader(f)
        missing = [c for c in REQUIRED if c not in (reader.fieldnames or [])]
        if missing:
            raise ValueError('%s lacks the column(s) %s' % (path, ', '.join(missing)))
        rows = [{k: float(v) for k, v in row.items() if k is not None and v not in (None, '')}
                for row in reader]
    if not rows:
        raise ValueError('%s has no rows yet' % path)
    return rows


OBS_PREFIX = 'obs_mean_'
# Command task (the CSV has obs_mean_forward_dot_command): the robot faces the command
# (mean cos of the angle > 0.9) and drives along it at more than half the 0.6 m/s maximum.
COMMAND_OBS_TARGETS = [('forward_dot_command', 0.9), ('lin_vel_b_x', 0.3)]


def obs_names(rows):
    """The observation names of the obs_mean_<name> columns, in the CSV's order."""
    return [k[len(OBS_PREFIX):] for k in rows[0] if k.startswith(OBS_PREFIX)]


def default_obs_targets(rows):
    names = obs_names(rows)
    if 'forward_dot_command' in names:
        return [(n, v) for n, v in COMMAND_OBS_TARGETS if n in names]
    return []


def meets(row, obs_targets):
    values = [row.get(OBS_PREFIX + n, float('nan')) for n, _ in obs_targets]
    return all(not math.isnan(v) and v > t for v, (_, t) in zip(values, obs_targets))


def target_from_config(run_dir):
    """target_reward from the run's config.yaml (the trainer's parameter), or None."""
    try:
        with open(os.path.join(run_dir, 'config.yaml')) as f:
            for line in f:
                if line.startswith('target_reward:'):
                    return float(line.split(':', 1)[1].split('#')[0])
    except (OSError, ValueError):
        pass
    return None


def obs_figures(rows, obs_targets):
    """Figures of the obs_mean_* columns: final values and when the targets were reached."""
    out = []
    for name in obs_names(rows):
        tail = [r[OBS_PREFIX + name] for r in rows[-10:]
                if not math.isnan(r.get(OBS_PREFIX + name, float('nan')))]
        out.append(('obs_mean_%s_last_10_iterations' % name,
                    '%.4f' % (sum(tail) / len(tail)) if tail else 'nan'))
    if not obs_targets:
        return out
    out.append(('obs_targets', ', '.join('%s > %g' % t for t in obs_targets)))
    reached = next((r for r in rows if meets(r, obs_targets)), None)
    if reached:
        out += [('obs_targets_reached_at_iteration', '%d' % reached['iteration']),
                ('obs_targets_reached_at_env_steps', '%d' % reached['env_steps']),
                ('obs_targets_reached_at_elapsed_s', '%.1f' % reached['elapsed_s'])]
    else:
        out.append(('obs_targets_reached_at_iteration', 'never'))
    # From which iteration on every later row meets them (robust to a lucky single row).
    held = None
    for r in reversed(rows):
        if not meets(r, obs_targets):
            break
        held = r
    if held:
        out += [('obs_targets_held_from_iteration', '%d' % held['iteration']),
                ('obs_targets_held_from_env_steps', '%d' % held['env_steps']),
                ('obs_targets_held_from_elapsed_s', '%.1f' % held['elapsed_s'])]
    else:
        out.append(('obs_targets_held_from_iteration', 'never'))
    return out


def figures(rows, target):
    """The final figures, as (name, value) pairs."""
    reward = [r['mean_reward_per_step'] for r in rows]
    last = rows[-1]
    reached = next((r for r in rows if r['mean_reward_per_step'] >= target), None)
    tail = reward[-10:]
    out = [
        ('iterations', '%d' % last['iteration']),
        ('env_steps', '%d' % last['env_steps']),
        ('elapsed_s', '%.1f' % last['elapsed_s']),
        ('first_mean_reward_per_step', '%.4f' % reward[0]),
        ('final_mean_reward_per_step', '%.4f' % reward[-1]),
        ('mean_reward_per_step_last_10_iterations', '%.4f' % (sum(tail) / len(tail))),
        ('best_mean_reward_per_step', '%.4f' % max(reward)),
        ('final_mean_episode_return', '%.2f' % last['mean_episode_return']
         if not math.isnan(last['mean_episode_return']) else 'nan'),
        ('mean_env_steps_per_s', '%.0f' % (last['env_steps'] / last['elapsed_s']
                                           if last['elapsed_s'] > 0 else float('nan'))),
        ('target_mean_reward_per_step', '%.4f' % target),
    ]
    if reached:
        out += [('target_reached_at_iteration', '%d' % reached['iteration']),
                ('target_reached_at_env_steps', '%d' % reached['env_steps']),
                ('target_reached_at_elapsed_s', '%.1f' % reached['elapsed_s'])]
    else:
        out += [('target_reached_at_iteration', 'never')]
    return out


RATES = ('success_rate', 'collision_rate', 'timeout_rate')


def has_goals(rows):
    """A task with goals (navigation): some episode reached its goal or collided."""
    return any(r.get(c, 0.0) > 0.0 for r in rows for c in RATES[:2] if not math.isnan(r.get(c, 0.0)))


def rate_figures(rows):
    """The success panel's figures: the last 10 iterations' rates, when success first held 0.9."""
    if not has_goals(rows):
        return []
    out = []
    for c in RATES:
        tail = [r[c] for r in rows[-10:] if not math.isnan(r[c])]
        out.append(('%s_last_10_iterations' % c, '%.3f' % (sum(tail) / len(tail)) if tail else 'nan'))
    first = next((r for r in rows if not math.isnan(r['success_rate']) and r['success_rate'] >= 0.9),
                 None)
    out.append(('success_rate_0.9_first_at_env_steps', '%d' % first['env_steps'] if first else 'never'))
    return out


def plot(rows, target, out, title, obs_targets=()):
    steps = [r['env_steps'] for r in rows]
    reward = [r['mean_reward_per_step'] for r in rows]
    episode = [r['mean_episode_return'] for r in rows]
    goals = has_goals(rows)
    names = [] if goals else obs_names(rows)  # a task with goals: the success panel instead
    if names or goals:
        fig, (ax1, ax2, ax3) = plt.subplots(3, 1, figsize=(8, 10), sharex=True)
    else:
        fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    ax1.plot(steps, reward, color='tab:blue', label='mean reward per step')
    ax1.axhline(target, color='tab:red', linestyle='--', linewidth=1,
                label='target %.3f m/s' % target)
    ax1.set_ylabel('mean reward per step [m/s]')
    ax1.grid(True, alpha=0.3)
    ax1.legend(loc='lower right')
    ax1.set_title(title)
    ax2.plot(steps, episode, color='tab:green', label='mean episode return (last 100)')
    ax2.set_ylabel('episode return')
    ax2.set_xlabel('env steps')
    ax2.grid(True, alpha=0.3)
    ax2.legend(loc='lower right')
    if goals:
        ax2.set_xlabel('')
        for c, color in zip(RATES, ('tab:green', 'tab:red', 'tab:gray')):
            ax3.plot(steps, [r.get(c, float('nan')) for r in rows], color=color,
                     label=c.replace('_', ' ') + ' (episodes ended in the iteration)')
        ax3.axhline(0.9, color='tab:green', linestyle='--', linewidth=1, label='0.9')
        ax3.set_ylim(-0.02, 1.02)
        ax3.set_ylabel('episode outcomes')
        ax3.set_xlabel('env steps')
        ax3.grid(True, alpha=0.3)
        ax3.legend(loc='center right', fontsize='small')
    if names:
        ax2.set_xlabel('')
        targets = dict(obs_targets)
        for k, name in enumerate(names):
            color = 'C%d' % k
            ax3.plot(steps, [r.get(OBS_PREFIX + name, float('nan')) for r in rows], color=color,
                     label=name)
            if name in targets:
                ax3.axhline(targets[name], color=color, linestyle='--', linewidth=1,
                            label='target %s > %g' % (name, targets[name]))
        reached = next((r for r in rows if obs_targets and meets(r, obs_targets)), None)
        if reached:
            ax3.axvline(reached['env_steps'], color='gray', linestyle=':', linewidth=1,
                        label='targets reached (%d env steps)' % reached['env_steps'])
        ax3.set_ylabel('mean observation, late episode steps')
        ax3.set_xlabel('env steps')
        ax3.grid(True, alpha=0.3)
        ax3.legend(loc='lower right', fontsize='small')
    # Wall time on a secondary axis, read from the same rows.
    top = ax1.secondary_xaxis(
        'top', functions=(lambda x: _interp(x, steps, [r['elapsed_s'] for r in rows]),
                          lambda t: _interp(t, [r['elapsed_s'] for r in rows], steps)))
    top.set_xlabel('wall time [s]')
    fig.tight_layout()
    fig.savefig(out, dpi=100)
    plt.close(fig)


def _interp(x, xs, ys):
    """Piecewise-linear map for the secondary axis (scalars or arrays), extended linearly
    beyond the data with the overall slope (matplotlib asks for the whole axis range)."""
    import numpy as np
    xs = np.concatenate(([0.0], np.asarray(xs, dtype=float)))
    ys = np.concatenate(([0.0], np.asarray(ys, dtype=float)))
    slope = (ys[-1] - ys[0]) / (xs[-1] - xs[0]) if xs[-1] > xs[0] else 1.0
    x = np.asarray(x, dtype=float)
    inside = np.interp(x, xs, ys)
    return np.where(x > xs[-1], ys[-1] + (x - xs[-1]) * slope,
                    np.where(x < xs[0], ys[0] + (x - xs[0]) * slope, inside))


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('run', help='run directory or its progress.csv')
    parser.add_argument('-o', '--output', help='PNG to write (default: RUN_DIR/learning_curve.png)')
    parser.add_argument('--target', type=float, default=None,
                        help='target mean reward per step (default: the run\'s config.yaml '
                        'target_reward, else 0.54 m/s = 90%% of 0.6)')
    parser.add_argument('--obs-target', action='append', default=None, metavar='NAME=VALUE',
                        help='target for the column obs_mean_NAME (reached when all are '
                        'exceeded); repeatable; default for the command task: '
                        'forward_dot_command=0.9 and lin_vel_b_x=0.3')
    parser.add_argument('--title', default=None, help='plot title')
    args = parser.parse_args(argv)

    csv_path = os.path.join(args.run, 'progress.csv') if os.path.isdir(args.run) else args.run
    try:
        rows = read_progress(csv_path)
    except (OSError, ValueError) as e:
        print('plot_learning_curve: %s' % e, file=sys.stderr)
        return 1
    run_dir = os.path.dirname(os.path.abspath(csv_path))
    target = args.target
    if target is None:
        target = target_from_config(run_dir)
    if target is None:
        target = 0.54
    if args.obs_target is None:
        obs_targets = default_obs_targets(rows)
    else:
        obs_targets = []
        for spec in args.obs_target:
            name, sep, value = spec.partition('=')
            try:
                obs_targets.append((name, float(value)))
            except ValueError:
                sep = ''
            if not sep or OBS_PREFIX + name not in rows[0]:
                print('plot_learning_curve: bad --obs-target %s: want NAME=VALUE with a column '
                      '%sNAME in the CSV (%s)' % (spec, OBS_PREFIX, ', '.join(obs_names(rows))),
                      file=sys.stderr)
                return 1
    out = args.output or os.path.join(run_dir, 'learning_curve.png')
    title = args.title or 'PPO on jetbot_env: %s' % run_dir
    plot(rows, target, out, title, obs_targets)
    print('learning curve: %s' % out)
    for name, value in figures(rows, target) + obs_figures(rows, obs_targets) + rate_figures(rows):
        print('%s: %s' % (name, value))
    return 0


if __name__ == '__main__':
    sys.exit(main())
