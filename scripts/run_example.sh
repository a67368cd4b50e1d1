#!/usr/bin/env bash
# Bootstraps, then runs the bundled cantilever example through `contact-app run` in build/examples
# (outputs stay out of the source tree) and compares its tip deflection with beam theory.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/bootstrap.sh
python=${PYTHON:-python3}
run_dir=build/examples/cantilever_2d
rm -rf "$run_dir"
mkdir -p "$run_dir"
cp examples/cantilever_2d/ProjectParameters.json examples/cantilever_2d/cantilever.mdpa \
  examples/cantilever_2d/cantilever_materials.json examples/cantilever_2d/compare_with_beam_theory.py "$run_dir"/
cd "$run_dir"
"$python" -m contact_app run ProjectParameters.json "$@"
"$python" compare_with_beam_theory.py cantilever_tip.json
echo "outputs: $(pwd)/vtk_output/Structure.pvd (open with ParaView), $(pwd)/cantilever_tip.json"
