#!/usr/bin/env bash
# Bootstraps, then runs the 2D Hertz example (examples/hertz_2d) in build/examples/hertz_2d (outputs
# stay out of the source tree): writes the mesh, runs the contact analysis, compares the contact
# pressure with Hertz theory. Extra arguments go to run_hertz_2d.py (e.g. --refinement 3).
# The cantilever example runs with: cd examples/cantilever_2d && contact-app run ProjectParameters.json
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/bootstrap.sh
python=${PYTHON:-python3}
run_dir=build/examples/hertz_2d
rm -rf "$run_dir"
mkdir -p "$run_dir"
cp examples/hertz_2d/ProjectParameters.json examples/hertz_2d/materials.json "$run_dir"/
cd "$run_dir"
"$python" ../../../examples/hertz_2d/run_hertz_2d.py "$@"
echo "VTK: $(pwd)/vtk_output/Structure.pvd (open with ParaView)"
