#!/usr/bin/python3
"""PPO in one file (CleanRL's style) that teaches the Jetbot velocity task through JetbotVecEnv
(and the command and navigation tasks, against an env node of that task).

Train against a running jetbot_env node in lockstep mode (100 envs), save, then play the policy:
    roslaunch jetbot_rl jetbot_env.launch publish_clock:=false tf_envs:=0
    rosrun jetbot_rl ppo_example.py --save /tmp/jetbot_ppo.pt
    rosrun jetbot_rl ppo_example.py --play /tmp/jetbot_ppo.pt

The choices of jetbot_ppo_trainer (config/ppo.yaml, rsl_rl's PPO): Gaussian policy with a learned
state-independent std, samples clipped to [-1, 1] and scaled onto the action bounds from ~spec
(+-20 rad/s); separate [32, 32] ELU actor and critic; running observation normalisation;
16 steps per env per iteration, 5 epochs of 4 minibatches, adaptive-KL learning rate; time-outs
bootstrapped with V(final observation); each env's first episode cut at a staggered step.
--obs-history K and --action-history M give the policy memory as the trainer's obs_history_length
and action_history_length do: it sees its last K observations and last M actions.
It reports the first iteration that reaches the task's target (--target, Target below): velocity
a reward per step of 0.54 m/s, command docs/command_task.md's mean heading and speed, navigation
a success rate of 0.9.
"""
import argparse
import os
import signal
import sys
import time


class Renamed(argparse.Action):
    """An option that was renamed: refused (exit 2) with an error naming the new one."""

    def __init__(self, option_strings, dest, new, **kwargs):
        self.new = new
        super().__init__(option_strings, dest, nargs='*', help=argparse.SUPPRESS, **kwargs)

    def __call__(self, parser, namespace, values, option_string=None):
        parser.error('%s was renamed %s' % (option_string, self.new))


def parse_args():
    p = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    p.add_argument('--env-nodes', nargs='+', default=['/jetbot_env'], metavar='NAME',
                   help='env node(s), stepped as one batch (default /jetbot_env)')
    p.add_argument('--seed', type=int, default=0, help='torch seed and env reset seed')
    p.add_argument('--iterations', type=int, default=60)
    p.add_argument('--num-steps', type=int, default=16, help='steps per env per iteration')
    p.add_argument('--target', type=float, default=None, metavar='LEVEL',
                   help="reported: the first iteration that reaches the task's target level "
                        "(velocity: reward/step, default 0.54; navigation: success rate, default "
                        "0.9; command: mean forward_dot_command in the episodes' second half, "
                        "default 0.9, with mean lin_vel_b_x > 0.3 m/s)")
    p.add_argument('--save', default='jetbot_ppo.pt', help='where training saves the policy')
    p.add_argument('--play', metavar='POLICY', help='play a saved policy instead of training')
    p.add_argument('--play-steps', type=int, default=600, help='steps to play')
    p.add_argument('--obs-history', type=int, default=1, metavar='K',
                   help='the policy sees the last K observations (default 1: the current one)')
    p.add_argument('--action-history', type=int, default=0, metavar='M',
                   help='the policy sees its last M actions (default 0)')
    p.add_argument('--node', action=Renamed, new='--env-nodes')
    args = p.parse_args()
    if args.obs_history < 1:
        p.error('invalid --obs-history = %d: must be >= 1' % args.obs_history)
    if args.action_history < 0:
        p.error('invalid --action-history = %d: must be >= 0' % args.action_history)
    return args


if __name__ == '__main__':
    # The options before libtorch's import (2.5 s of CPU): --help and a refused option answer at
    # once.
    ARGUMENTS = parse_args()

import numpy as np  # noqa: E402
import rospy  # noqa: E402
import torch  # noqa: E402
import torch.nn as nn  # noqa: E402

from jetbot_rl import JetbotVecEnv  # noqa: E402


# PPO hyper-parameters (config/ppo.yaml)
EPOCHS, MINIBATCHES, GAMMA, LAM, CLIP, VALUE_COEF, ENTROPY_COEF = 5, 4, 0.99, 0.95, 0.2, 1.0, 0.005
LR, DESIRED_KL, MIN_LR, MAX_LR, MAX_GRAD_NORM = 1e-3, 0.01, 1e-5, 1e-2, 1.0


def mlp(n_in, n_out):
    return nn.Sequential(nn.Linear(n_in, 32), nn.ELU(), nn.Linear(32, 32), nn.ELU(),
                         nn.Linear(32, n_out))


