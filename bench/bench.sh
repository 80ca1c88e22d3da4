#!/usr/bin/env bash
# Runs the core benchmark (jetbot_rl_bench) and the end-to-end lockstep benchmark
# (jetbot_rl_ros_bench against a jetbot_env node) for N = 1, 100, 1024, 10000 and 1 and 2 threads,
# and the memory per env at N = 10,000; prints a table. Against the same node, right after the C++
# client, python_bench.py measures the Python client (JetbotVecEnv): a second table. Needs a built
# workspace:
#   source ~/jetbot_rl_ws/devel/setup.bash && rosrun jetbot_rl bench.sh [N ...]
# The env node runs as for training (no /clock, no tf). A third table: the env and the bench as
# nodelets of one manager (messages by shared pointer). Uses its own ROS master on port
# $JETBOT_RL_BENCH_PORT (default 11399).
set -euo pipefail

sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(1 100 1024 10000)
# shellcheck source=bench_common.sh
source "$(dirname "${BASH_SOURCE[0]}")/bench_common.sh" "${JETBOT_RL_BENCH_PORT:-11399}"

steps_for() {  # enough steps for about a second of work at each size
  case "$1" in 1) echo 20000 ;; 100) echo 3000 ;; 1024) echo 400 ;; *) echo 40 ;; esac
}
rows=()
py_rows=()
inproc_rows=()
for n in "${sizes[@]}"; do
  steps=$(steps_for "$n")
  for t in 1 2; do
    core=$(rosrun jetbot_rl jetbot_rl_bench --num-envs "$n" --steps "$steps" --threads "$t" | field env_steps_per_s)
    roslaunch jetbot_rl jetbot_env.launch num_envs:="$n" num_threads:="$t" publish_clock:=false \
      tf_envs:=0 robot_view_envs:=0 output:=log > "$bench_dir/env.log" 2>&1 &
    launch_pid=$!
    out=$(rosrun jetbot_rl jetbot_rl_ros_bench --num-envs "$n" --steps "$steps")
    py_out=$(rosrun jetbot_rl python_bench.py --num-envs "$n" --steps "$steps")
    stop_launch
    # In one process: the env and the bench as nodelets of one manager (bench_nodelets.launch).
    roslaunch jetbot_rl bench_nodelets.launch num_envs:="$n" num_threads:="$t" steps:="$steps" \
      > "$bench_dir/inproc.log" 2>&1 &
    launch_pid=$!
    wait_for_figures "$bench_dir/inproc.log"
    stop_launch
    inproc_out=$(cat "$bench_dir/inproc.log")
    e2e=$(echo "$out" | field env_steps_per_s)
    same_run_core=$(echo "$out" | field core_env_steps_per_s)
    p50=$(echo "$out" | grep '^topic' | field p50)
    p50_srv=$(echo "$out" | grep '^service' | field p50)
    rows+=("$(printf '| %6s | %d | %10.0f | %10.0f | %10.0f | %5.2f | %8.1f | %8.1f |' "$n" "$t" \
      "$core" "$e2e" "$same_run_core" "$(awk "BEGIN { print $e2e / $same_run_core }")" "$p50" "$p50_srv")")
    py=$(echo "$py_out" | field env_steps_per_s)
    py_p50=$(echo "$py_out" | grep '^python' | field p50)
    py_rows+=("$(printf '| %6s | %d | %10.0f | %10.0f | %5.2f | %8.1f | %8.1f |' "$n" "$t" \
      "$e2e" "$py" "$(awk "BEGIN { print $py / $e2e }")" "$p50" "$py_p50")")
    inproc=$(echo "$inproc_out" | field env_steps_per_s)
    inproc_p50=$(echo "$inproc_out" | grep '^topic' | field p50)
    inproc_rows+=("$(printf '| %6s | %d | %10.0f | %10.0f | %5.2f | %8.1f | %8.1f |' "$n" "$t" \
      "$e2e" "$inproc" "$(awk "BEGIN { print $inproc / $e2e }")" "$p50" "$inproc_p50")")
    # Progress on stderr; the tables follow on stdout at the end.
    echo "N = $n, $t thread(s): core $core, over TCP $e2e, Python $py, in-process $inproc env steps/s" >&2
  done
done

rss_kib() { rosrun jetbot_rl jetbot_rl_bench --num-envs "$1" --steps 20 --threads 2 | field rss_kib; }
small=$(rss_kib 1000)
large=$(rss_kib 10000)

echo
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "| N | threads | core env steps/s | end-to-end env steps/s | core, same run | e2e/core | topic round trip p50 [us] | ~step p50 [us] |"
echo "|---|---|---|---|---|---|---|---|"
printf '%s\n' "${rows[@]}"
echo
echo "| N | threads | C++ client env steps/s | Python client env steps/s | Python/C++ | C++ round trip p50 [us] | Python round trip p50 [us] |"
echo "|---|---|---|---|---|---|---|"
printf '%s\n' "${py_rows[@]}"
echo
echo "| N | threads | over TCP env steps/s | in-process (nodelets) env steps/s | in-process/TCP | TCP round trip p50 [us] | in-process round trip p50 [us] |"
echo "|---|---|---|---|---|---|---|"
printf '%s\n' "${inproc_rows[@]}"
echo
echo "memory: $(awk "BEGIN { printf \"%.1f\", ($large - $small) / 9000 }") KiB per env (resident set growth from 1,000 to 10,000 envs)"
