#!/usr/bin/env bash
# bench_report.sh: runs every benchmark program and writes their output as one Markdown file
# (docs/benchmarks.md by `make bench`), stamped with the date, the machine and the commit.
# usage: scripts/bench_report.sh BUILD_DIR DATA_ROOT OUT.md
# Each program's output goes under its own heading in a closed code fence, so the file renders
# whatever the programs print; the heading's first line names the commit, date and load it ran
# at. The file is written to a temporary name and moved into place at the end: a second run
# replaces it, a failed run leaves the previous file alone.
# BENCH_ONLY="bench_a bench_b" (`make bench BENCH_ONLY=...`) runs only those programs and keeps the
# other programs' sections of OUT.md as they were (a program without one runs too).
set -euo pipefail
build=${1:?usage: bench_report.sh BUILD_DIR DATA_ROOT OUT.md}
data=${2:?usage: bench_report.sh BUILD_DIR DATA_ROOT OUT.md}
out=${3:?usage: bench_report.sh BUILD_DIR DATA_ROOT OUT.md}
tmp="$out.tmp.$$"
trap 'rm -f "$tmp" "$tmp.run"' EXIT

cores=$(nproc 2>/dev/null || echo "?")
cpu=$(sed -n 's/^model name[[:space:]]*:[[:space:]]*//p' /proc/cpuinfo 2>/dev/null | head -n 1)
mem_kb=$(sed -n 's/^MemTotal:[[:space:]]*\([0-9]*\) kB/\1/p' /proc/meminfo 2>/dev/null)
mem=$([ -n "$mem_kb" ] && echo "$((mem_kb / 1024 / 1024)) GiB" || echo "?")
commit=$(git rev-parse --short=12 HEAD 2>/dev/null || echo "unknown")
git diff --quiet HEAD -- 2>/dev/null || commit="$commit (with uncommitted changes)"
load_start=$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo "?")
started=$(date -u '+%Y-%m-%d %H:%M UTC')
t0=$(date +%s)

# The fence must be longer than any run of backticks in the output it encloses.
fence_for() {
  local longest
  longest=$(grep -o '`\+' "$1" | awk '{ if (length($0) > n) n = length($0) } END { print n + 0 }')
  [ "$longest" -lt 3 ] && longest=3 || longest=$((longest + 1))
  printf '%*s' "$longest" '' | tr ' ' '`'
}

# The previous file's section of a program (from its heading to the next), for BENCH_ONLY.
old_section() {
  [ -f "$out" ] || return 0
  awk -v h="## $1" '$0 == h { on = 1; print; next } on && /^## bench_/ { exit } on { print }' "$out"
}

only=" ${BENCH_ONLY:-} "
# bench_proxies sets V-HACD beside its proxies: its set-up (npm, a compiler) may fail, and the
# bench then says so in its table and measures the rest
if [ -x "$build/bench_proxies" ] && { [ -z "${BENCH_ONLY:-}" ] || [[ "$only" == *" bench_proxies "* ]]; }; then
  bash "$(dirname "$0")/../bench/vhacd/setup.sh" "$build" || echo "bench_report: V-HACD not set up; bench_proxies runs without it" >&2
fi
body=""
for b in "$build"/bench_*; do
  [ -x "$b" ] && [ -f "$b" ] || continue
  name=$(basename "$b")
  if [ -n "${BENCH_ONLY:-}" ] && [[ "$only" != *" $name "* ]]; then
    kept=$(old_section "$name")
    if [ -n "$kept" ]; then
      body+=$'\n'"$kept"$'\n'
      continue
    fi
  fi
  echo "== $name" >&2
  s0=$(date +%s)
  load0=$(cut -d' ' -f1 /proc/loadavg 2>/dev/null || echo "?")
  status=0
  "$b" "$data" | tee "$tmp.run" || status=$?
  secs=$(( $(date +%s) - s0 ))
  f=$(fence_for "$tmp.run")
  body+=$'\n'"## $name"$'\n\n'"\`$name $data\`: exit status $status, $secs s wall; commit $commit, $(date -u '+%Y-%m-%d %H:%M UTC'), load $load0 at the start."$'\n\n'"$f"$'\n'
  body+=$(cat "$tmp.run")
  body+=$'\n'"$f"$'\n'
  [ "$status" -eq 0 ] || { echo "bench_report: $name failed (status $status); $out not written" >&2; exit 1; }
done

load_end=$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo "?")
total=$(( $(date +%s) - t0 ))
busy=""
if [ "$cores" != "?" ] && awk -v l="${load_start%% *}" -v c="$cores" 'BEGIN { exit !(l >= c / 2) }'; then
  busy=" The load average at the start was at least half the core count: the machine was shared, so the timings are noisy."
fi
{
  echo "# Benchmarks"
  echo
  echo "Written by \`make bench\` (\`scripts/bench_report.sh\`); run it again to replace this file with your machine's figures."
  echo "The paper's models are read from \`$data\` (not in this repository); a program prints \"skipped\" when they are missing."
  echo
  echo "- date: $started"
  echo "- machine: $cores cores, ${cpu:-unknown CPU}, $mem memory"
  echo "- commit: $commit"
  echo "- load average (1, 5, 15 min): $load_start at the start, $load_end at the end.$busy"
  if [ -n "${BENCH_ONLY:-}" ]; then
    echo "- duration: $total s for $BENCH_ONLY; the other sections were kept from an earlier run (a section written since names its commit)"
  else
    echo "- duration: $total s for all programs"
  fi
  printf '%s\n' "$body"
} > "$tmp"
mv "$tmp" "$out"
echo "bench_report: wrote $out ($total s)" >&2
