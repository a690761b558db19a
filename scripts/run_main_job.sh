#!/usr/bin/env bash
# Installs missing Debian packages, builds rigidfold, and runs the main job: the
# foldability report of the bundled patterns (data/bundled), with figures, in out/report.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/bootstrap.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" --target rigidfold
./build/app/rigidfold report data/bundled --out out/report
/usr/bin/python3 python/plot_report.py out/report
# Fold-angle curves of the bundled square twists (seed 001 figures): the rigid types with
# their M-V assignment, the modified types along the branch the solver traces.
mkdir -p out/report/traces
csvs=()
for name in square_twist_30_type3 square_twist_30_type4 square_twist_30_type2m; do
  ./build/app/rigidfold trace "data/bundled/$name.fold" --steps 80 --csv "out/report/traces/$name.csv" >/dev/null
  csvs+=("out/report/traces/$name.csv")
done
for csv in "${csvs[@]}"; do
  /usr/bin/python3 python/plot_branches.py "$csv" --out "out/report/figures/$(basename "$csv" .csv)_branches.png" >/dev/null
done
# The bundled tube (a sheet with a hole): both branches through its given 3D state.
./build/app/rigidfold trace data/bundled/miura_tube_6_alpha60.fold --branch all \
  --csv out/report/traces/miura_tube_6_alpha60.csv >/dev/null
/usr/bin/python3 python/plot_branches.py out/report/traces/miura_tube_6_alpha60.b0.csv \
  out/report/traces/miura_tube_6_alpha60.b1.csv --from-given-state --title "Miura tube, both ways from its given state" \
  --out out/report/figures/miura_tube_6_alpha60_branches.png >/dev/null
# Branch diagrams of the modified square twists (seed 001 Figs. 8, 10): every branch through
# the flat state and the located bifurcations; creases b2 (diagonal, 12), b3 (1), b4 (7),
# b5 (6) against b1 (side AB, 0).
mkdir -p out/report/branches
for name in square_twist_30_type1m square_twist_30_type2m; do
  ./build/app/rigidfold check "data/bundled/$name.fold" --json > "out/report/branches/$name.check.json"
  ./build/app/rigidfold trace "data/bundled/$name.fold" --branch all --csv "out/report/branches/$name.csv" >/dev/null
  /usr/bin/python3 python/plot_bifurcation.py "out/report/branches/$name.check.json" out/report/branches/"$name".b*.csv \
    --x-edge 0 --edges 12,1,7,6 --out "out/report/figures/${name}_bifurcations.png" >/dev/null
done
# Waterbomb bistability (seed 004; n = 3, 4 (Fig 2.9: rest at 60 deg, equal springs) and 10):
# stable states, energy and force against apex height, every sample checked on the general
# 2n-crease model; and the bundled base (a FOLD file, no waterbomb code on that path) searched
# for its stable states and the barriers between them by the general energy command.
mkdir -p out/report/waterbomb
for spec in "3 60 1" "4 60 1" "10 45 1"; do
  read -r n t0 kr <<<"$spec"
  stem="out/report/waterbomb/waterbomb_n${n}_theta${t0}_k${kr}"
  ./build/app/rigidfold waterbomb --n "$n" --theta0-deg "$t0" --k-ratio "$kr" --json > "$stem.json"
  ./build/app/rigidfold waterbomb --n "$n" --theta0-deg "$t0" --k-ratio "$kr" --curve "$stem.csv" >/dev/null
  /usr/bin/python3 python/plot_waterbomb.py "$stem.csv" "$stem.json" \
    --out "out/report/figures/$(basename "$stem").png" >/dev/null
done
./build/app/rigidfold energy data/bundled/waterbomb_base.fold --rest data/energy/waterbomb_base_rest60.json \
  --barriers --json > out/report/waterbomb/waterbomb_base_energy.json
# Mountain-valley classes (seed 003 §3.2-3.3): every flat-folding assignment of units P and Q
# and of the square twist, in classes under the pattern's symmetry and the global flip, each
# with its rigid-foldability verdict.
mkdir -p out/report/assignments
for name in corrugated_p_rigid corrugated_q_rigid square_twist_30_type1; do
  ./build/app/rigidfold assignments "data/bundled/$name.fold" --json > "out/report/assignments/$name.json"
  /usr/bin/python3 python/plot_assignments.py "data/bundled/$name.fold" "out/report/assignments/$name.json" \
    --out "out/report/figures/${name}_assignments.png" >/dev/null
