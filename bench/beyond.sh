#!/usr/bin/env bash
# The benchmarks beyond the paper, whole process at 1920x1080, rtd and POV-Ray 3.7 alternating:
#   mesh:   a terrain of 1,002,528 triangles (an OBJ file) under a perspective camera, flat colours;
#           POV-Ray's twin is the same mesh as mesh2 (bench's MeshGenerator writes both).
#   shaded: 100,000 random spheres above a mirroring floor, two lights (shadows, reflection);
#           POV-Ray's twin is written by rtd itself (--export-pov).
#
#   bench/beyond.sh            # 5 runs of each
#   RUNS=3 bench/beyond.sh
#
# Prints the median, fastest and slowest wall time of each, its median CPU time (user + system),
# and the ratio of the medians.
# Needs /usr/bin/time (Debian package "time") and POV-Ray (apt-get install povray).
set -euo pipefail
cd "$(dirname "$0")/.."

RUNS=${RUNS:-5}
mvn -q -B package -DskipTests
mvn -q -B -f bench/pom.xml package
mkdir -p bench/scenes bench/out
gen() { java -cp bench/target/benchmarks.jar "$@"; }

[ -f bench/scenes/terrain_708.obj ] || gen rtd.bench.MeshGenerator terrain 708 bench/scenes/terrain_708.obj bench/scenes/mesh_1000000.pov
cat > bench/scenes/mesh_1000000.txt <<'SCENE'
// A terrain of 708 x 708 quads, 1,002,528 triangles (bench/beyond.sh)
ambient:(16|18|28)
perspective_camera:(0|1.2|2.2):(0|-0.55|-1):(60)
mesh:(terrain_708.obj):(0|0|0):(1):(90|160|80)
SCENE

[ -f bench/scenes/shaded_100000.txt ] || gen rtd.bench.SceneGenerator 100000 42 bench/scenes/shaded_100000.txt shaded
[ -f bench/scenes/shaded_100000.pov ] ||
  java -jar target/rtd.jar bench/scenes/shaded_100000.txt --export-pov bench/scenes/shaded_100000.pov \
    --width 192 --height 108 -o bench/out/export.png >/dev/null 2>&1

# Prints "seconds cpu_seconds" for one run of the command (cpu: user + system time, which moves less
# than the wall time on a busy shared machine).
once() {
  /usr/bin/time -f "%e %U %S" -o bench/out/.time "$@" >/dev/null 2>&1 || { echo "failed: $*" >&2; return 1; }
  awk '{ printf "%s %.2f\n", $1, $2 + $3 }' bench/out/.time
}

median() { sort -n | sed -n "$(( (RUNS + 1) / 2 ))p"; }

compare() { # name rtd-scene pov-scene
  local rtd="" pov=""
  for _ in $(seq "$RUNS"); do
    rtd+="$(once java -jar target/rtd.jar "$2" -o bench/out/"$1"-rtd.png)"$'\n'
    pov+="$(once povray "+I$3" +Obench/out/"$1"-pov.png +W1920 +H1080 -D -A +FN File_Gamma=1.0 -GA)"$'\n'
  done
  local a b
  a=$(printf '%s' "$rtd" | cut -d' ' -f1 | median)
  b=$(printf '%s' "$pov" | cut -d' ' -f1 | median)
  printf "%-7s rtd median %.2f s (%s), CPU %s s   POV-Ray median %.2f s (%s), CPU %s s   ratio %.3f\n" "$1" "$a" \
    "$(printf '%s' "$rtd" | cut -d' ' -f1 | sort -n | tr '\n' ' ')" "$(printf '%s' "$rtd" | cut -d' ' -f2 | median)" \
    "$b" "$(printf '%s' "$pov" | cut -d' ' -f1 | sort -n | tr '\n' ' ')" "$(printf '%s' "$pov" | cut -d' ' -f2 | median)" \
    "$(awk -v a="$a" -v b="$b" 'BEGIN { print a / b }')"
}

echo "machine: $(nproc) cores, $(java -version 2>&1 | head -n 1), $(povray --version 2>&1 | grep -m1 -o 'POV-Ray [0-9.]*')"
compare mesh bench/scenes/mesh_1000000.txt bench/scenes/mesh_1000000.pov
compare shaded bench/scenes/shaded_100000.txt bench/scenes/shaded_100000.pov
