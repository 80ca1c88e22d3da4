#!/usr/bin/env bash
# Trains the policies shipped in policies/ (policies/README.md), each exactly as its row there
# says, and keeps of each run directory what a user plays, deploys and reads in policies/<name>/:
# checkpoints/best.pt, exported/ (TorchScript), config.yaml and summary.yaml.
# Deterministic: the same build trains the same policies bit for bit. Needs a sourced workspace
# (devel/setup.bash).
#   bash scripts/train_shipped_policies.sh [NAME ...]   (none: all of them)
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
config=$repo/config
work=${JETBOT_RL_POLICY_RUNS:-$(mktemp -d /tmp/jetbot_rl_policies_XXXXXX)}

# name: train.launch arguments (in_process:=true, seed 0 always)
declare -A recipe=(
  [velocity]="task:=velocity iterations:=60 randomization:=$config/randomization.yaml"
  [command]="task:=command iterations:=300 randomization:=$config/randomization.yaml"
  [command_memory]="task:=command config:=$config/ppo_command_memory.yaml robot_config:=$config/jetbot_motors.yaml randomization:=$config/randomization.yaml"
  [command_motors]="task:=command iterations:=300 robot_config:=$config/jetbot_motors.yaml randomization:=$config/randomization.yaml"
  [navigation]="task:=navigation"
  [navigation_arena]="task:=navigation iterations:=200 task_config:=$config/navigation_arena.yaml"
  [people]="task:=navigation task_config:=$config/navigation_people.yaml config:=$config/ppo_navigation_people.yaml"
  [swap]="task:=navigation task_config:=$config/navigation_swap.yaml config:=$config/ppo_navigation_swap.yaml"
  [navigation_mix]="task:=navigation mix:=true"
  [navigation_camera]="task:=navigation urdf:=$repo/urdf/jetbot_camera.urdf task_config:=$config/navigation_camera_env.yaml world:=$config/world_generated.yaml"
  [road_following]="task:=road_following"
)
names=("$@")
[ ${#names[@]} -gt 0 ] || names=(velocity command command_memory command_motors navigation_arena people navigation swap navigation_mix navigation_camera road_following)
for name in "${names[@]}"; do
  [ -n "${recipe[$name]+x}" ] || { echo "unknown policy '$name': one of ${!recipe[*]}" >&2; exit 2; }
done
for name in "${names[@]}"; do
  run_dir=$work/$name
  echo "== $name: train.launch in_process:=true seed:=0 ${recipe[$name]}"
  start=$(date +%s)
  # shellcheck disable=SC2086
  roslaunch jetbot_rl train.launch in_process:=true seed:=0 output:=log run_dir:="$run_dir" ${recipe[$name]} >/dev/null
  echo "   $(( $(date +%s) - start )) s"
  cat "$run_dir/summary.yaml"
  keep=$repo/policies/$name
  rm -rf "$keep"
  mkdir -p "$keep/checkpoints"
  cp "$run_dir/checkpoints/best.pt" "$keep/checkpoints/"
  cp -r "$run_dir/exported" "$run_dir/config.yaml" "$run_dir/summary.yaml" "$keep/"
done
