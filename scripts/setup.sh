#!/usr/bin/env bash
# One-command set-up for a fresh Debian 12 machine (idempotent):
#   bash scripts/setup.sh main   install Debian packages, build, train a Jetbot (100 envs) and plot it
#   bash scripts/setup.sh test   install Debian packages, build, run every test (non-zero on failure)
# The catkin workspace lives outside the source tree: $JETBOT_RL_WS, default ~/jetbot_rl_ws.
set -euo pipefail

mode=${1:-main}
case "$mode" in main | test) ;; *) echo "usage: bash scripts/setup.sh main|test" >&2; exit 2 ;; esac

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
ws=${JETBOT_RL_WS:-$HOME/jetbot_rl_ws}
jobs=${JETBOT_RL_JOBS:-$(nproc)}

install_packages() {
  local missing=()
  while read -r pkg; do
    [ -n "$pkg" ] || continue
    dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed" || missing+=("$pkg")
  done < "$repo/scripts/debian-packages.txt"
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "== installing Debian packages: ${missing[*]}"
  local sudo=""
  [ "$(id -u)" -eq 0 ] || sudo=sudo
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

# build [TARGET...]: the package (make's default target) or the targets given.
build() {
  echo "== building in $ws"
  mkdir -p "$ws/src"
  ln -sfn "$repo" "$ws/src/jetbot_rl"
  # catkin caches the tests' environment when it configures; the generated Python messages'
  # folder must exist by then, or rostests of a fresh workspace cannot import jetbot_rl.msg.
  mkdir -p "$ws/devel/lib/python3/dist-packages"
  cd "$ws"
  # ROS's Python tools need Debian's interpreter, not a pyenv python3 on the PATH.
  local start=$SECONDS
  catkin_make -j"$jobs" -DPYTHON_EXECUTABLE=/usr/bin/python3 -DCMAKE_BUILD_TYPE=Release "$@"
  echo "== built in $((SECONDS - start)) s"
  set +u
  # shellcheck disable=SC1091
  source "$ws/devel/setup.bash"
  set -u
}

run_tests() {
  cd "$ws"
  rm -rf "$ws/build/test_results"
  # Four lanes (run_tests.sh): the tests that time what they measure in the foreground and the
  # driving lane, the rest beside them in two lanes at nice 10; then the rate comparisons alone.
  local start=$SECONDS
  bash "$repo/scripts/run_tests.sh" "$ws"
  echo "== tests ran in $((SECONDS - start)) s"
  local status=0
  catkin_test_results --verbose "$ws/build/test_results" || status=$?
  /usr/bin/python3 "$repo/scripts/summarize_test_results.py" "$ws/build/test_results" || status=1
  exit "$status"
}

install_packages
if [ "$mode" = test ]; then
  build all tests  # the package and its test programs, in one make on every core
  run_tests
else
  build
  # The main job: PPO learns to drive with 100 envs; the run directory gets progress.csv,
  # checkpoints and learning_curve.png. roslaunch starts a ROS master when none runs.
  run_dir="$HOME/.ros/jetbot_rl/main_$(date +%Y%m%d_%H%M%S)"
  roslaunch jetbot_rl train.launch run_dir:="$run_dir"
  rosrun jetbot_rl plot_learning_curve.py "$run_dir"
fi