class History:
    """Each env's last k observations (raw, newest first) and last m actions (in [-1, 1], newest
    first): the policy's input, as jetbot_ppo_trainer's obs_history_length and
    action_history_length build it. An env whose episode ended starts over at its next
    observation: every slot holds it and the actions are zero. k = 1, m = 0: the observation."""

    def __init__(self, n, obs_dim, action_dim, k, m):
        self.k, self.m = k, m
        self.obs, self.act = torch.zeros(n, k, obs_dim), torch.zeros(n, m, action_dim)
        self.fresh = torch.ones(n, dtype=torch.bool)

    def _pushed(self, rows, obs, fresh):
        newest = obs.unsqueeze(1)
        slots = torch.cat([newest, self.obs[rows, :self.k - 1]], 1)
        slots = torch.where(fresh.view(-1, 1, 1), newest.expand_as(slots), slots)
        acts = torch.where(fresh.view(-1, 1, 1), torch.zeros_like(self.act[rows]), self.act[rows])
        return slots, acts

    @staticmethod
    def _input(slots, acts, normalize):
        n = slots.shape[0]
        obs = normalize(slots.reshape(-1, slots.shape[2])).reshape(n, -1)
        return torch.cat([obs, acts.reshape(n, -1)], 1)

    def push(self, obs, normalize):
        """Pushes every env's observation; returns the input [n, input_dim]."""
        self.obs, self.act = self._pushed(torch.arange(len(obs)), obs, self.fresh)
        self.fresh[:] = False
        return self._input(self.obs, self.act, normalize)

    def push_actions(self, actions):
        if self.m:
            self.act = torch.cat([actions.clamp(-1.0, 1.0).unsqueeze(1), self.act[:, :-1]], 1)

    def peek(self, rows, obs, normalize, fresh=None):
        """The input envs `rows` would get from push(obs); nothing changes."""
        fresh = torch.zeros(len(rows), dtype=torch.bool) if fresh is None else fresh
        return self._input(*self._pushed(rows, obs, fresh), normalize)

    def end(self, ended):
        """Envs whose episode ended: they start over at their next observation."""
        self.fresh |= torch.as_tensor(ended)


class Agent(nn.Module):
    def __init__(self, obs_dim, action_dim, input_dim=None):
        super().__init__()
        input_dim = input_dim or obs_dim  # with a history: k x obs_dim + m x action_dim
        self.actor, self.critic = mlp(input_dim, action_dim), mlp(input_dim, 1)
        self.log_std = nn.Parameter(torch.zeros(action_dim))  # std 1 = the action limit
        # running observation statistics, saved with the policy
        self.register_buffer('obs_mean', torch.zeros(obs_dim, dtype=torch.float64))
        self.register_buffer('obs_var', torch.ones(obs_dim, dtype=torch.float64))
        self.register_buffer('obs_count', torch.zeros((), dtype=torch.float64))

    def update_normalizer(self, obs):  # merges the batch's mean and variance (Chan et al.)
        x, c = obs.double(), self.obs_count
        n, delta = x.shape[0], x.mean(0) - self.obs_mean
        total = c + n
        self.obs_var.copy_((self.obs_var * c + x.var(0, unbiased=False) * n
                            + delta ** 2 * c * n / total) / total)
        self.obs_mean.add_(delta * n / total)
        self.obs_count.fill_(total)

    def normalize(self, obs):  # rsl_rl's (obs - mean) / (std + 0.01), clipped to +-10
        std = self.obs_var.sqrt() + 0.01
        return ((obs - self.obs_mean.float()) / std.float()).clamp(-10.0, 10.0)

    def dist(self, obs_n):
        mean = self.actor(obs_n)
        return torch.distributions.Normal(mean, self.log_std.exp().expand_as(mean))

    def value(self, obs_n):
        return self.critic(obs_n).squeeze(-1)


