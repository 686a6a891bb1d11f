#!/usr/bin/env bash
# tools/fuzz-long.sh TARGET... - make fuzz-long: each libFuzzer target for
# FUZZ_SECONDS, FUZZ_JOBS at a time (niced), starting from the committed
# corpus; writes one line per target to FUZZ_LONG_OUT (executions,
# coverage, features, corpus size before/after the merge, crashes) and
# merges the new inputs into tests/fuzz/corpus/NAME with -merge=1
# -use_counters=0 (only inputs that reach new edges: the corpus stays small).
# Exits non-zero if any target crashed (its crash input stays in
# FUZZ_LOG_DIR/NAME-crash-*).
set -uo pipefail
: "${FUZZ_CC:=clang}" "${FUZZ_SECONDS:=600}" "${FUZZ_JOBS:=2}"
: "${FUZZ_LOG_DIR:=build/fuzz-long}" "${FUZZ_LONG_OUT:=bench/fuzz-long.txt}"
mkdir -p "$FUZZ_LOG_DIR" build/fuzz-long-bin
rev=$(git rev-parse --short HEAD 2>/dev/null)  # the sources the binaries are built from
for t in "$@"; do
  x=; [ "$t" = fuzz_seq ] && x=${FUZZ_PY:-}  # the embedded interpreter's flags
  # shellcheck disable=SC2086
  "$FUZZ_CC" -std=c99 -Wall -Wextra -Werror -g -O1 -fsanitize=fuzzer,address,undefined \
    -fno-sanitize-recover=all -Icsrc/include -Icsrc/src -Itests/c tests/fuzz/$t.c csrc/src/*/*.c \
    $x -lm -o build/fuzz-long-bin/$t || exit 1
done
run_one() {
  local t=$1 dir="$FUZZ_LOG_DIR/new_$1"
  rm -rf "$dir"; mkdir -p "$dir"
  nice -n 19 ./build/fuzz-long-bin/$t -max_total_time="$FUZZ_SECONDS" -timeout=20 -print_final_stats=1 \
    -artifact_prefix="$FUZZ_LOG_DIR/$t-" "$dir" tests/fuzz/corpus/$t > "$FUZZ_LOG_DIR/$t.log" 2>&1
  echo $? > "$FUZZ_LOG_DIR/$t.rc"
}
running=0
for t in "$@"; do
  run_one "$t" &
  running=$((running + 1))
  if [ "$running" -ge "$FUZZ_JOBS" ]; then wait -n; running=$((running - 1)); fi
done
wait
status=0
{
  echo "# make fuzz-long: $(date -u '+%Y-%m-%d %H:%M UTC'), FUZZ_SECONDS=$FUZZ_SECONDS each, $FUZZ_JOBS at a time (nice 19), $(nproc) cores"
  echo "# $($FUZZ_CC --version | head -1); libFuzzer + ASan + UBSan; built from git $rev"
  printf '# %-16s %12s %8s %8s %10s %8s %s\n' target executions exec/s cov ft corpus crashes
  for t in "$@"; do
    log="$FUZZ_LOG_DIR/$t.log"
    execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
    rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log")
    last=$(grep -E '^#[0-9]+.*cov:' "$log" | tail -1)
    cov=$(sed -n 's/.* cov: \([0-9]*\).*/\1/p' <<<"$last")
    ft=$(sed -n 's/.* ft: \([0-9]*\).*/\1/p' <<<"$last")
    before=$(ls tests/fuzz/corpus/$t | wc -l)
    crashes=$(ls "$FUZZ_LOG_DIR" | grep -c "^$t-\(crash\|leak\|timeout\|oom\)-" || true)
    rc=$(cat "$FUZZ_LOG_DIR/$t.rc")
    if [ "$rc" != 0 ] || [ "$crashes" != 0 ]; then status=1; else
      # merge into the committed corpus: only inputs adding coverage stay
      ./build/fuzz-long-bin/$t -merge=1 -use_counters=0 tests/fuzz/corpus/$t "$FUZZ_LOG_DIR/new_$t" > "$FUZZ_LOG_DIR/$t.merge.log" 2>&1
    fi
    after=$(ls tests/fuzz/corpus/$t | wc -l)
    printf '  %-16s %12s %8s %8s %10s %8s %s\n' "$t" "${execs:-?}" "${rate:-?}" "${cov:-?}" "${ft:-?}" "$before->$after" "$crashes (exit $rc)"
  done
} > "$FUZZ_LONG_OUT.tmp"
mv "$FUZZ_LONG_OUT.tmp" "$FUZZ_LONG_OUT"
cat "$FUZZ_LONG_OUT"
exit $status
