#!/bin/bash
# Byte-identity check for refactors (issue 15): runs a fixed set of foldkit commands and prints one md5 per
# output (timing keys stripped from JSON). Usage: bench/output_hashes.sh FOLDKIT OUTDIR > hashes.txt
# Compare two builds: diff <(bench/output_hashes.sh OLD/foldkit /tmp/a) <(bench/output_hashes.sh NEW/foldkit /tmp/b)
set -u
ROOT=$(cd "$(dirname "$0")/.." && pwd); S=${FOLDKIT_CORPUS:-$ROOT/../shared/meshes}; E=$ROOT/examples
[ -d "$S" ] || { echo "output_hashes: no corpus at $S: skipped"; exit 0; }
S=$(realpath "$S"); F=$(realpath "$1"); O=$2
# OUTDIR must be new or empty: the script never deletes what it did not make.
mkdir -p "$O" && [ -z "$(ls -A "$O")" ] || { echo "output_hashes: $O is not an empty folder" >&2; exit 2; }
cd "$O"
strip_json() { python3 -c '
import json,sys
def s(x):
    if isinstance(x,dict): return {k:s(v) for k,v in x.items() if not (k.endswith("_s") or k.endswith("_mb") or k in ("file","seconds","wall_s","cpu_s"))}
    if isinstance(x,list): return [s(v) for v in x]
    return x
print(json.dumps(s(json.load(sys.stdin)),sort_keys=True))'; }
run() { local tag=$1; shift; mkdir -p "$tag"; ( cd "$tag" && "$F" "$@" > stdout.txt 2> stderr.txt; echo "rc=$?" >> stderr.txt ); }
for m in $S/lowpoly/barn.obj $S/lowpoly/football.obj $S/tricky/quads_ngons.obj $E/spot_350.obj $E/penguin_500.obj $S/bob_1000.obj $E/spot_textured/spot_control_mesh.obj; do
  n=$(basename $m .obj)
  run make150_$n make $m --size 150mm -o s.svg --json --hints
  run makefit_$n make $m -o s.svg --json
  run unfold_$n unfold $m -o net.obj --json
  run unfoldsz_$n unfold $m -o net.obj --size 150mm --paper A4
done
for m in $S/bob_350.obj $E/spot_350.obj; do n=$(basename $m .obj)
  for mth in mst search ga; do run unfold_${mth}_$n unfold $m --method $mth -o net.obj --seed 1; done; done
run cut_cameo3 cut $E/spot_128.obj --device cameo3 --size 100mm -o job.gpgl --draw-labels --regmarks
run cut_cameo4 cut $E/bob_128.obj --device cameo4 --size 120mm -o job.gpgl
run cut_gx24 cut $E/bob_128.obj --device roland-gx24 --size 120mm -o job.plt
run cut_hpgl cut $E/spot_128.obj --device generic-hpgl --size 120mm -o job.hpgl --draw-labels
run cut_dry cut $E/spot_128.obj --dry-run --size 100mm --preview p.svg --json
run bench_unfold bench $S --max-faces 128 --methods mst,search --json
run bench_layout bench $S --layout --filter _128 --json
run inspect inspect $E/spot_350.obj --json
for d in */; do d=${d%/}
  for f in $(cd $d && find . -type f | sort); do
    case $f in
      *stdout.txt) if head -c1 $d/$f | grep -q '[{[]'; then h=$(strip_json < $d/$f | md5sum); else h=$(grep -v -i 'second\| s\b\|[0-9]s)' $d/$f | md5sum); fi;;
      *stderr.txt) h=$(grep -v "%" $d/$f | grep -v -i 'second\|[0-9] s\b\|[0-9]s\b' | md5sum);;
      *.pdf) h=$(pdftotext $d/$f - | md5sum);;
      *) h=$(md5sum < $d/$f);;
    esac
    echo "$d/${f#./} ${h%% *}"
  done
done
