#!/usr/bin/env bash
# The world and the laser scanner's cost (docs/performance.md): jetbot_rl_bench env steps/s per
# thread for an empty world, random obstacles (a 4 x 4 m arena, 3 boxes, 2 cylinders), the same
# with 10 walking people (world_people.yaml), the office
# map, clutter (a 10 x 10 m arena, 200 obstacles) and a Gazebo world of 500 cylinder models
# (world_gazebo.yaml), each with no scanner, 24 beams every step,
# 360 beams every 6th step and 360 beams every step, as a markdown table with each row's ratio to
# the empty world without a scanner; then the memory per env.
# Needs no ROS at run time (jetbot_rl_bench from the workspace, or $JETBOT_RL_BENCH):
#   rosrun jetbot_rl bench_world.sh [N] [STEPS] [THREADS ...]     # defaults 256, 300, 1
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# Installed, the inputs lie in the package's share folder, not beside this script.
[ -f "$here/world_map.yaml" ] || here="$(rospack find jetbot_rl)/bench"
bench=${JETBOT_RL_BENCH:-$(command -v jetbot_rl_bench || echo "rosrun jetbot_rl jetbot_rl_bench")}
n=${1:-256}
steps=${2:-300}
shift $(( $# > 2 ? 2 : $# ))
threads=("$@")
[ ${#threads[@]} -gt 0 ] || threads=(1)

field() { grep -o "$1=[0-9.]*" | tail -1 | cut -d= -f2; }
run() {  # THREADS WORLD SCAN [N]: env steps/s (or rss_kib with N)
  local args=(--num-envs "${4:-$n}" --steps "$steps" --threads "$1")
  [ "$2" = none ] || args+=(--config "$here/world_$2.yaml")
  [ "$3" = none ] || args+=(--config "$here/scan_$3.yaml")
  $bench "${args[@]}"
}

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "| threads | world | scanner | env steps/s | per thread | / empty, no scanner |"
echo "|---|---|---|---|---|---|"
for t in "${threads[@]}"; do
  base=""
  for world in none obstacles people map clutter gazebo; do
    for scan in none 24 360 360_every_step; do
      rate=$(run "$t" "$world" "$scan" | field env_steps_per_s)
      [ -n "$base" ] || base=$rate
      label=$scan
      case "$scan" in
        none) label="none" ;; 24) label="24 beams every step" ;;
        360) label="360 beams every 6th step" ;; 360_every_step) label="360 beams every step" ;;
      esac
      printf '| %d | %s | %s | %.0f | %.0f | %.2f |\n' "$t" "$world" "$label" "$rate" \
        "$(awk "BEGIN { print $rate / $t }")" "$(awk "BEGIN { print $rate / $base }")"
    done
  done
done
echo
for world in none obstacles people map clutter gazebo; do
  small=$(steps=20 run 2 "$world" 24 1000 | field rss_kib)
  large=$(steps=20 run 2 "$world" 24 10000 | field rss_kib)
  [ "$world" != gazebo ] || echo "start-up, world gazebo: $( { /usr/bin/time -f %e $bench --num-envs 1 --steps 1 --config "$here/world_gazebo.yaml" >/dev/null; } 2>&1 | tail -1) s (1 env, 1 step)"
  echo "memory, world $world, 24 beams: $(awk "BEGIN { printf \"%.1f\", ($large - $small) / 9000 }") KiB per env (resident set growth from 1,000 to 10,000 envs)"
done