class Target:
    """The task's target, checked once per iteration (--target LEVEL):
    - velocity (and a task it does not know): the mean reward per step >= LEVEL (0.54 m/s: 90 %
      of the wheels' top speed);
    - a task with goals (navigation): the success rate of the episodes that ended in the
      iteration (infos["outcome"]) >= LEVEL (0.9);
    - command: docs/command_task.md's targets, the means over the observations the policy acted
      on in the second half of their episode (episode step >= max_episode_length / 2, as
      jetbot_ppo_trainer's obs_mean_* columns): forward_dot_command > LEVEL (0.9) and
      lin_vel_b_x > 0.3 m/s."""

    COMMAND_SPEED = 0.3  # m/s: half the top speed

    def __init__(self, env, level):
        names = env.observation_names
        if env.has_goals:
            self.kind, default = 'success', 0.9
        elif env.task == 'command' and {'forward_dot_command', 'lin_vel_b_x'} <= set(names):
            self.kind, default = 'command', 0.9
            self.dot, self.speed = names.index('forward_dot_command'), names.index('lin_vel_b_x')
            self.from_step = env.max_episode_length // 2
        else:
            self.kind, default = 'reward', 0.54
        self.level = default if level is None else level
        # (">=": no "reward/step <number>" that a progress-line parser would take for one)
        self.name = {'success': 'success rate >= %.2f', 'reward': 'reward/step >= %.2f',
                     'command': 'forward_dot_command > %.2f and lin_vel_b_x > %.2f'}[self.kind] % (
            (self.level, self.COMMAND_SPEED) if self.kind == 'command' else self.level)

    def describe(self):
        if self.kind == 'success':
            return self.name + ' (episodes ended in an iteration)'
        if self.kind == 'command':
            return self.name + ' m/s (means from episode step %d on)' % self.from_step
        return self.name

    def start(self):
        self.sums, self.count = np.zeros(2), 0

    def observe(self, obs, episode_steps):
        """The observations the policy acts on and their episode steps (command task)."""
        if self.kind == 'command':
            rows = obs[episode_steps >= self.from_step]
            self.sums += rows[:, [self.dot, self.speed]].sum(0)
            self.count += len(rows)

    def progress(self):
        """The command task's means for the progress line, '' for the others."""
        if self.kind != 'command' or not self.count:
            return ''
        return ' | forward_dot_command %.2f lin_vel_b_x %.2f' % tuple(self.sums / self.count)

    def reached(self, reward_per_step, outcomes):
        if self.kind == 'success':
            return outcomes.sum() > 0 and outcomes[1] / outcomes.sum() >= self.level
        if self.kind == 'command':
            return (self.count > 0 and self.sums[0] / self.count > self.level
                    and self.sums[1] / self.count > self.COMMAND_SPEED)
        return reward_per_step >= self.level


def to_env(agent_actions, low, high):
    """Gaussian samples -> clipped to [-1, 1] -> the env's [low, high] [rad/s]."""
    return (low + (high - low) * (agent_actions.clamp(-1.0, 1.0) + 1.0) / 2.0).numpy()


