#!/usr/bin/env bash
# Several env nodes against one: N envs in total stepped through K nodes of T/K threads each
# versus one node of T threads, in the same run (issue 13's bench). Default N = 1024, K = 2,
# T = 2. Needs a built workspace:
#   source ~/jetbot_rl_ws/devel/setup.bash && rosrun jetbot_rl bench_nodes.sh [N] [K] [T] [STEPS]
# Uses its own ROS master on port 11398; prints env steps/s of both and their ratio.
set -euo pipefail

n=${1:-1024}
k=${2:-2}
t=${3:-2}
steps=${4:-400}
# shellcheck source=bench_common.sh
source "$(dirname "${BASH_SOURCE[0]}")/bench_common.sh" 11398

# run K: K nodes sharing n envs and t threads; prints env steps/s through all of them.
run() {
  local num_env_nodes=$1 nodes
  roslaunch jetbot_rl env_nodes.launch num_env_nodes:="$num_env_nodes" num_envs:="$n" num_threads:="$t" \
    > "$bench_dir/env.log" 2>&1 &
  launch_pid=$!
  nodes=$(seq -s, -f 'jetbot_env_%g' 0 $((num_env_nodes - 1)))
  rosrun jetbot_rl jetbot_rl_nodes_bench --env-nodes "$nodes" --steps "$steps" | field env_steps_per_s
  stop_launch
}

one=$(run 1)
several=$(run "$k")
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "| N | nodes x threads | env steps/s |"
echo "|---|---|---|"
printf '| %d | 1 x %d | %.0f |\n' "$n" "$t" "$one"
printf '| %d | %d x %d | %.0f |\n' "$n" "$k" "$((t / k > 0 ? t / k : 1))" "$several"
echo "ratio_several_over_one=$(awk "BEGIN { printf \"%.3f\", $several / $one }")"
