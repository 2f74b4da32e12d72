#!/usr/bin/env bash
# Issue 26's check that the suite does not depend on an idle machine: N clean clones of this repository's HEAD
# (default 3), each running `CI=true bash .ci/run` with H busy-looping CPU hogs beside it (default 2), as a
# contributor's laptop or a shared CI runner does other work. Prints each run's result, time and load average (at
# its start and end), the test counts and durations vitest printed, the engines' table, then a summary; exits 1
# unless every run passed. The hogs are ended by their own PIDs when each run ends, and the run itself (its own
# process group) if the script is stopped. Uncommitted changes are not in a clone: commit first.
#   scripts/ci-under-load.sh [-n RUNS] [--hogs H] [--keep] [--only lint]
#     --only lint   a quick pass that proves the script: `npm ci` and `npm run lint` instead of .ci/run
#     --keep        keep the clones (default: each is removed after its run; its log is always kept)
set -u
runs=3
hogs=2
only=''
keep=0
while [ $# -gt 0 ]; do
  case "$1" in
    -n) runs=$2; shift 2 ;;
    --hogs) hogs=$2; shift 2 ;;
    --only) only=$2; shift 2 ;;
    --keep) keep=1; shift ;;
    *) echo "usage: scripts/ci-under-load.sh [-n RUNS] [--hogs H] [--keep] [--only lint]"; exit 2 ;;
  esac
done
case "$only" in
  '') steps='CI=true bash .ci/run' ;;
  lint) steps='npm ci --no-audit --no-fund && npm run lint' ;;
  *) echo "ci-under-load: --only takes 'lint'"; exit 2 ;;
esac

root=$(git -C "$(dirname "$0")/.." rev-parse --show-toplevel) || exit 2
commit=$(git -C "$root" rev-parse HEAD) || exit 2
work=$(mktemp -d "${TMPDIR:-/tmp}/ci-under-load.XXXXXX")
pids=()
step=''
stop_hogs() {
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null; done
  pids=()
}
stop_step() { [ -n "$step" ] && kill -- "-$step" 2>/dev/null; step=''; }
trap 'stop_step; stop_hogs; exit 130' INT TERM
trap stop_hogs EXIT

echo "ci-under-load: $runs run(s) of '$steps' on $(git -C "$root" log -1 --format='%h %s' | cut -c1-70)"
echo "ci-under-load: $hogs CPU hog(s) beside each, on $(nproc) core(s); logs in $work"
passed=0
results=()
for i in $(seq 1 "$runs"); do
  dir="$work/run-$i"
  log="$work/run-$i.log"
  git clone --quiet --no-hardlinks "$root" "$dir" && git -C "$dir" checkout --quiet "$commit" || exit 2
  for _ in $(seq 1 "$hogs"); do ( while :; do :; done ) & pids+=($!); done
  load=$(cut -d' ' -f1-3 /proc/loadavg)
  start=$(date +%s)
  # in a process group of its own (setsid), so that stopping this script stops the whole run
  (cd "$dir" && exec setsid -w bash -c "$steps") >"$log" 2>&1 &
  step=$!
  wait "$step"
  rc=$?
  step=''
  took=$(( $(date +%s) - start ))
  load_end=$(cut -d' ' -f1-3 /proc/loadavg)
  stop_hogs
  verdict=FAIL
  [ $rc -eq 0 ] && { verdict=pass; passed=$((passed + 1)); }
  line=$(printf 'run %d: %s in %d min %02d s (exit %d, load average %s at the start, %s at the end)' \
    "$i" "$verdict" $((took / 60)) $((took % 60)) "$rc" "$load" "$load_end")
  results+=("$line")
  echo "$line"
  # the figures: vitest's counts and durations (unit and browser projects together) and the engines' table
  sed 's/\x1b\[[0-9;]*m//g' "$log" | grep -aE '^ *(Test Files|Tests|Duration) ' | sed 's/^ */    /'
  sed 's/\x1b\[[0-9;]*m//g' "$log" | grep -aE '^(engine|chromium|firefox|webkit) ' | sed 's/^/    /'
  # the failed tests by name (vitest's FAIL lines), so the summary says what to look at
  [ $rc -ne 0 ] && sed 's/\x1b\[[0-9;]*m//g' "$log" | grep -aE '^ *(FAIL|×)' | sort -u | head -20 | sed 's/^/    /'
  [ $keep -eq 1 ] || rm -rf "$dir"
done
echo "ci-under-load: $passed of $runs run(s) passed with $hogs CPU hog(s) beside them"
printf '  %s\n' "${results[@]}"
[ "$passed" -eq "$runs" ]
