#!/usr/bin/env bash
# Runs every test of the package in a built catkin workspace (bash scripts/run_tests.sh WS) in
# four lanes at once, then the rest alone:
# - the foreground: every test no list names, one after another at normal priority;
# - the driving lane: those test/driving_lane.txt names (realtime closed loops that drive a robot
#   through the deploy node), one after another at normal priority;
# - two background lanes at nice 10, which take those test/background_lane.txt names from one
#   queue in its order (each the next when it is free: the list puts the longest first), as do
#   the two lanes above (at nice 10 too) once their own are done;
# - then those test/alone.txt names, by themselves.
# The tests that time what they measure (realtime nodes, signals) keep the CPU they need; the
# background lanes use what the others leave idle (a rostest waits much of its time: for its nodes
# to start, for realtime to pass).
# Results: WS/build/test_results (catkin's JUnit XML); a lane never stops at a failed test. Each
# test's line `== NAME: N s (CPU M s)` gives its wall time and the CPU its processes used.
set -euo pipefail

# One test (called by the lanes below): its lines prefixed, then its wall and CPU time.
run_one() {
  local prefix=$1 build=$2 target=$3 started=$SECONDS cpu_file user system
  cpu_file=$(mktemp)
  echo "$prefix== ${target#run_tests_jetbot_rl_}"
  # /fast: the test alone, without make checking (in every lane at once) what it depends on.
  /usr/bin/time -f "%U %S" -o "$cpu_file" \
    make --no-print-directory -C "$build" "$target/fast" 2>&1 | sed -u "s/^/$prefix/"
  # The last line: time writes "Command exited with non-zero status N" before it when make fails.
  read -r user system < <(tail -n 1 "$cpu_file")
  rm -f "$cpu_file"
  echo "$prefix== ${target#run_tests_jetbot_rl_}: $((SECONDS - started)) s" \
    "(CPU $(awk "BEGIN { print $user + $system }") s)"
}

# A lane (called by this script): its targets one after another.
if [ "${1:-}" = --lane ]; then
  prefix=$2 build=$3
  shift 3
  for target in "$@"; do run_one "$prefix" "$build" "$target"; done
  exit 0
fi

# A lane that takes its targets from a queue file, the first line first, until it is empty.
if [ "${1:-}" = --queue ]; then
  prefix=$2 build=$3 queue=$4
  while target=$(flock "$queue" sh -c 'head -n 1 "$1" && sed -i 1d "$1"' sh "$queue") &&
    [ -n "$target" ]; do
    run_one "$prefix" "$build" "$target"
  done
  exit 0
fi

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
ws=${1:?usage: bash scripts/run_tests.sh WORKSPACE}
build="$ws/build"

mapfile -t targets < <(make -C "$build" help |
  sed -n 's/^\.\.\. \(run_tests_jetbot_rl_\(gtest\|rostest\)_.\+\)$/\1/p' | sort)
[ ${#targets[@]} -gt 0 ] || { echo "no test targets in $build: build the tests first" >&2; exit 1; }

# A list's entries as catkin's target names: test/ppo/train.test -> ..._rostest_test_ppo_train.test
declare -A lane=() known=()
for target in "${targets[@]}"; do known[$target]=1; done
read_list() {
  local list=$1 name=$2 entry target
  while read -r entry; do
    entry=${entry%%#*}
    entry=${entry//[[:space:]]/}
    [ -n "$entry" ] || continue
    if [[ $entry == *.test ]]; then
      target=run_tests_jetbot_rl_rostest_${entry//\//_}
    else
      target=run_tests_jetbot_rl_gtest_$entry
    fi
    [ -n "${known[$target]:-}" ] ||
      { echo "$list: '$entry' is no test of the package" >&2; exit 1; }
    lane[$target]=$name
    [ "$name" != background ] || background_targets+=("$target")
  done < "$repo/$list"
}
background_targets=()  # in the list's order
read_list test/background_lane.txt background
read_list test/driving_lane.txt driving
read_list test/alone.txt alone

foreground_targets=() driving_targets=() alone_targets=()
for target in "${targets[@]}"; do
  case ${lane[$target]:-} in
    background) ;;
    driving) driving_targets+=("$target") ;;
    alone) alone_targets+=("$target") ;;
    *) foreground_targets+=("$target") ;;
  esac
done
echo "== running ${#targets[@]} test files: ${#foreground_targets[@]} in the foreground," \
  "${#driving_targets[@]} in the driving lane, ${#background_targets[@]} in two background" \
  "lanes, then ${#alone_targets[@]} alone"

queue=$(mktemp)
trap 'rm -f "$queue"' EXIT
printf '%s\n' "${background_targets[@]}" > "$queue"
# nice 10, not the idle class: a background trainer starved for longer than its step_timeout
# (10 s) while the foreground trains on both cores would give up.
nice -n 10 bash "${BASH_SOURCE[0]}" --queue "[bg] " "$build" "$queue" &
background_a=$!
nice -n 10 bash "${BASH_SOURCE[0]}" --queue "[bg2] " "$build" "$queue" &
background_b=$!
# The driving lane; its own done, it helps empty the queue (at nice 10: a realtime test may still
# run in the foreground).
{
  bash "${BASH_SOURCE[0]}" --lane "[drive] " "$build" "${driving_targets[@]}"
  nice -n 10 bash "${BASH_SOURCE[0]}" --queue "[drive] " "$build" "$queue"
} &
driving=$!
bash "${BASH_SOURCE[0]}" --lane "" "$build" "${foreground_targets[@]}"
# Its own done, the foreground helps empty the queue (as the driving lane, at nice 10).
nice -n 10 bash "${BASH_SOURCE[0]}" --queue "[fg] " "$build" "$queue"
wait "$background_a" "$background_b" "$driving"
# Those that load both cores and measure a rate, with nothing beside them.
bash "${BASH_SOURCE[0]}" --lane "" "$build" "${alone_targets[@]}"
