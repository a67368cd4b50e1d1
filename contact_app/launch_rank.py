"""The MPI rank of this process as its launcher tells it, read without initialising MPI.

Under ``mpirun`` every rank runs the whole analysis on the whole model and the PETSc solver
distributes rank 0's system (docs/running.md, "MPI"). The ranks then hold the same results, so only
rank 0 writes files (VTK, JSON, restart files, ProjectParametersOutput.json) and prints the run's
table: several ranks writing one path would interleave or truncate it. The launchers export the
rank before Python starts: Open MPI ``OMPI_COMM_WORLD_RANK``, MPICH/Hydra ``PMI_RANK``, PMIx
launchers ``PMIX_RANK``.
"""

from __future__ import annotations

import os

#: Environment variables that carry the world rank, in the order they are read.
RANK_VARIABLES = ("OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK")


def launch_rank() -> int:
    """The world rank the launcher gave this process (0 outside a launcher)."""
    for name in RANK_VARIABLES:
        value = os.environ.get(name, "").strip()
        if value.isdigit():
            return int(value)
    return 0


def is_output_rank() -> bool:
    """True for the process that writes files and prints: rank 0, or a process without launcher."""
    return launch_rank() == 0
