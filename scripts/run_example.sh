#!/usr/bin/env bash
# Bootstraps, then runs the bundled example through the contact-app command line.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/bootstrap.sh
python=${PYTHON:-python3}
"$python" -m contact_app info examples/two_blocks_2d/two_blocks_2d.mdpa "$@"
