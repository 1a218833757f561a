#!/usr/bin/env bash
# The whole-process speed targets, each measured side by side with what it is compared to, in
# alternating runs (A, B, A, B, ...) so that a busy moment of this shared machine hits both:
#
#   1. the paper's example against the floor program (bench/target/floor.jar: picocli and
#      javax.imageio writing a flat PNG of the same size, nothing else);
#   2. 1,000,000 random spheres at 1920x1080 against POV-Ray 3.7 (its twin written by rtd's
#      --export-pov), with rtd's peak memory;
#   3. the second core: the render phase (--stats) of 100,000 spheres with --threads 1 against
#      --threads 2, through the view grid (--accel grid, which auto takes there too).
#
#   bench/targets.sh              # 11 pairs each (POV-Ray: POV_RUNS=3 runs, it takes 10-20 s each)
#   RUNS=21 POV_RUNS=1 bench/targets.sh
#
# Prints medians, fastest and slowest runs, the median CPU time (user + system), and the ratios of
# the medians. Needs /usr/bin/time (Debian package "time"); POV-Ray (apt-get install povray) for
# the second line.
set -euo pipefail
cd "$(dirname "$0")/.."

RUNS=${RUNS:-11}
POV_RUNS=${POV_RUNS:-3}
mvn -q -B package -DskipTests
mvn -q -B -f bench/pom.xml package
mkdir -p bench/scenes bench/out
for n in 100000 1000000; do
  [ -f "bench/scenes/spheres_$n.txt" ] ||
    java -cp bench/target/benchmarks.jar rtd.bench.SceneGenerator "$n" 42 "bench/scenes/spheres_$n.txt"
done
[ -f bench/scenes/spheres_1000000.export.pov ] ||
  java -jar target/rtd.jar bench/scenes/spheres_1000000.txt --export-pov bench/scenes/spheres_1000000.export.pov \
    -o bench/out/export.png >/dev/null 2>&1

# One run: prints "seconds peak_kb render_seconds cpu_seconds" (render_seconds from --stats, or "-";
# cpu_seconds is user + system time: on a busy shared machine it moves less than the wall time).
once() {
  /usr/bin/time -f "%e %M %U %S" -o bench/out/.time "$@" >/dev/null 2>bench/out/.stderr ||
    { cat bench/out/.stderr >&2; return 1; }
  local render
  render=$(awk '$1 == "render" { print $2 }' bench/out/.stderr)
  awk -v r="${render:--}" '{ printf "%s %s %s %.2f\n", $1, $2, r, $3 + $4 }' bench/out/.time
}


column() { cut -d' ' -f"$1" <<<"$2" | sort -n; } # field, lines
middle() { local sorted; sorted=$(column "$1" "$2"); sed -n "$(( ($(wc -l <<<"$sorted") + 1) / 2 ))p" <<<"$sorted"; }
spread() { local sorted; sorted=$(column "$1" "$2"); echo "$(head -n 1 <<<"$sorted")-$(tail -n 1 <<<"$sorted")"; }

# Alternates two commands RUNS times each; the commands are given as two strings.
pairs() { # name_a command_a name_b command_b field runs
  local a="" b=""
  for _ in $(seq "$6"); do
    a+="$(once $2)"$'\n'
    b+="$(once $4)"$'\n'
  done
  a=${a%$'\n'}
  b=${b%$'\n'}
  local ma mb
  ma=$(middle "$5" "$a")
  mb=$(middle "$5" "$b")
  printf "  %-22s median %6.2f s  (%s s)  peak %4d MB  CPU %s s\n" "$1" "$ma" "$(spread "$5" "$a")" \
    $(( $(middle 2 "$a") / 1024 )) "$(middle 4 "$a")"
  printf "  %-22s median %6.2f s  (%s s)  peak %4d MB  CPU %s s\n" "$3" "$mb" "$(spread "$5" "$b")" \
    $(( $(middle 2 "$b") / 1024 )) "$(middle 4 "$b")"
  printf "  ratio %s / %s: %.2f\n" "$1" "$3" "$(awk -v x="$ma" -v y="$mb" 'BEGIN { print x / y }')"
}

echo "machine: $(nproc) cores, $(java -version 2>&1 | head -n 1), $(povray --version 2>&1 | grep -m1 -o 'POV-Ray [0-9.]*' || echo 'no POV-Ray')"
echo
echo "1. the paper's example, whole process ($RUNS pairs); target: rtd at most 1.15 x the floor"
pairs "rtd" "java -jar target/rtd.jar examples/input_rtd.txt -o bench/out/paper.png" \
  "floor program" "java -jar bench/target/floor.jar examples/input_rtd.txt -o bench/out/floor.png" 1 "$RUNS"
echo
echo "2. 1,000,000 spheres, whole process; targets: at most 1.5 s, 400 MB, 0.15 x POV-Ray"
# A first run whose files (the JDK's, the jar, the 50 MB scene) are no longer in the page cache
# reads them from disk (6.3 s against 2.1 s for the next runs, measured after dropping the cache).
# So one run of rtd, not counted, and a read of POV-Ray's 162 MB scene come first: the runs below
# then compare the work, not the disk.
once java -jar target/rtd.jar bench/scenes/spheres_1000000.txt -o bench/out/million.png >/dev/null
if command -v povray >/dev/null; then cat bench/scenes/spheres_1000000.export.pov >/dev/null; fi
rtd_runs=""
for _ in $(seq "$RUNS"); do
  rtd_runs+="$(once java -jar target/rtd.jar bench/scenes/spheres_1000000.txt -o bench/out/million.png)"$'\n'
done
rtd_runs=${rtd_runs%$'\n'}
printf "  rtd alone, %d runs: median %.2f s (%s s), peak memory %d MB, CPU %s s\n" "$RUNS" "$(middle 1 "$rtd_runs")" \
  "$(spread 1 "$rtd_runs")" $(( $(middle 2 "$rtd_runs") / 1024 )) "$(middle 4 "$rtd_runs")"
if command -v povray >/dev/null; then
  pairs "rtd" "java -jar target/rtd.jar bench/scenes/spheres_1000000.txt -o bench/out/million.png" \
    "POV-Ray 3.7" "povray +Ibench/scenes/spheres_1000000.export.pov +Obench/out/million-pov.png +W1920 +H1080 -D -A +FN File_Gamma=1.0 -GA" \
    1 "$POV_RUNS"
fi
echo
echo "3. 100,000 spheres, the render phase (--stats, $RUNS pairs); target: 2 threads at least 1.6 x faster than 1"
pairs "1 thread" "java -jar target/rtd.jar bench/scenes/spheres_100000.txt -o bench/out/t1.png --stats --threads 1 --accel grid" \
  "2 threads" "java -jar target/rtd.jar bench/scenes/spheres_100000.txt -o bench/out/t2.png --stats --threads 2 --accel grid" 3 "$RUNS"
