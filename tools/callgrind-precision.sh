#!/bin/sh
# callgrind-precision: instruction counts (Ir) of draw() in
# bench/bench_precision.c, each scene through each path once: the cost of
# the 64-bit vertex path against the 32-bit one without the machine's
# timing noise.   tools/callgrind-precision.sh build/bench_precision
set -eu
bin=${1:-build/bench_precision}
out=$(mktemp -d)
printf '%-8s %14s %14s %14s %14s |  64-bit / 32-bit\n' scene "int32 S=8" "int64 S=8" "int64 S=24" "int64 S=32"
for s in 0 1 2; do
  name=$(echo "random star small" | cut -d' ' -f$((s + 1)))
  line=$(printf '%-8s' "$name"); base=
  ratios=
  for p in 0 1 2 3; do
    valgrind -q --tool=callgrind --toggle-collect='draw*' --callgrind-out-file="$out/cg.$s.$p" \
      "$bin" one $s $p > /dev/null
    ir=$(callgrind_annotate "$out/cg.$s.$p" 2>/dev/null | awk '/PROGRAM TOTALS/ {gsub(",", "", $1); print $1; exit}')
    line="$line $(printf '%14s' "$ir")"
    if [ -z "$base" ]; then base=$ir; else ratios="$ratios $(awk -v a="$ir" -v b="$base" 'BEGIN {printf "%.3fx", a / b}')"; fi
  done
  echo "$line |$ratios"
done
rm -rf "$out"