done
# Thick panels (seed 003 ch. 4): the bundled 4x4 Miura with Bennett hinge heights (DOF 1, on the
# zero-thickness motion) and with each hinge on the face its crease folds toward (rigid), the
# Bennett sheet as FOLD and its slabs at 60 deg as STL.
mkdir -p out/report/thick
./build/app/rigidfold thick data/bundled/miura_4x4_alpha60.fold --thickness 0.05 --hinges bennett \
  --out out/report/thick/miura_4x4_bennett.fold --stl out/report/thick/miura_4x4_bennett_60deg.stl --at 60 \
  --json > out/report/thick/miura_4x4_bennett.json
./build/app/rigidfold thick data/bundled/miura_4x4_alpha60.fold --thickness 0.05 --hinges valley \
  --json > out/report/thick/miura_4x4_valley.json
# The diamond arch (seed 003 §4.4.1): check on its zero-thickness strip and on its thick sheet
# (plane-symmetric Bricard loops; check reads the thick FOLD with the thick model).
./build/app/rigidfold check data/thick/diamond_arch_6_a30.fold --json > out/report/thick/diamond_arch_check.json
./build/app/rigidfold check data/thick/diamond_arch_6_a30_thick.fold --json > out/report/thick/diamond_arch_thick_check.json
# Formats: every bundled crease pattern as SVG (Origami Simulator's convention) and DXF; the tube
# has no flat crease pattern and is skipped.
mkdir -p out/report/export
for f in data/bundled/*.fold; do
  name="$(basename "$f" .fold)"
  [ "$name" = miura_tube_6_alpha60 ] && continue
  ./build/app/rigidfold export "$f" --svg "out/report/export/$name.svg" --dxf "out/report/export/$name.dxf" >/dev/null
done
# SORCE rolling-contact joints (seed 002) on the traced path (both patterns here: their exact
# multiplier family): the seed's
# vertex A with linear offsets (eq 27's end values from the stacking rule) and the bundled 4x4
# Miura folded flat; per crease its profile pair (profiles.svg/.dxf), one printable STL per
# panel, the panels at t = 0.5, frames.fold and poses.csv (`rigidfold sorce`).
./build/app/rigidfold sorce data/sorce/vertex_a.fold --thickness 0.1 --drive 1 --to 180 --at 0.5 \
  --out out/report/sorce/vertex_a >/dev/null
./build/app/rigidfold sorce data/bundled/miura_4x4_alpha60.fold --thickness 0.05 --drive 4 --to=-180 --at 0.5 \
  --out out/report/sorce/miura_4x4 >/dev/null
# Spherical-linkage networks given by twists (seed 003 ch. 2): each bundled network's closed
# configuration, DOF and verdict, and (the mobile ones) its input-output table traced in 12 steps;
# eq 2-34 with one vertex perturbed does not close (its least residual, as evidence).
mkdir -p out/report/network
for f in data/network/*.json; do
  name="$(basename "$f")"
  if [ "$name" = eq2-34_perturbed.json ]; then
    ./build/app/rigidfold network "$f" --json > "out/report/network/$name"
  else
    ./build/app/rigidfold network "$f" --json --trace 12 > "out/report/network/$name"
  fi
done
# The eq 2-34 assembly as a crease pattern (Fig 2-12), and its verdict.
./build/app/rigidfold network data/network/eq2-34.json --out out/report/network/eq2-34.fold >/dev/null
./build/app/rigidfold check out/report/network/eq2-34.fold --json > out/report/network/eq2-34_check.json
# Metamaterial units (seed 003 ch. 3): the square twist's dimensions and Poisson's ratios along
# its motion (nu_HL changes sign at the height maximum), table and plots, cross-checked against
# the 3 x 3 tessellation traced by the general solver (--cross-check).
./build/app/rigidfold metamaterial --unit square-twist --json --cross-check --plot out/report/metamaterial/square_twist \
  > out/report/metamaterial_square_twist.json
./build/app/rigidfold metamaterial --unit element3 --plot out/report/metamaterial/element3 >/dev/null
# The stacked metamaterials 1-4 (§3.2.3): each layer traced, the stack measured against the
# elements' closed forms.
for m in 1 2 3 4; do
  ./build/app/rigidfold metamaterial --stacked "$m" --json > "out/report/metamaterial/stacked_$m.json"
done
# The browser viewer (viewer/): the bundled Type 2M (every branch), a Miura and the tube,
# playable from out/report/viewer/index.html, and a screenshot of it (type2m.png).
bash viewer/main_job.sh out/report
echo "report: out/report/REPORT.md"
