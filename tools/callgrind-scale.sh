#!/bin/sh
# callgrind-scale: instructions (Ir) of one call of draw() in
# bench/cbench_scale.c, per scene family, size N (doubled step by step) and
# method, then each step's growth exponent log2(Ir(2N) / Ir(N)): 1 is a
# cost in proportion to the work.  A run over LIMIT seconds shows "-".
#   tools/callgrind-scale.sh build/cbench_scale [FAMILY ...]
# METHODS, SIZES_<family> and LIMIT (seconds, 300) may be set.
set -u
bin=${1:-build/cbench_scale}
[ $# -gt 0 ] && shift
fams=${*:-text smalltris bigtris meshrings}
limit=${LIMIT:-300}
out=$(mktemp -d)
for f in $fams; do
  case $f in
    text) sizes=${SIZES_text:-250 500 1000 2000} ;;
    smalltris) sizes=${SIZES_smalltris:-1000 2000 4000 8000} ;;
    bigtris) sizes=${SIZES_bigtris:-25 50 100 200} ;;
    meshrings) sizes=${SIZES_meshrings:-400 800 1600 3200} ;;
    *) sizes=${SIZES:-100 200 400 800} ;;
  esac
  case $f in
    *tris) methods=${METHODS:-area accumulate ss4 binary tarea taccumulate tss4 tbinary} ;;
    *) methods=${METHODS:-area accumulate ss4 binary} ;;
  esac
  printf '%-10s %-12s' "$f" method
  for n in $sizes; do printf ' %14s' "N=$n"; done
  printf ' | exponents\n'
  for m in $methods; do
    printf '%-10s %-12s' "$f" "$m"
    prev= exps=
    for n in $sizes; do
      ir=-
      if timeout "$limit" valgrind -q --tool=callgrind --toggle-collect='draw*' \
          --callgrind-out-file="$out/cg" "$bin" "$f" "$n" "$m" > /dev/null 2>&1; then
        ir=$(callgrind_annotate "$out/cg" 2>/dev/null | awk '/PROGRAM TOTALS/ {gsub(",", "", $1); print $1; exit}')
      fi
      printf ' %14s' "$ir"
      if [ -n "$prev" ] && [ "$prev" != - ] && [ "$ir" != - ]; then
        exps="$exps $(awk -v a="$ir" -v b="$prev" 'BEGIN {printf "%.2f", log(a / b) / log(2)}')"
      fi
      prev=$ir
      rm -f "$out/cg"
    done
    printf ' |%s\n' "$exps"
  done
done
rm -rf "$out"
