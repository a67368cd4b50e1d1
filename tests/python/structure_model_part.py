"""The "Structure" model part the plate tests and the block benchmark start from.

On ``sys.path`` for the tests through pytest's ``pythonpath`` (pyproject.toml); the benchmark
imports it by path.
"""

from __future__ import annotations

import contact_app as ca


def create_structure(
    model: ca.Model, domain_size: int, young_modulus: float, law: str, thickness: float | None
) -> tuple[ca.ModelPart, ca.Properties]:
    """Return "Structure" (buffer 2, DISPLACEMENT, REACTION, VOLUME_ACCELERATION) and properties 1.

    Properties 1 hold ``young_modulus``, POISSON_RATIO 0.3, the constitutive law ``law`` and,
    unless it is None, ``thickness``.
    """
    mp = model.CreateModelPart("Structure", 2)
    for variable in (ca.DISPLACEMENT, ca.REACTION, ca.VOLUME_ACCELERATION):
        mp.AddNodalSolutionStepVariable(variable)
    mp.ProcessInfo[ca.DOMAIN_SIZE] = domain_size
    props = mp.CreateNewProperties(1)
    props[ca.YOUNG_MODULUS] = young_modulus
    props[ca.POISSON_RATIO] = 0.3
    if thickness is not None:
        props[ca.THICKNESS] = thickness
    props.SetValue(ca.CONSTITUTIVE_LAW, ca.create_constitutive_law(law))
    return mp, props
