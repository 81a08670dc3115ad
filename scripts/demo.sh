#!/usr/bin/env bash
# Installs the dependencies, builds flume and runs the dam-break demo: BL 5.3 against Martin &
# Moyce, with the case's scheme and the three formulations of BL Figs 9-11 beside it (about four
# minutes on two cores). Then says where the results and the plots are.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
bash scripts/build.sh
verdict=0
./build/flume validate dam_break --out validation || verdict=$?
run=validation/dam_break/continuity
if ! grep -q '"status": "completed"' "$run/summary.json"; then
  echo "the dam-break run failed: see $run/summary.json" >&2
  exit 1
fi
echo
echo "dam break run:       $(pwd)/$run/  (diagnostics.csv, probes.csv, snapshots/snapshots.pvd for ParaView)"
echo "surge front plot:    $(pwd)/validation/dam_break_surge_front.png"
echo "column height plot:  $(pwd)/validation/dam_break_column_height.png"
echo "validation report:   $(pwd)/validation/report.md"
if [ "$verdict" -eq 0 ]; then
  echo "validation: PASSED (every gated metric within its tolerance)"
else
  echo "validation: FAILED (some metrics are outside their tolerance: the report says which and by how much)"
fi
