#!/usr/bin/env bash
# Runs every test of the package in a built catkin workspace (bash scripts/run_tests.sh WS), in
# two lanes at once: the tests test/background_lane.txt names, one after another at nice 10, and
# every other test, one after another at normal priority; then those test/alone.txt names, by
# themselves. The tests that time what they measure (realtime nodes, signals) run in the
# foreground and keep the CPU they need; the background uses what the foreground leaves idle.
# Results: WS/build/test_results (catkin's JUnit XML); a lane never stops at a failed test.
set -euo pipefail

# One lane (called by this script): its targets one after another, each line prefixed.
if [ "${1:-}" = --lane ]; then
  prefix=$2 build=$3
  shift 3
  for target in "$@"; do
    started=$SECONDS
    echo "$prefix== ${target#run_tests_jetbot_rl_}"
    # /fast: the test alone, without make checking (in both lanes at once) what it depends on.
    make --no-print-directory -C "$build" "$target/fast" 2>&1 | sed -u "s/^/$prefix/"
    echo "$prefix== ${target#run_tests_jetbot_rl_}: $((SECONDS - started)) s"
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
  done < "$repo/$list"
}
read_list test/background_lane.txt background
read_list test/alone.txt alone

foreground_targets=() background_targets=() alone_targets=()
for target in "${targets[@]}"; do
  case ${lane[$target]:-} in
    background) background_targets+=("$target") ;;
    alone) alone_targets+=("$target") ;;
    *) foreground_targets+=("$target") ;;
  esac
done
echo "== running ${#targets[@]} test files: ${#foreground_targets[@]} in the foreground," \
  "${#background_targets[@]} in the background, then ${#alone_targets[@]} alone"

# nice 10, not the idle class: a background trainer starved for longer than its step_timeout
# (10 s) while the foreground trains on both cores would give up.
nice -n 10 bash "${BASH_SOURCE[0]}" --lane "[bg] " "$build" "${background_targets[@]}" &
background_pid=$!
bash "${BASH_SOURCE[0]}" --lane "" "$build" "${foreground_targets[@]}"
wait "$background_pid"
# Those that load both cores and measure a rate, with nothing beside them.
bash "${BASH_SOURCE[0]}" --lane "" "$build" "${alone_targets[@]}"
