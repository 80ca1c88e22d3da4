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
export ROS_MASTER_URI=http://localhost:11398
dir=$(mktemp -d)
roscore -p 11398 > "$dir/roscore.log" 2>&1 &
roscore_pid=$!
launch_pid=""
cleanup() {
  [ -z "$launch_pid" ] || kill -INT "$launch_pid" 2> /dev/null || true
  kill -INT "$roscore_pid" 2> /dev/null || true
  wait 2> /dev/null || true
  rm -rf "$dir"
}
trap cleanup EXIT
until rostopic list > /dev/null 2>&1; do sleep 0.2; done  # the master answers
field() { grep -o "$1=[0-9.]*" | tail -n 1 | cut -d= -f2; }

# run COUNT: COUNT nodes sharing n envs and t threads; prints env steps/s through all of them.
run() {
  local count=$1 nodes
  roslaunch jetbot_rl env_nodes.launch count:="$count" num_envs:="$n" num_threads:="$t" \
    > "$dir/env.log" 2>&1 &
  launch_pid=$!
  nodes=$(seq -s, -f 'jetbot_env_%g' 0 $((count - 1)))
  rosrun jetbot_rl jetbot_rl_nodes_bench --nodes "$nodes" --steps "$steps" | field env_steps_per_s
  kill -INT "$launch_pid"
  wait "$launch_pid" 2> /dev/null || true
  launch_pid=""
}

one=$(run 1)
several=$(run "$k")
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "| N | nodes x threads | env steps/s |"
echo "|---|---|---|"
printf '| %d | 1 x %d | %.0f |\n' "$n" "$t" "$one"
printf '| %d | %d x %d | %.0f |\n' "$n" "$k" "$((t / k > 0 ? t / k : 1))" "$several"
echo "ratio_several_over_one=$(awk "BEGIN { printf \"%.3f\", $several / $one }")"
