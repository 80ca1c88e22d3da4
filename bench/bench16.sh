#!/usr/bin/env bash
# Threads against processes, small against large batches: the core (jetbot_rl_bench) and, when
# built, MuJoCo (mujoco_bench, the same robot and loop) in one run, as a markdown table
# (docs/performance.md). Needs no ROS at run time:
#   bash bench/bench16.sh [K] [N] [STEPS] [REPEATS]
# K threads (default: all cores) in one process with N envs (default 512 K) against K single-thread
# processes of N/K envs each, started together (their figures are summed); and one thread with
# N/K envs against one with $LARGE (default 4096). Every run steps STEPS control steps (default 120) after
# STEPS/10 of warm-up; each case runs REPEATS times (default 3), alternating, and the median is
# shown. Programs: $JETBOT_RL_BENCH (default: jetbot_rl_bench on the PATH, else from catkin_find),
# $MUJOCO_BENCH (default: mujoco_bench likewise; the MuJoCo column is left out without it),
# $JETBOT_RL_BENCH_BEFORE (optional: another build of jetbot_rl_bench, e.g. of an earlier commit,
# measured in the same rounds for a "before" column; a build older than --num-envs gets --envs), $JETBOT_RL_URDF (default urdf/jetbot.urdf beside this script), $MUJOCO_MODEL (default
# bench/jetbot_mujoco.xml beside it).
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
k=${1:-$(nproc)}
n=${2:-$((512 * k))}
steps=${3:-120}
repeats=${4:-3}
large=${LARGE:-4096}
[ $((n % k)) -eq 0 ] || { echo "bench16.sh: N = $n is not a multiple of K = $k" >&2; exit 2; }
per=$((n / k))

find_program() {  # name, variable value
  if [ -n "$2" ]; then echo "$2"; return; fi
  command -v "$1" 2> /dev/null && return
  command -v catkin_find > /dev/null 2>&1 && catkin_find --first-only jetbot_rl "$1" 2> /dev/null && return
  true
}
ours=$(find_program jetbot_rl_bench "${JETBOT_RL_BENCH:-}")
theirs=$(find_program mujoco_bench "${MUJOCO_BENCH:-}")
before=${JETBOT_RL_BENCH_BEFORE:-}
[ -n "$ours" ] || { echo "bench16.sh: jetbot_rl_bench not found (set JETBOT_RL_BENCH)" >&2; exit 2; }
urdf=${JETBOT_RL_URDF:-$root/urdf/jetbot.urdf}
mjcf=${MUJOCO_MODEL:-$root/bench/jetbot_mujoco.xml}

# The before build's option for the batch size: --num-envs, or --envs when it predates the rename.
before_envs=--num-envs
if [ -n "$before" ] && ! "$before" --num-envs 1 --threads 1 --steps 1 --urdf "$urdf" > /dev/null 2>&1; then
  before_envs=--envs
fi

field() { grep -o "$1=[0-9.]*" | tail -n 1 | cut -d= -f2; }
run() {  # program (ours|before|theirs), envs, threads: prints env steps per second
  if [ "$1" = ours ]; then
    "$ours" --num-envs "$2" --threads "$3" --steps "$steps" --urdf "$urdf" | field env_steps_per_s
  elif [ "$1" = before ]; then
    "$before" "$before_envs" "$2" --threads "$3" --steps "$steps" --urdf "$urdf" | field env_steps_per_s
  else
    "$theirs" --num-envs "$2" --threads "$3" --steps "$steps" --model "$mjcf" | field env_steps_per_s
  fi
}
processes() {  # program: K single-thread processes started together, their figures summed
  local dir pids=() total=0 i
  dir=$(mktemp -d)
  for ((i = 0; i < k; ++i)); do
    run "$1" "$per" 1 > "$dir/$i" &
    pids+=($!)
  done
  for i in "${pids[@]}"; do wait "$i"; done
  for ((i = 0; i < k; ++i)); do total=$(awk "BEGIN { print $total + $(cat "$dir/$i") }"); done
  rm -rf "$dir"
  echo "$total"
}
median() { printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
ratio() { if [ -n "$1" ] && [ -n "$2" ]; then awk "BEGIN { printf \"%.2f\", $1 / $2 }"; fi; }
num() { if [ -n "$1" ]; then awk "BEGIN { printf \"%.0f\", $1 }" | sed ':a;s/\B[0-9]\{3\}\>/,&/;ta'; fi; }

programs=(ours)
[ -z "$before" ] || programs+=(before)
[ -z "$theirs" ] || programs+=(theirs)
declare -A samples
for ((r = 0; r < repeats; ++r)); do
  for p in "${programs[@]}"; do
    samples[$p,small]+=" $(run "$p" "$per" 1)"
    samples[$p,large]+=" $(run "$p" "$large" 1)"
    samples[$p,procs]+=" $(processes "$p")"
    samples[$p,threads]+=" $(run "$p" "$n" "$k")"
    echo "round $((r + 1)) $p: small${samples[$p,small]} | large${samples[$p,large]} |" \
      "processes${samples[$p,procs]} | threads${samples[$p,threads]}" >&2
  done
done
declare -A m
for p in ours before theirs; do
  for c in small large procs threads; do
    # shellcheck disable=SC2086
    m[$p,$c]=$([ -z "${samples[$p,$c]:-}" ] || median ${samples[$p,$c]})
  done
done

echo
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "steps $steps per run, median of $repeats runs; env steps/s"
echo
echo "| case | jetbot_rl_bench | before | MuJoCo | jetbot_rl / MuJoCo |"
echo "|---|---|---|---|---|"
row() {
  echo "| $1 | $(num "${m[ours,$2]}") | $(num "${m[before,$2]}") | $(num "${m[theirs,$2]}") |" \
    "$(ratio "${m[ours,$2]}" "${m[theirs,$2]}") |"
}
per_case() { echo "| $1 | $(ratio "${m[ours,$2]}" "${m[ours,$3]}") | $(ratio "${m[before,$2]}" "${m[before,$3]}") | $(ratio "${m[theirs,$2]}" "${m[theirs,$3]}") | |"; }
row "1 thread, N = $per" small
row "1 thread, N = $large" large
per_case "per thread, N = $large / N = $per" large small
row "$k threads in one process, N = $n" threads
row "$k single-thread processes, $per envs each" procs
per_case "$k threads / $k processes" threads procs
