#!/usr/bin/env bash
# The cost of several robots per env (docs/performance.md): jetbot_rl_bench env steps/s per
# thread of ROWS robots as ROWS / 20 envs of 20 robots (world_team.yaml) against ROWS envs of one
# robot in the same arena (world_team_solo.yaml), without a scanner and with 24 beams every
# step, alternating RUNS times; the ratio team / solo (the issue's target: >= 0.9).
# Needs no ROS at run time (jetbot_rl_bench from the workspace, or $JETBOT_RL_BENCH):
#   rosrun jetbot_rl bench_team.sh [ROWS] [STEPS] [RUNS] [THREADS]     # defaults 200, 300, 3, 1
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
[ -f "$here/world_team.yaml" ] || here="$(rospack find jetbot_rl)/bench"
bench=${JETBOT_RL_BENCH:-$(command -v jetbot_rl_bench || echo "rosrun jetbot_rl jetbot_rl_bench")}
rows=${1:-200}
steps=${2:-300}
runs=${3:-3}
threads=${4:-1}
k=20
[ $((rows % k)) -eq 0 ] || { echo "ROWS must be a multiple of $k" >&2; exit 2; }

field() { grep -o "$1=[0-9.]*" | tail -1 | cut -d= -f2; }
run() {  # WORLD ENVS SCAN: env steps/s
  local args=(--num-envs "$2" --steps "$steps" --threads "$threads" --config "$here/world_$1.yaml")
  [ "$3" = none ] || args+=(--config "$here/scan_$3.yaml")
  $bench "${args[@]}" | field env_steps_per_s
}

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "$rows rows, $steps steps, $threads thread(s)"
echo "| scanner | run | $((rows / k)) envs x $k robots: env steps/s | $rows envs x 1 robot | team / solo |"
echo "|---|---|---|---|---|"
for scan in none 24; do
  for r in $(seq "$runs"); do
    team=$(run team $((rows / k)) "$scan")
    solo=$(run team_solo "$rows" "$scan")
    printf '| %s | %d | %.0f | %.0f | %.2f |\n' "$scan" "$r" "$team" "$solo" \
      "$(awk "BEGIN { print $team / $solo }")"
  done
done
