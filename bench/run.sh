#!/usr/bin/env bash
# Whole-process benchmark of rtd (--accel none, the default, and bvh) and, where installed, POV-Ray 3.7, on
# random scenes of 10 to 1,000,000 spheres rendered at 1920x1080.
#
#   bench/run.sh              # 3 runs per case, the median is reported
#   RUNS=5 SIZES="10 1000" bench/run.sh
#
# Prints a Markdown table and writes bench/out/results.csv and bench/out/chart.png.
# Needs /usr/bin/time (Debian package "time"); POV-Ray: apt-get install povray.
set -euo pipefail
cd "$(dirname "$0")/.."

RUNS=${RUNS:-3}
SIZES=${SIZES:-"10 1000 100000 1000000"}
NONE_UP_TO=${NONE_UP_TO:-1000}   # the paper's loop tests every sphere for every ray: N x 2 M tests
PIXELS=$((1920 * 1080))

mvn -q -B package -DskipTests
mvn -q -B -f bench/pom.xml package
mkdir -p bench/scenes bench/out
for n in $SIZES; do
  [ -f "bench/scenes/spheres_$n.txt" ] ||
    java -cp bench/target/benchmarks.jar rtd.bench.SceneGenerator "$n" 42 "bench/scenes/spheres_$n.txt"
  # POV-Ray's twin, as rtd itself writes it (--export-pov; at the same size, for the camera's half-pixel shift)
  [ -f "bench/scenes/spheres_$n.export.pov" ] ||
    java -jar target/rtd.jar "bench/scenes/spheres_$n.txt" --export-pov "bench/scenes/spheres_$n.export.pov" \
      -o bench/out/export.png >/dev/null 2>&1
done

# One run: prints "seconds peak_kb render_seconds" (render_seconds from --stats, or "-").
run_once() {
  local timing=bench/out/.time stderr=bench/out/.stderr
  /usr/bin/time -f "%e %M" -o "$timing" "$@" >/dev/null 2>"$stderr" || { cat "$stderr" >&2; return 1; }
  local render
  render=$(awk '$1 == "render" { print $2 }' "$stderr")
  echo "$(cat "$timing") ${render:--}"
}

# The median line (by wall time) of RUNS runs.
median_of_runs() {
  for _ in $(seq "$RUNS"); do run_once "$@"; done | sort -n | sed -n "$(( (RUNS + 1) / 2 ))p"
}

echo "machine: $(nproc) cores, $(java -version 2>&1 | head -n 1), $(povray --version 2>&1 | grep -m1 -o 'POV-Ray [0-9.]*' || echo 'no POV-Ray')"
echo
echo "| spheres | renderer | wall time (median of $RUNS) | peak memory | Mrays/s (render phase) |"
echo "| ---: | --- | ---: | ---: | ---: |"
echo "spheres,renderer,seconds,peak_mb" > bench/out/results.csv
report() { # spheres renderer "seconds peak_kb render_seconds"
  read -r seconds peak render <<<"$3"
  local rate="-"
  [ "$render" != "-" ] && rate=$(awk -v p="$PIXELS" -v s="$render" 'BEGIN { printf "%.2f", p / s / 1e6 }')
  printf "| %'d | %s | %.2f s | %d MB | %s |\n" "$1" "$2" "$seconds" $((peak / 1024)) "$rate"
  echo "$1,$2,$seconds,$((peak / 1024))" >> bench/out/results.csv
}

for n in $SIZES; do
  scene=bench/scenes/spheres_$n.txt
  if [ "$n" -le "$NONE_UP_TO" ]; then
    report "$n" "rtd --accel none" "$(median_of_runs java -jar target/rtd.jar "$scene" -o bench/out/none.png --accel none --stats)"
  fi
  report "$n" "rtd (default)" "$(median_of_runs java -jar target/rtd.jar "$scene" -o bench/out/auto.png --stats)"
  report "$n" "rtd --accel bvh" "$(median_of_runs java -jar target/rtd.jar "$scene" -o bench/out/bvh.png --accel bvh --stats)"
  if command -v povray >/dev/null; then
    report "$n" "POV-Ray 3.7" "$(median_of_runs povray "+I${scene%.txt}.export.pov" +Obench/out/povray.png +W1920 +H1080 -D -A +FN File_Gamma=1.0 -GA)"
  fi
done

java -cp bench/target/benchmarks.jar rtd.bench.ChartWriter bench/out/results.csv bench/out/chart.png
echo
echo "chart: bench/out/chart.png"
