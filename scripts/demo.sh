#!/usr/bin/env bash
# Installs the dependencies, builds flume and runs the dam-break demo (BL 5.3 against
# Martin & Moyce), then says where the results and the plot are.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
bash scripts/build.sh
status=0
./build/flume validate dam_break --out validation || status=$?
echo
echo "dam break results:   $(pwd)/validation/dam_break/  (diagnostics.csv, probes.csv, snapshots/snapshots.pvd for ParaView)"
echo "surge front plot:    $(pwd)/validation/dam_break_surge_front.png"
echo "column height plot:  $(pwd)/validation/dam_break_column_height.png"
echo "validation report:   $(pwd)/validation/report.md"
exit $status
