# Sourced by the bench scripts: a ROS master of their own on port $1, removed on exit with any
# launch started in the background ($launch_pid); a scratch folder $bench_dir; field NAME reads
# NAME=<number> (the last one) from standard input.
port=$1
export ROS_MASTER_URI=http://localhost:$port
bench_dir=$(mktemp -d)
roscore -p "$port" > "$bench_dir/roscore.log" 2>&1 &
roscore_pid=$!
launch_pid=""
cleanup() {
  [ -z "$launch_pid" ] || kill -INT "$launch_pid" 2> /dev/null || true
  kill -INT "$roscore_pid" 2> /dev/null || true
  wait 2> /dev/null || true
  rm -rf "$bench_dir"
}
trap cleanup EXIT
until rostopic list > /dev/null 2>&1; do sleep 0.2; done  # the master answers (no event to wait on)
field() { grep -o "$1=[0-9.]*" | tail -n 1 | cut -d= -f2; }
# stop_launch: ends the background launch and waits for it.
stop_launch() {
  kill -INT "$launch_pid"
  wait "$launch_pid" 2> /dev/null || true
  launch_pid=""
}
# wait_for_figures LOG: until the background launch's LOG holds the bench's last line
# (env_steps_per_s); fails when the launch ended first.
wait_for_figures() {
  until grep -q env_steps_per_s "$1"; do
    kill -0 "$launch_pid" 2> /dev/null || { echo "$1: the launch ended early" >&2; exit 1; }
    sleep 0.2
  done
}
