#!/bin/sh
# Cost of the local-lines solver against n on the grid rooms or the museum: wall time, peak memory and area-weighted
# relative RMS error, one row per run. A size N[:SUBDIVIDE] is the grid room of N x N quads per wall
# (make_grid_room.py); museum:ELEMENTS is the museum at about that many elements (make_large_scenes.py). The error is measured against an independent run with 4 times the rays (another seed),
# whose own noise is removed by radiosity_error.py's ratio argument; NO_REFERENCE=1 skips it (the error column is then
# empty and only the solver's reported standard error is given).
# Usage: scenes/tools/bench_local_lines.sh OUTDIR "N[:SUBDIVIDE] ... museum:ELEMENTS ..." RAYS_PER_ELEMENT
# e.g.   scenes/tools/bench_local_lines.sh out/bench "20 40 90 200 200:2" 250
#        scenes/tools/bench_local_lines.sh out/bench "museum:1000 museum:4000 museum:16000" 250
set -eu
out=$1
sizes=$2
per=$3
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
bin=${RADIOSITY:-$root/build/release/bin/radiosity}
mkdir -p "$out"
echo "scene,subdivide,elements,rays_per_iteration,total_rays,seconds,peak_MB,reported_se,error,ref_seconds,ref_peak_MB"
for spec in $sizes; do
  n=${spec%%:*}
  sub=1
  [ "$spec" != "$n" ] && sub=${spec#*:}
  mesh="--no-subdivide"
  if [ "$n" = museum ]; then
    n=museum-$sub
    sub=1
    scene=$out/$n.obj
    [ -f "$scene" ] || python3 "$here/make_large_scenes.py" museum "${n#museum-}" "$scene" >/dev/null
    elements=$(grep -c '^f ' "$scene")
  else
    scene=$out/grid-room-$n.json
    [ -f "$scene" ] || python3 "$here/make_grid_room.py" "$n" "$scene" >/dev/null
    [ "$sub" != 1 ] && mesh="--subdivide $sub"
    elements=$(( (6 * n * n + 12) * sub * sub ))
  fi
  rays=$(( per * elements ))
  run() {  # seed rays tag
    /usr/bin/time -v "$bin" solve "$scene" $mesh --solver local-lines --seed "$1" --rays-per-iteration "$2" \
      --tolerance 1e-3 --output "$out/B-$n-$sub-$3.csv" >"$out/log-$n-$sub-$3.txt" 2>&1
    wall=$(sed -n 's/.*Elapsed (wall clock) time (h:mm:ss or m:ss): //p' "$out/log-$n-$sub-$3.txt" |
      awk -F: '{ s = 0; for (i = 1; i <= NF; i++) s = s * 60 + $i; print s }')
    peak=$(sed -n 's/.*Maximum resident set size (kbytes): //p' "$out/log-$n-$sub-$3.txt" | awk '{ print $1 / 1024 }')
    total=$(sed -n 's/.* \([0-9]*\) rays, .*/\1/p' "$out/log-$n-$sub-$3.txt")
    se=$(sed -n 's/.*relative standard error //p' "$out/log-$n-$sub-$3.txt")
  }
  refwall=
  refpeak=
  error=
  if [ -z "${NO_REFERENCE:-}" ]; then
    run 2 $((4 * rays)) ref
    refwall=$wall
    refpeak=$peak
  fi
  run 1 $rays run
  [ -z "${NO_REFERENCE:-}" ] &&
    error=$(python3 "$here/radiosity_error.py" "$out/B-$n-$sub-run.csv" "$out/B-$n-$sub-ref.csv" 4)
  echo "$n,$sub,$elements,$rays,$total,$wall,$peak,$se,$error,$refwall,$refpeak"
done
