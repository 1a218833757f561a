#!/usr/bin/env bash
# How much of a first run is the JIT's, set beside POV-Ray: for the terrain and the shaded scene of
# bench/beyond.sh (which writes them: run it first), rounds of four runs, one after the other:
#
#   first    rtd as `java -jar` runs it;
#   start    `java -jar target/rtd.jar --version`: the JVM's start, picocli and the exit, nothing else;
#   warm     start + the median of runs 2-5 of rtd.bench.WarmRuns 5 (five runs in one JVM; from the
#            second on, rtd's code is compiled), each from reading the scene to the written picture;
#   POV-Ray  3.7, beyond.sh's command.
#
#   bench/warm.sh                                      # 3 rounds of each scene
#   ROUNDS=5 bench/warm.sh
#   JAVA_OPTS=-XX:TieredStopAtLevel=1 bench/warm.sh    # rtd's JVMs with options of yours (here C1 alone)
#
# Prints one line per round: the seconds of each, and first / POV-Ray and warm / POV-Ray. Needs
# /usr/bin/time (Debian package "time") and POV-Ray (apt-get install povray).
set -euo pipefail
cd "$(dirname "$0")/.."

ROUNDS=${ROUNDS:-3}
read -r -a java_opts <<<"${JAVA_OPTS:-}"
for f in mesh_1000000.txt mesh_1000000.pov shaded_100000.txt shaded_100000.pov; do
  [ -f "bench/scenes/$f" ] || { echo "no bench/scenes/$f: bench/beyond.sh writes it" >&2; exit 1; }
done
mvn -q -B package -DskipTests
mvn -q -B -f bench/pom.xml package
mkdir -p bench/out

seconds() { # the wall time of one run of the command
  /usr/bin/time -f "%e" -o bench/out/.time "$@" >/dev/null 2>&1 || { echo "failed: $*" >&2; return 1; }
  cat bench/out/.time
}

warm_total() { # the median total (--stats) of runs 2 to 5 in one JVM
  java "${java_opts[@]}" -cp bench/target/benchmarks.jar rtd.bench.WarmRuns 5 "$1" -o bench/out/warm.png --stats 2>&1 |
    awk '$1 == "total" { if (++n > 1) print $2 }' | sort -n | awk '{ t[NR] = $1 } END { print (t[2] + t[3]) / 2 }'
}

echo "machine: $(nproc) cores, $(java -version 2>&1 | head -n 1), $(povray --version 2>&1 | grep -m1 -o 'POV-Ray [0-9.]*')"
echo "rtd's JVM options: ${JAVA_OPTS:-none}"
for scene in mesh shaded; do
  case $scene in
    mesh) rtd_scene=bench/scenes/mesh_1000000.txt pov_scene=bench/scenes/mesh_1000000.pov ;;
    shaded) rtd_scene=bench/scenes/shaded_100000.txt pov_scene=bench/scenes/shaded_100000.pov ;;
  esac
  for _ in $(seq "$ROUNDS"); do
    first=$(seconds java "${java_opts[@]}" -jar target/rtd.jar "$rtd_scene" -o bench/out/first.png)
    start=$(seconds java "${java_opts[@]}" -jar target/rtd.jar --version)
    warm=$(warm_total "$rtd_scene")
    pov=$(seconds povray "+I$pov_scene" +Obench/out/warm-pov.png +W1920 +H1080 -D -A +FN File_Gamma=1.0 -GA)
    awk -v s="$scene" -v f="$first" -v st="$start" -v w="$warm" -v p="$pov" 'BEGIN {
      printf "%-7s first %5.2f s   start %4.2f s + warm run %5.3f s   POV-Ray %6.2f s   first/POV %.2f   warm/POV %.2f\n",
        s, f, st, w, p, f / p, (st + w) / p }'
  done
done
