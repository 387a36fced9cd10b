#!/usr/bin/env bash
# A bounded libFuzzer run of one target, for ctest (preset `fuzz`).
# Usage: run-fuzzer.sh FUZZER SEED_DIR SECONDS ARTIFACT_DIR [RUNS SEED]
# RUNS > 0: exactly RUNS inputs from libFuzzer seed SEED, one process, no
# time limit (repeatable: what CI runs); otherwise SECONDS of fuzzing from a
# random seed.
# New inputs go to a temporary corpus (the seeds in the repository stay as
# they are); a crash, leak, timeout or out-of-memory input is kept in
# ARTIFACT_DIR and fails the run.
set -u
fuzzer=$1 seeds=$2 seconds=$3 artifacts=$4 runs=${5:-0} seed=${6:-1}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$artifacts"
# -max_len: larger seeds (the 20,000-node chains) are used truncated here;
# the replay tests run them whole. -timeout: one input may take 10 s
# (a hang is a finding). -rss_limit_mb: the loaders' stated limits keep
# any input far below 2 GB.
# A run-bounded run is repeatable: a fixed seed, no reloading of the corpus
# directory (libFuzzer does that on a clock), and no address randomisation
# (setarch -R), since heap addresses reach the comparisons libFuzzer mines
# for its dictionary and the order of pointer-keyed containers.
launch=()
if [[ $runs -gt 0 ]]; then
  bound=(-runs="$runs" -seed="$seed" -reload=0)
  what="$runs inputs from seed $seed"
  if setarch "$(uname -m)" -R true 2>/dev/null; then launch=(setarch "$(uname -m)" -R); fi
else
  bound=(-max_total_time="$seconds")
  what="$seconds s"
fi
"${launch[@]}" "$fuzzer" "${bound[@]}" -max_len=16384 -timeout=10 -rss_limit_mb=2048 \
  -artifact_prefix="$artifacts/" -print_final_stats=1 "$work" "$seeds" 2>"$work/log"
code=$?
tail -n 20 "$work/log"
if [[ $code -ne 0 ]]; then
  echo "FAIL: $(basename "$fuzzer") exited with $code; inputs kept in $artifacts:"
  ls -la "$artifacts"
  exit 1
fi
echo "ok: $(basename "$fuzzer") ran $what without a finding"
