#!/usr/bin/env bash
# Runs the whole `npm test` N times in a row (default 5) while two CPU-bound processes keep both cores busy, to show
# that no test depends on how fast the machine runs. Prints each run's result and time, keeps each run's log, stops
# the load on exit (also on Ctrl-C or a failure), and exits non-zero if any run failed.
#
#   bash scripts/flake-check.sh [N]        logs in artifacts/flake-check/run-K.log
#   FLAKE_LOAD=0 bash scripts/flake-check.sh 1   without the extra load
set -uo pipefail
cd "$(dirname "$0")/.."

runs="${1:-5}"
if ! [[ "$runs" =~ ^[1-9][0-9]*$ ]]; then
  echo "usage: bash scripts/flake-check.sh [N]   (N: how many runs of npm test, a whole number >= 1; got '$runs')" >&2
  exit 2
fi
load="${FLAKE_LOAD:-2}"
logs=artifacts/flake-check
mkdir -p "$logs"

pids=()
test_group=''
cleanup() {
  # A run cut short (Ctrl-C): its whole process group (npm, the test runners, chromium) goes too.
  if [[ -n $test_group ]]; then kill -- "-$test_group" 2>/dev/null; fi
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null; done
  for pid in "${pids[@]}"; do wait "$pid" 2>/dev/null; done
  pids=()
}
trap cleanup EXIT
trap 'exit 130' INT TERM

# The load: one busy process per core (`yes` writes as fast as it can into /dev/null).
for ((k = 0; k < load; k++)); do
  yes > /dev/null &
  pids+=("$!")
done
echo "flake check: npm test x $runs, with $load CPU-bound processes running (pids ${pids[*]:-none}), $(nproc) cores"

failed=0
total_start=$SECONDS
for ((run = 1; run <= runs; run++)); do
  log="$logs/run-$run.log"
  start=$SECONDS
  # In its own process group, in the background: `wait` returns at once on a signal (a foreground run would delay
  # the traps until it ended).
  setsid npm test > "$log" 2>&1 &
  test_group=$!
  wait "$test_group"
  status=$?
  test_group=''
  if [[ $status -eq 0 ]]; then
    result=passed
  else
    result=FAILED
    failed=$((failed + 1))
  fi
  echo "run $run/$runs: $result in $((SECONDS - start)) s (log: $log)"
  if [[ $result == FAILED ]]; then
    # What failed, from the test runners' summaries.
    grep -E '❌|failing|failed|Error:|AssertionError' "$log" | head -n 20 | sed 's/^/    /'
  fi
done

echo "flake check: $((runs - failed)) of $runs runs passed in $((SECONDS - total_start)) s"
[[ $failed -eq 0 ]]