def train(args):
    torch.manual_seed(args.seed)
    env = JetbotVecEnv(env_nodes=args.env_nodes)
    n, steps, obs_dim, act_dim = env.num_envs, args.num_steps, env.obs_dim, env.action_dim
    low, high = torch.from_numpy(env.action_low), torch.from_numpy(env.action_high)
    history = History(n, obs_dim, act_dim, args.obs_history, args.action_history)
    input_dim = args.obs_history * obs_dim + args.action_history * act_dim
    agent = Agent(obs_dim, act_dim, input_dim)
    optimizer = torch.optim.Adam(agent.parameters(), lr=LR)
    lr = LR
    buf_obs, buf_act = torch.zeros(steps, n, input_dim), torch.zeros(steps, n, act_dim)
    buf_mean = torch.zeros(steps, n, act_dim)
    buf_logp, buf_val, buf_rew = (torch.zeros(steps, n) for _ in range(3))
    buf_end = torch.zeros(steps, n, dtype=torch.bool)  # the episode ended after this step
    buf_boot = torch.zeros(steps, n)  # its value after the end: V(final obs) for a time-out, 0 else
    # Staggering: env i's first episode is cut after i x (max_episode_length - 1) / n steps (a
    # bootstrapped time-out; 299 with the defaults), so that episodes end at different steps from
    # then on.
    cut_at = np.arange(n) * (env.max_episode_length - 1) // n
    target = Target(env, args.target)
    env_steps, target_at, start = 0, None, time.monotonic()
    obs, infos = env.reset(seed=args.seed)
    episode_steps = infos['episode_steps']  # of obs, the observations the policy acts on
    # Ctrl-C and SIGTERM end training at the next step: the rollout under way is dropped and the
    # policy of the last whole iteration is saved (within a step's time, not an iteration's).
    stop = []
    for sig in (signal.SIGINT, signal.SIGTERM):
        signal.signal(sig, lambda *_: stop.append(True))
    reward_per_step, interrupted, iterations_done = float('nan'), False, 0
    for iteration in range(1, args.iterations + 1):
        if stop:
            print('stopped by a signal after iteration %d: saving its policy' % (iteration - 1),
                  flush=True)
            interrupted = True
            break
        t0 = time.monotonic()
        outcomes = np.zeros(3, dtype=np.int64)  # ended episodes: time-out, success, collision
        target.start()
        taken = 0  # steps of this rollout
        for t in range(steps):
            if stop:
                break
            target.observe(obs, episode_steps)
            o = torch.from_numpy(obs)
            agent.update_normalizer(o)
            o_n = history.push(o, agent.normalize)
            with torch.no_grad():
                d = agent.dist(o_n)
                a = d.sample()
                buf_logp[t], buf_mean[t] = d.log_prob(a).sum(-1), d.mean
                buf_val[t] = agent.value(o_n)
            buf_obs[t], buf_act[t] = o_n, a
            history.push_actions(a)
            obs, reward, terminated, truncated, infos = env.step(to_env(a, low, high))
            episode_steps = infos['episode_steps']
            buf_rew[t] = torch.from_numpy(reward)
            if 'outcome' in infos:  # EnvStep.OUTCOME_*, for the envs in _outcome
                counts = np.bincount(infos['outcome'][infos['_outcome']], minlength=6)
                # 2-4: the world, a mover, a robot; 5: a round's wait (rounds), no episode
                outcomes += [counts[0], counts[1], counts[2:5].sum()]
            boot = np.zeros(n, dtype=np.float32)
            timed_out = truncated & ~terminated
            cut = (cut_at == env_steps // n + t + 1) & ~terminated & ~truncated
            # V(the observation after the end) continues the env's history
            with torch.no_grad():
                if timed_out.any():
                    rows = torch.from_numpy(np.flatnonzero(timed_out))
                    final = torch.from_numpy(infos['final_obs'][timed_out])
                    boot[timed_out] = agent.value(history.peek(rows, final, agent.normalize))
                if cut.any():
                    rows = torch.from_numpy(np.flatnonzero(cut))
                    now = torch.from_numpy(obs[cut])
                    boot[cut] = agent.value(history.peek(rows, now, agent.normalize))
            if cut.any():
                obs, infos = env.reset(options={'reset_mask': cut})
                episode_steps = infos['episode_steps']
            history.end(terminated | truncated | cut)
            buf_end[t] = torch.from_numpy(terminated | truncated | cut)
            buf_boot[t] = torch.from_numpy(boot)
            taken = t + 1
        env_steps += taken * n
        if taken < steps:
            print('stopped by a signal in iteration %d: saving the policy of iteration %d'
                  % (iteration, iteration - 1), flush=True)
            interrupted = True
            break

        # GAE; an ended episode's next value is its bootstrap value, and nothing flows across it
        with torch.no_grad():
            next_value = agent.value(history.peek(torch.arange(n), torch.from_numpy(obs),
                                                  agent.normalize, history.fresh))
        advantages, gae = torch.zeros(steps, n), torch.zeros(n)
        for t in reversed(range(steps)):
            nxt = next_value if t == steps - 1 else buf_val[t + 1]
            nxt = torch.where(buf_end[t], buf_boot[t], nxt)
            delta = buf_rew[t] + GAMMA * nxt - buf_val[t]
            gae = delta + GAMMA * LAM * (~buf_end[t]).float() * gae
            advantages[t] = gae
        returns = advantages + buf_val
        advantages = (advantages - advantages.mean()) / (advantages.std() + 1e-8)

        b_obs, b_act, b_mean = (x.flatten(0, 1) for x in (buf_obs, buf_act, buf_mean))
        b_logp, b_val, b_adv, b_ret = (x.flatten() for x in (buf_logp, buf_val, advantages,
                                                             returns))
        old_std = agent.log_std.exp().detach()
        for _ in range(EPOCHS):
            for idx in torch.randperm(steps * n).chunk(MINIBATCHES):
                d = agent.dist(b_obs[idx])
                with torch.no_grad():  # KL(old || new) drives the learning rate (rsl_rl)
                    kl = (torch.log(d.stddev / old_std) + (old_std ** 2 + (b_mean[idx] - d.mean)
                          ** 2) / (2 * d.stddev ** 2) - 0.5).sum(-1).mean().item()
                if kl > 2 * DESIRED_KL:
                    lr = max(MIN_LR, lr / 1.5)
                elif 0 < kl < DESIRED_KL / 2:
                    lr = min(MAX_LR, lr * 1.5)
                for group in optimizer.param_groups:
                    group['lr'] = lr
                ratio = torch.exp(d.log_prob(b_act[idx]).sum(-1) - b_logp[idx])
                adv = b_adv[idx]
                surrogate = torch.max(-adv * ratio, -adv * ratio.clamp(1 - CLIP, 1 + CLIP)).mean()
                value = agent.value(b_obs[idx])
                clipped = b_val[idx] + (value - b_val[idx]).clamp(-CLIP, CLIP)
                value_loss = torch.max((value - b_ret[idx]) ** 2,
                                       (clipped - b_ret[idx]) ** 2).mean()
                entropy = d.entropy().sum(-1).mean()
                loss = surrogate + VALUE_COEF * value_loss - ENTROPY_COEF * entropy
                optimizer.zero_grad()
                loss.backward()
                nn.utils.clip_grad_norm_(agent.parameters(), MAX_GRAD_NORM)
                optimizer.step()

        reward_per_step = buf_rew.mean().item()
        elapsed = time.monotonic() - start
        if target_at is None and target.reached(reward_per_step, outcomes):
            target_at = (iteration, env_steps, elapsed)
        rates = target.progress()
        if env.has_goals and outcomes.sum():  # some episode ended in the iteration
            rates += ' | success %.2f collision %.2f' % tuple(outcomes[1:] / outcomes.sum())
        print('iteration %d/%d | env steps %d | reward/step %.4f%s | %.0f env steps/s | elapsed '
              '%.1f s' % (iteration, args.iterations, env_steps, reward_per_step, rates,
                          steps * n / (time.monotonic() - t0), elapsed), flush=True)
        iterations_done = iteration
    elapsed = time.monotonic() - start
    torch.save({'model': agent.state_dict(), 'obs_dim': obs_dim, 'action_dim': act_dim,
                'obs_history': args.obs_history, 'action_history': args.action_history},
               args.save)
    env.close()
    print('saved %s' % args.save)
    print('status=%s' % ('interrupted' if interrupted else 'completed'))
    print('final_mean_reward_per_step=%.4f' % reward_per_step)
    print('env_steps=%d elapsed_s=%.1f mean_env_steps_per_s=%.0f'
          % (env_steps, elapsed, env_steps / elapsed))
    print('target=%s' % target.describe())
    if target_at:
        print('%s reached at iteration %d (%d env steps, %.1f s)' % ((target.name,) + target_at))
        print('target_reached_at_iteration=%d target_reached_at_env_steps=%d '
              'target_reached_at_elapsed_s=%.1f' % target_at)
    else:
        print('%s not reached in %d iterations' % (target.name, iterations_done))
        print('target_reached_at_iteration=never')


def play(args):
    """Drives every env with the policy's mean action; prints the reward and episode returns."""
    saved = torch.load(args.play)
    obs_dim, act_dim = saved['obs_dim'], saved['action_dim']
    k, m = saved.get('obs_history', 1), saved.get('action_history', 0)
    agent = Agent(obs_dim, act_dim, k * obs_dim + m * act_dim)
    agent.load_state_dict(saved['model'])
    env = JetbotVecEnv(env_nodes=args.env_nodes)
    history = History(env.num_envs, obs_dim, act_dim, k, m)
    low, high = torch.from_numpy(env.action_low), torch.from_numpy(env.action_high)
    obs, _ = env.reset(seed=args.seed)
    episode_return, returns, rewards, at_limit = np.zeros(env.num_envs), [], 0.0, 0
    for _ in range(args.play_steps):
        with torch.no_grad():
            mean = agent.actor(history.push(torch.from_numpy(obs), agent.normalize))
        history.push_actions(mean)
        targets = to_env(mean, low, high)
        saturated = np.all(np.abs(np.abs(targets) - high.numpy()) < 0.02 * high.numpy(), axis=1)
        at_limit += int(np.sum(saturated & (np.sign(targets[:, 0]) == np.sign(targets[:, 1]))))
        obs, reward, terminated, truncated, _ = env.step(targets)
        rewards += reward.sum()
        episode_return += reward
        ended = terminated | truncated
        history.end(ended)
        returns.extend(episode_return[ended].tolist())
        episode_return[ended] = 0.0
    env.close()
    steps = args.play_steps * env.num_envs
    print('play_mean_reward_per_step=%.4f' % (rewards / steps))
    print('play_fraction_both_wheels_at_limit=%.4f' % (at_limit / steps))
    print('play_mean_episode_return=%s (%d episodes)'
          % ('%.2f' % np.mean(returns) if returns else 'nan', len(returns)))


if __name__ == '__main__':
    torch.set_num_threads(1)  # reproducible, and leaves the other core to the env
    if ARGUMENTS.play:
        play(ARGUMENTS)
    else:
        train(ARGUMENTS)
    # Done (the policy saved, the figures printed): unregister from the master, then exit without
    # Python's teardown of libtorch's modules (half a second of CPU, twice that on a loaded
    # machine, after a Ctrl-C that should end the program at once).
    rospy.signal_shutdown('done')
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(0)
