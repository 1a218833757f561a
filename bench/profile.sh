#!/usr/bin/env bash
# Where the CPU time of one run goes: rtd's own code (and whether it ran C2-compiled, C1-compiled
# or interpreted), the JIT compilers, the collector, the kernel, the JDK; then the methods of rtd
# that the samples were taken in most. A sampling profiler outside the JVM's safepoints,
# async-profiler (Apache 2.0, from Maven Central: tools.profiler:async-profiler), sampling every
# thread once per millisecond of CPU; not a dependency of rtd, only of this script.
#
#   bench/profile.sh examples/input_rtd.txt                  # a first run, as java -jar runs it
#   WARM=4 bench/profile.sh bench/scenes/shaded_100000.txt   # 4 runs in one JVM (rtd.bench.WarmRuns)
#   bench/profile.sh SCENE --threads 1                       # anything after the scene goes to rtd
#
# The benchmark scenes under bench/scenes/ are written by bench/targets.sh and bench/beyond.sh.
# Writes bench/out/profile.collapsed (one line per stack: a flame graph tool reads it) and prints
# the summary (rtd.bench.ProfileSummary). Linux on x86-64 or ARM64 only; the kernel's share needs
# perf events (in many containers it reads 0). Unlike JFR, it samples the JIT compilers' and the
# collector's threads too, and says how each sampled method ran (interpreted, C1, C2).
set -euo pipefail

[ $# -ge 1 ] || { echo "usage: bench/profile.sh SCENE [rtd's options]" >&2; exit 2; }
[ -f "$1" ] || { echo "no scene file $1 (bench/scenes/ is written by bench/targets.sh and bench/beyond.sh)" >&2; exit 1; }
[[ "${WARM:-0}" =~ ^[0-9]+$ ]] || { echo "WARM is a number of runs, not '$WARM'" >&2; exit 2; }
scene=$(realpath "$1") # before the cd below, which the relative path was not given from
shift
cd "$(dirname "$0")/.."
PROFILER_VERSION=3.0
case "$(uname -m)" in
  x86_64) arch=linux-x64 ;;
  aarch64) arch=linux-arm64 ;;
  *) echo "async-profiler has no library for $(uname -s) $(uname -m) here" >&2; exit 1 ;;
esac

mvn -q -B package -DskipTests
mvn -q -B -f bench/pom.xml package
mkdir -p bench/out bench/target/profiler
library=bench/target/profiler/$arch/libasyncProfiler.so
if [ ! -f "$library" ]; then
  mvn -q -B org.apache.maven.plugins:maven-dependency-plugin:3.8.1:copy \
    -Dartifact="tools.profiler:async-profiler:$PROFILER_VERSION" \
    -DoutputDirectory=bench/target/profiler
  (cd bench/target/profiler && jar xf "async-profiler-$PROFILER_VERSION.jar" "$arch/libasyncProfiler.so")
fi

agent="-agentpath:$PWD/$library=start,event=cpu,interval=1ms,file=$PWD/bench/out/profile.collapsed,collapsed,ann"
if [ "${WARM:-0}" -gt 0 ]; then
  java "$agent" -cp bench/target/benchmarks.jar rtd.bench.WarmRuns "$WARM" "$scene" -o bench/out/profile.png "$@" >&2
else
  java "$agent" -jar target/rtd.jar "$scene" -o bench/out/profile.png "$@" >&2
fi
java -cp bench/target/benchmarks.jar rtd.bench.ProfileSummary bench/out/profile.collapsed 20
