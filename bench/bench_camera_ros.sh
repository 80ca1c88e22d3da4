#!/usr/bin/env bash
# What carrying camera images costs a learner (docs/camera.md): lockstep env steps/s of the camera
# Jetbot (bench/camera_64.yaml: 64 x 64 RGB + depth at every control step) through the C++ client
# over TCP (jetbot_rl_ros_bench), the Python client (python_bench.py --observation dict) and the
# env and the bench as nodelets of one manager (messages by shared pointer), each with the images
# in EnvStep and without (camera/batch_images false: the same rendering, no images carried); the
# ratio is what the transport of the images costs. Needs a built workspace:
#   source ~/jetbot_rl_ws/devel/setup.bash && rosrun jetbot_rl bench_camera_ros.sh [N ...]
# Uses its own ROS master on port $JETBOT_RL_BENCH_PORT (default 11398).
set -euo pipefail

sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(1 16 64 256)
# shellcheck source=bench_common.sh
source "$(dirname "${BASH_SOURCE[0]}")/bench_common.sh" "${JETBOT_RL_BENCH_PORT:-11398}"
share=$(rospack find jetbot_rl)
urdf=$share/urdf/jetbot_camera.urdf
with=$share/bench/camera_64.yaml
[ -f "$with" ] || with=$(dirname "${BASH_SOURCE[0]}")/camera_64.yaml
without=$bench_dir/camera_64_unbatched.yaml
{ cat "$with"; echo "  batch_images: false"; } > "$without"

steps_for() {  # about a second or more of work at each size
  case "$1" in 1) echo 2000 ;; 16) echo 600 ;; 64) echo 200 ;; *) echo 60 ;; esac
}
# measure CONFIG N STEPS: "tcp python inproc" env steps/s
measure() {
  local config=$1 n=$2 steps=$3 tcp py inproc observation=dict
  grep -q 'batch_images: false' "$config" && observation=vector
  roslaunch jetbot_rl jetbot_env.launch num_envs:="$n" num_threads:=2 publish_clock:=false \
    tf_envs:=0 robot_view_envs:=0 urdf:="$urdf" robot_config:="$config" output:=log \
    > "$bench_dir/env.log" 2>&1 &
  launch_pid=$!
  tcp=$(rosrun jetbot_rl jetbot_rl_ros_bench --num-envs "$n" --steps "$steps" | grep '^topic' | field control_steps_per_s)
  py=$(rosrun jetbot_rl python_bench.py --num-envs "$n" --steps "$steps" --observation "$observation" | field env_steps_per_s)
  stop_launch
  roslaunch jetbot_rl bench_nodelets.launch num_envs:="$n" num_threads:=2 steps:="$steps" \
    urdf:="$urdf" robot_config:="$config" > "$bench_dir/inproc.log" 2>&1 &
  launch_pid=$!
  wait_for_figures "$bench_dir/inproc.log"
  stop_launch
  inproc=$(grep '^topic' "$bench_dir/inproc.log" | field control_steps_per_s)
  echo "$(awk "BEGIN { print $tcp * $n }") $py $(awk "BEGIN { print $inproc * $n }")"
}

rows=()
for n in "${sizes[@]}"; do
  steps=$(steps_for "$n")
  read -r tcp py inproc <<< "$(measure "$with" "$n" "$steps")"
  read -r tcp0 py0 inproc0 <<< "$(measure "$without" "$n" "$steps")"
  mb=$(awk "BEGIN { printf \"%.2f\", $n * 64 * 64 * 7 / 1e6 }")
  rows+=("$(printf '| %5s | %5s | %9.0f | %9.0f | %4.2f | %9.0f | %9.0f | %4.2f | %9.0f | %9.0f | %4.2f |' \
    "$n" "$mb" "$tcp" "$tcp0" "$(awk "BEGIN { print $tcp / $tcp0 }")" "$py" "$py0" \
    "$(awk "BEGIN { print $py / $py0 }")" "$inproc" "$inproc0" "$(awk "BEGIN { print $inproc / $inproc0 }")")")
  echo "N = $n: C++ over TCP $tcp vs $tcp0, Python $py vs $py0, in-process $inproc vs $inproc0 env steps/s" >&2
done

echo
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "| N | images MB/step | C++ TCP, images | C++ TCP, none | ratio | Python, images | Python, none | ratio | nodelets, images | nodelets, none | ratio |"
echo "|---|---|---|---|---|---|---|---|---|---|---|"
printf '%s\n' "${rows[@]}"
