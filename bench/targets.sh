#!/usr/bin/env bash
# The two whole-process targets of the speed issue, each run RUNS times on this machine:
# the paper's example and a million random spheres, 1920x1080, from `java -jar` to the PNG on disk.
#
#   bench/targets.sh            # 11 runs each
#   RUNS=21 bench/targets.sh
#
# Prints the median, the fastest and the slowest run and the median peak memory. The machine is
# shared, so single runs vary by a quarter; compare medians. Needs /usr/bin/time (Debian package "time").
set -euo pipefail
cd "$(dirname "$0")/.."

RUNS=${RUNS:-11}
mvn -q -B package -DskipTests
mvn -q -B -f bench/pom.xml package
mkdir -p bench/scenes bench/out
[ -f bench/scenes/spheres_1000000.txt ] ||
  java -cp bench/target/benchmarks.jar rtd.bench.SceneGenerator 1000000 42 bench/scenes/spheres_1000000.txt

# Prints "seconds peak_kb" for each of RUNS runs of the command, one a line.
runs() {
  for _ in $(seq "$RUNS"); do
    /usr/bin/time -f "%e %M" -o bench/out/.time "$@" >/dev/null 2>&1
    cat bench/out/.time
  done
}

summary() { # name; reads lines of "seconds peak_kb"
  local lines times memory
  lines=$(cat)
  times=$(cut -d' ' -f1 <<<"$lines" | sort -n)
  memory=$(cut -d' ' -f2 <<<"$lines" | sort -n)
  printf "%-18s median %.2f s  (fastest %.2f s, slowest %.2f s, %d runs)  peak memory %d MB\n" "$1" \
    "$(sed -n "$(( (RUNS + 1) / 2 ))p" <<<"$times")" "$(head -n 1 <<<"$times")" "$(tail -n 1 <<<"$times")" "$RUNS" \
    "$(( $(sed -n "$(( (RUNS + 1) / 2 ))p" <<<"$memory") / 1024 ))"
}

echo "machine: $(nproc) cores, $(java -version 2>&1 | head -n 1)"
runs java -jar target/rtd.jar examples/input_rtd.txt -o bench/out/paper.png | summary "paper's example"
runs java -jar target/rtd.jar bench/scenes/spheres_1000000.txt -o bench/out/million.png | summary "1,000,000 spheres"
