#!/usr/bin/env bash
# Times CI as a fresh clone meets it: clones HEAD (committed work only) into
# a new directory, runs .ci/run there with no build tree and an empty ccache,
# and prints the table that docs/reliability.md#ci keeps for today's HEAD.
#   tools/ci-times.sh [DIR]   clone into DIR (default: a new one under /tmp);
#                             DIR/ci.log keeps .ci/run's whole output
# Extra environment (MARCH_CI_SANITIZE=0, ...) passes through to .ci/run.
set -euo pipefail
src=$(git -C "$(dirname "$0")" rev-parse --show-toplevel)
dir=${1:-$(mktemp -d /tmp/ci-times.XXXXXX)}
commit=$(git -C "$src" rev-parse --short HEAD)
git clone -q --no-hardlinks "$src" "$dir"
git -C "$dir" checkout -q "$commit"
cd "$dir"
load_before=$(cut -d' ' -f1-3 /proc/loadavg)
# The caller's cache would make a fresh clone look warm: .ci/run picks its own.
status=0
env -u CCACHE_DIR -u CCACHE_BASEDIR CI=true bash .ci/run >ci.log 2>&1 || status=$?
load_after=$(cut -d' ' -f1-3 /proc/loadavg)
steps=$(grep -oE '^\[[0-9]+/[0-9]+\] (Building|Linking)' ci.log | head -1 | sed -E 's/^.[0-9]+.([0-9]+).*/\1/' || true)
tests=$(grep -oE 'tests failed out of [0-9]+' ci.log | head -1 | grep -oE '[0-9]+$' || true)
echo "Fresh clone of $commit on $(date -u +%F), $(nproc) cores, load average $load_before before and"
echo "$load_after after; .ci/run exit $status; $steps build steps, $tests tests (log: $dir/ci.log)"
echo
echo "| stage | wall time | ends at |"
echo "|---|---|---|"
sed -nE 's/^ci: (.*) took ([0-9]+) s, done at ([0-9]+) s$/| \1 | \2 s | \3 s |/p' ci.log
total=$(sed -nE 's/^ci: .* done at ([0-9]+) s$/\1/p' ci.log | tail -1)
[ -n "$total" ] && echo "| all | $total s ($(( total / 60 )) min $(( total % 60 )) s) | |"
echo
sed -n '/^ci: slowest tests$/,/^ci: /p' ci.log | sed '1d;$d'
exit "$status"
