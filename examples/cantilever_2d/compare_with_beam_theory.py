"""Compare the tip deflection written by the cantilever run with Timoshenko beam theory."""

from __future__ import annotations

import json
import sys
from pathlib import Path

LENGTH, HEIGHT, THICKNESS = 10.0, 1.0, 1.0
YOUNG, POISSON = 1000.0, 0.0
LOAD_PER_LENGTH = 1.0e-2  # LINE_LOAD modulus at t = 1 over the tip edge


def main(results: Path) -> int:
    """Print computed vs analytic tip deflection; return 0."""
    data = json.loads(results.read_text(encoding="utf-8"))
    tips = [values["DISPLACEMENT_Y"][-1] for key, values in data.items() if key.startswith("NODE_")]
    computed = -sum(tips) / len(tips)
    load = LOAD_PER_LENGTH * HEIGHT * THICKNESS
    inertia = THICKNESS * HEIGHT**3 / 12.0
    shear_modulus = YOUNG / (2.0 * (1.0 + POISSON))
    bending = load * LENGTH**3 / (3.0 * YOUNG * inertia)
    shear = load * LENGTH / (5.0 / 6.0 * shear_modulus * THICKNESS * HEIGHT)
    analytic = bending + shear
    error = abs(computed - analytic) / analytic
    time = data["TIME"][-1]
    print(f"tip deflection at t = {time:g}: computed {computed:.6e}, Timoshenko {analytic:.6e}")
    print(f"relative difference {100 * error:.2f} % (bilinear quads converge as h^2)")
    return 0


if __name__ == "__main__":
    sys.exit(main(Path(sys.argv[1]) if len(sys.argv) > 1 else Path("cantilever_tip.json")))
