#!/usr/bin/env bash
# Animations, whole job, rtd and POV-Ray 3.7 alternating, 60 frames each:
#   orbit: the paper's scene with the camera circling it (examples/orbit.txt), 1920x1080 PNG frames;
#   glass: examples/glass_and_mirror.txt with its camera circling the spheres, 960x540 PNG frames.
# POV-Ray renders the file rtd --export-pov --frames 60 writes (+KFI0 +KFF59, its clock from 0 to 1) on
# 2 threads (+WT2); rtd draws all frames in one run, on every core.
#
#   bench/motion.sh            # 3 runs of each
#   RUNS=5 bench/motion.sh
#
# Prints the median, fastest and slowest wall time of each, its median CPU time (user + system),
# and the ratio of the medians. Needs /usr/bin/time (Debian package "time") and POV-Ray.
set -euo pipefail
cd "$(dirname "$0")/.."

RUNS=${RUNS:-3}
FRAMES=${FRAMES:-60}
mvn -q -B package -DskipTests
mkdir -p bench/scenes bench/out/motion
sed 's#^perspective_camera:.*#perspective_camera:(9*sin(360*clock)|2.5|9*cos(360*clock)):(at 0|1|0):(60)#' \
  examples/glass_and_mirror.txt > bench/scenes/glass_orbit.txt
cp examples/orbit.txt bench/scenes/orbit.txt

export_pov() { # scene width height
  java -jar target/rtd.jar "bench/scenes/$1.txt" --frames "$FRAMES" --width "$2" --height "$3" \
    --export-pov "bench/scenes/$1.pov" -o "bench/out/motion/$1-export.png" >/dev/null 2>&1
  rm -f bench/out/motion/"$1"-export-*.png
}
export_pov orbit 1920 1080
export_pov glass_orbit 960 540

once() { # prints "seconds cpu_seconds" of one run of the command
  /usr/bin/time -f "%e %U %S" -o bench/out/.time "$@" >/dev/null 2>&1 || { echo "failed: $*" >&2; return 1; }
  awk '{ printf "%s %.2f\n", $1, $2 + $3 }' bench/out/.time
}

median() { sort -n | sed -n "$(( (RUNS + 1) / 2 ))p"; }

compare() { # name scene width height
  local rtd="" pov=""
  for _ in $(seq "$RUNS"); do
    rtd+="$(once java -jar target/rtd.jar "bench/scenes/$2.txt" --frames "$FRAMES" --width "$3" --height "$4" \
      -o "bench/out/motion/$1-rtd.png")"$'\n'
    pov+="$(once povray "+Ibench/scenes/$2.pov" "+Obench/out/motion/$1-pov.png" "+W$3" "+H$4" -D -A +FN \
      File_Gamma=1.0 +KFI0 "+KFF$((FRAMES - 1))" +KI0 +KF1 +WT2 -GA)"$'\n'
  done
  local a b
  a=$(printf '%s' "$rtd" | cut -d' ' -f1 | median)
  b=$(printf '%s' "$pov" | cut -d' ' -f1 | median)
  printf "%-6s rtd median %.2f s (%s), CPU %s s   POV-Ray median %.2f s (%s), CPU %s s   ratio %.3f\n" "$1" "$a" \
    "$(printf '%s' "$rtd" | cut -d' ' -f1 | sort -n | tr '\n' ' ')" "$(printf '%s' "$rtd" | cut -d' ' -f2 | median)" \
    "$b" "$(printf '%s' "$pov" | cut -d' ' -f1 | sort -n | tr '\n' ' ')" "$(printf '%s' "$pov" | cut -d' ' -f2 | median)" \
    "$(awk -v a="$a" -v b="$b" 'BEGIN { print a / b }')"
}

echo "machine: $(nproc) cores, $(java -version 2>&1 | head -n 1), $(povray --version 2>&1 | grep -m1 -o 'POV-Ray [0-9.]*')"
compare orbit orbit 1920 1080
compare glass glass_orbit 960 540
