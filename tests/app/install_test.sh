#!/usr/bin/env bash
# An installed vigil: `cmake --install` into a temporary prefix, then `vigil paper --seeds 1` from there finds
# the configs installed beside the binary (not the source tree's: the installed sweep is shortened here to 3 s
# runs, and the runs must show it), and a binary copied on its own says to use --sweep.
# Usage: install_test.sh BUILD_DIR
set -euo pipefail
build=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cmake --install "$build" --prefix "$tmp/prefix" >/dev/null
for f in bin/vigil share/vigil/configs/paper_sweep.yaml share/vigil/configs/paper.yaml share/doc/vigil/README.md \
  share/doc/vigil/docs/README.md share/doc/vigil/docs/cli.md; do
  [[ -f $tmp/prefix/$f ]] || { echo "missing after install: $f"; exit 1; }
done
# The installed tree moves as a whole.
mv "$tmp/prefix" "$tmp/moved"
for f in paper_sweep.yaml paper_noise_sweep.yaml; do
  sed -i 's/^set:$/set:\n  duration_s: 3/' "$tmp/moved/share/vigil/configs/$f"
done
(cd "$tmp" && "$tmp/moved/bin/vigil" paper -o "$tmp/paper" --seeds 1 -j 2 --quiet)
[[ -f $tmp/paper/table2.md && -f $tmp/paper/summary.md && -f $tmp/paper/figures/fig6_summary.png ]] ||
  { echo "vigil paper from the prefix did not write its tables and figures"; exit 1; }
# One run per cell of the installed sweep (its methods x glitch settings, 1 seed), and the noise ablation beside.
methods=$(sed -n '/^methods:/,/^[a-z_]*:/p' "$tmp/moved/share/vigil/configs/paper_sweep.yaml" | grep -c '^  [a-z_]*:')
runs=$(ls "$tmp/paper/runs" | wc -l)
[[ $methods -ge 3 && $runs == $((3 * methods)) ]] ||
  { echo "expected $((3 * methods)) runs (3 settings x $methods methods x 1 seed), got $runs"; exit 1; }
[[ -f $tmp/paper/reproduction.md && -f $tmp/paper/noise_ablation/results.csv ]] ||
  { echo "vigil paper from the prefix did not write reproduction.md and the noise ablation"; exit 1; }
grep -q '"duration_s": 3' "$tmp/paper/noise_ablation/runs/noise_0_1-vins_euroc-dtw-s001/metrics.json" ||
  { echo "the noise ablation did not use the installed paper_noise_sweep.yaml"; exit 1; }
grep -q '"duration_s": 3' "$tmp/paper/runs/noise_0_1-dtw-s001/metrics.json" ||
  { echo "the runs did not use the installed paper_sweep.yaml"; exit 1; }
# --sweep overrides.
cp "$tmp/moved/share/vigil/configs/paper.yaml" "$tmp/base.yaml"
printf 'base: base.yaml\nset: {duration_s: 2}\nmethods: {original: none}\nseeds: [1]\n' >"$tmp/mine.yaml"
"$tmp/moved/bin/vigil" paper --sweep "$tmp/mine.yaml" -o "$tmp/mine" --seeds 1 --quiet
[[ $(ls "$tmp/mine/runs" | wc -l) == 1 ]] || { echo "--sweep FILE was not used"; exit 1; }
# A binary copied alone: no configs, a clear error (exit 2), unless --sweep names one.
cp "$tmp/moved/bin/vigil" "$tmp/alone"
set +e
"$tmp/alone" paper -o "$tmp/none" --seeds 1 2>"$tmp/err"
status=$?
set -e
[[ $status == 2 ]] && grep -q "paper_sweep.yaml: not found beside the binary" "$tmp/err" ||
  { echo "copied binary: expected exit 2 and a clear message, got $status: $(cat "$tmp/err")"; exit 1; }
[[ ! -e $tmp/none ]] || { echo "copied binary wrote an output directory"; exit 1; }
echo "install test passed"
