#!/usr/bin/env bash
# Soft shadows against POV-Ray, whole process, rtd and POV-Ray 3.7 alternating: the shaded bench scene
# (100,000 random spheres above a mirroring floor) with its two point lights replaced by area lights of
# 4 x 4 samples (4 x 4 units each, centred where the point lights were); POV-Ray's twin is written by rtd
# itself (--export-pov: area_light on the same 16 points each, every light tested, no jitter).
#
#   bench/area.sh                         # 5 runs of each at 1920x1080
#   RUNS=3 W=480 H=270 bench/area.sh      # fewer, smaller runs on a busy machine
#
# Prints the median, fastest and slowest wall time of each, its median CPU time (user + system), and the
# ratio of the medians; then rtd's --stats for one run (how long the light grids took to build).
# Needs /usr/bin/time (Debian package "time") and POV-Ray (apt-get install povray).
set -euo pipefail
cd "$(dirname "$0")/.."

RUNS=${RUNS:-5}
W=${W:-1920}
H=${H:-1080}
mvn -q -B package -DskipTests
mvn -q -B -f bench/pom.xml package
mkdir -p bench/scenes bench/out
[ -f bench/scenes/shaded_100000.txt ] ||
  java -cp bench/target/benchmarks.jar rtd.bench.SceneGenerator 100000 42 bench/scenes/shaded_100000.txt shaded
sed -e 's/^light:(-30|40|30):(200|190|170)$/area_light:(-32|40|28):(4|0|0):(0|0|4):(4|4):(200|190|170)/' \
    -e 's/^light:(35|25|10):(90|110|160)$/area_light:(33|25|8):(4|0|0):(0|0|4):(4|4):(90|110|160)/' \
    -e 's/two lights/two area lights of 4 x 4 (bench\/area.sh)/' \
    bench/scenes/shaded_100000.txt > bench/scenes/area_100000.txt
grep -c '^area_light:' bench/scenes/area_100000.txt | grep -qx 2 || { echo "the bench scene's lights were not found" >&2; exit 1; }
java -jar target/rtd.jar bench/scenes/area_100000.txt --export-pov bench/scenes/area_100000.pov \
  --width "$W" --height "$H" -o bench/out/area-export.png >/dev/null 2>&1

once() { # prints "seconds cpu_seconds" for one run of the command
  /usr/bin/time -f "%e %U %S" -o bench/out/.time "$@" >/dev/null 2>&1 || { echo "failed: $*" >&2; return 1; }
  awk '{ printf "%s %.2f\n", $1, $2 + $3 }' bench/out/.time
}
median() { sort -n | sed -n "$(( (RUNS + 1) / 2 ))p"; }

rtd="" pov=""
for _ in $(seq "$RUNS"); do
  rtd+="$(once java -jar target/rtd.jar bench/scenes/area_100000.txt --width "$W" --height "$H" -o bench/out/area-rtd.png)"$'\n'
  pov+="$(once povray +Ibench/scenes/area_100000.pov +Obench/out/area-pov.png +W"$W" +H"$H" -D -A +FN File_Gamma=1.0 -GA)"$'\n'
done
a=$(printf '%s' "$rtd" | cut -d' ' -f1 | median)
b=$(printf '%s' "$pov" | cut -d' ' -f1 | median)
echo "machine: $(nproc) cores, $(java -version 2>&1 | head -n 1), $(povray --version 2>&1 | grep -m1 -o 'POV-Ray [0-9.]*'), ${W}x${H}"
printf "area   rtd median %.2f s (%s), CPU %s s   POV-Ray median %.2f s (%s), CPU %s s   ratio %.3f\n" "$a" \
  "$(printf '%s' "$rtd" | cut -d' ' -f1 | sort -n | tr '\n' ' ')" "$(printf '%s' "$rtd" | cut -d' ' -f2 | median)" \
  "$b" "$(printf '%s' "$pov" | cut -d' ' -f1 | sort -n | tr '\n' ' ')" "$(printf '%s' "$pov" | cut -d' ' -f2 | median)" \
  "$(awk -v a="$a" -v b="$b" 'BEGIN { print a / b }')"
java -jar target/rtd.jar bench/scenes/area_100000.txt --width "$W" --height "$H" -o bench/out/area-rtd.png --stats 2>&1 >/dev/null
