"""What the Hertz and Cattaneo-Mindlin examples share: meshing, width estimates, E*, settings.

Mesh grading, gmsh groups, the mirror image of a mesh about x = 0 and the mesh scripts' command
line, the contact width estimates, E*, loading a folder's script by path and the contact process
settings, the mesh of a run, the summary's frame, the figures, the command line and the writing of
the outputs; for the Hertz runners also the example folder (``Example``: mesh script, output names,
run and command line), the result's common fields (``HertzRun``: each runner adds its width b or
a, with its errors as ``RelativeError``), the two profiles (``SEMI_ELLIPSE``, ``HALF_ELLIPSOID``),
the Newton record and the pressure plot. What only the
Cattaneo-Mindlin runners share is in ``cattaneo_mindlin_common``.

Both examples measure an elliptic pressure profile p(c) = p0 sqrt(1 - c^2/w^2) (c = x in 2D, the
radius r in 3D; w = b or a) two ways: a least-squares fit of p^2 against c^2, and the second
moment of the nodal contact forces, w^2 = ratio * sum(c^2 f) / sum(f) (ratio 4 for the 2D
semi-ellipse, 5/2 for the 3D half-ellipsoid), which integrates the whole profile and so does not
depend on where the contact edge falls between two nodes.
"""

from __future__ import annotations

import argparse
import contextlib
import importlib.util
import json
import math
import os
import sys
import time
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import meshio
import numpy as np


def graded(length: float, fine_length: float, fine_intervals: int, growth: float) -> np.ndarray:
    """Parameters in [0, 1]: uniform over ``fine_length``, then geometric up to ``length``.

    Beyond the fine zone the fewest intervals whose ratio does not exceed ``growth`` are used, with
    the ratio that fills the rest exactly.
    """
    h = fine_length / fine_intervals
    rest = length - fine_length
    if rest <= 0.0:
        raise ValueError(f"fine length {fine_length} exceeds the edge length {length}")

    def filled(ratio: float, count: int) -> float:
        return h * sum(ratio**k for k in range(1, count + 1))

    count = 1
    while filled(growth, count) < rest:
        count += 1
    low, high = 0.5, growth
    for _ in range(200):
        ratio = 0.5 * (low + high)
        low, high = (ratio, high) if filled(ratio, count) < rest else (low, ratio)
    steps = h * np.concatenate((np.ones(fine_intervals), ratio ** np.arange(1, count + 1)))
    values = np.concatenate(([0.0], np.cumsum(steps))) / length
    values[-1] = 1.0
    return values


def subdivide(parameters: np.ndarray, factor: int) -> np.ndarray:
    """Split each interval into ``factor`` equal ones."""
    pieces = [
        np.linspace(a, b, factor + 1)[:-1]
        for a, b in zip(parameters[:-1], parameters[1:], strict=True)
    ]
    return np.concatenate([*pieces, parameters[-1:]])


def gmsh_mesh(
    points: np.ndarray,
    cells: list[tuple[str, np.ndarray]],
    tags: list[str],
    node_groups: dict[str, np.ndarray | list[int]],
    groups: dict[str, tuple[int, int]],
) -> meshio.Mesh:
    """A meshio mesh whose cell blocks carry gmsh physical tags.

    ``tags`` names the physical group of each block of ``cells``; every entry of ``node_groups``
    becomes a block of ``vertex`` cells of its group. ``groups`` maps a group name to its
    (tag, dimension), written as the mesh's field data.
    """
    cells = list(cells)
    tags = list(tags)
    for name, nodes in node_groups.items():
        cells.append(("vertex", np.asarray(nodes, dtype=int).reshape(-1, 1)))
        tags.append(name)
    physical = [
        np.full(len(block[1]), groups[name][0], dtype=int)
        for block, name in zip(cells, tags, strict=True)
    ]
    return meshio.Mesh(
        points,
        cells,
        cell_data={"gmsh:physical": physical, "gmsh:geometrical": [p.copy() for p in physical]},
        field_data={name: np.array(value) for name, value in groups.items()},
    )


class MirrorAboutX:
    """A gmsh mesh and its mirror image about x = 0, the nodes on x = 0 merged.

    Points: the mesh's, then the images of those off x = 0 (``points``); ``image[i]`` is the
    image of node i (i itself on x = 0). The Cattaneo-Mindlin meshers mirror the Hertz half
    (quarter) models so: the tangential load is antisymmetric about x = 0.
    """

    def __init__(self, mesh: meshio.Mesh, groups: dict[str, tuple[int, int]], length: float):
        """Mirror ``mesh``, whose physical tags ``groups`` names; x = 0 within 1e-9 ``length``."""
        names = {tag: name for name, (tag, _) in groups.items()}
        self.blocks = {
            names[int(tags[0])]: block.data
            for block, tags in zip(mesh.cells, mesh.cell_data["gmsh:physical"], strict=True)
        }
        points = np.asarray(mesh.points, dtype=float)
        self.on_plane = np.abs(points[:, 0]) < 1e-9 * length
        off = ~self.on_plane
        self.image = np.arange(len(points))
        self.image[off] = len(points) + np.arange(np.count_nonzero(off))
        self.points = np.vstack((points, points[off] * np.array([-1.0, 1.0, 1.0])))

    def cells(self, name: str, order: Any = slice(None, None, -1)) -> np.ndarray:
        """The cells of group ``name``, then their images with the nodes in ``order``.

        Mirroring reverses a cell's orientation; the default, the reversed node order, restores
        it for lines and quads (counter-clockwise again, or the same normal).
        """
        connectivity = self.blocks[name]
        return np.vstack((connectivity, self.image[connectivity][:, order]))

    def nodes(self, name: str) -> np.ndarray:
        """The nodes of group ``name`` and their images, sorted."""
        group = self.blocks[name].ravel()
        return np.unique(np.concatenate((group, self.image[group])))


def write_gmsh(path: Path, mesh: meshio.Mesh, binary: bool) -> meshio.Mesh:
    """Write ``mesh`` to ``path`` (gmsh 2.2) and return it."""
    meshio.write(str(path), mesh, file_format="gmsh22", binary=binary)
    return mesh


def mesh_parser(
    doc: str, refinement_type: type, output: Path, levels: str = "1 = coarsest (default 2)"
) -> argparse.ArgumentParser:
    """The parser of ``--refinement`` (default 2, help ``levels``) and ``--output`` (``output``).

    A mesh script with options of its own adds them to it (hertz_3d's ``--check``).
    """
    parser = argparse.ArgumentParser(description=doc.splitlines()[0])
    parser.add_argument("--refinement", type=refinement_type, default=2, help=levels)
    parser.add_argument("--output", type=Path, default=output)
    return parser


def mesh_arguments(doc: str, refinement_type: type, output: Path) -> argparse.Namespace:
    """``--refinement`` (default 2) and ``--output`` (default ``output``) of a mesh script."""
    return mesh_parser(doc, refinement_type, output).parse_args()


def fit_elliptic_profile(c: np.ndarray, p: np.ndarray, shape: str) -> tuple[float, float]:
    """(w, p0) of p^2 = p0^2 - (p0/w)^2 c^2 fitted in the least-squares sense.

    ``shape`` names the profile in the error messages ("semi-ellipse", "half-ellipsoid").
    """
    if len(c) < 2:
        raise ValueError(f"{len(c)} active contact node(s): cannot fit a {shape}")
    matrix = np.column_stack((np.ones_like(c), c**2))
    (intercept, slope), *_ = np.linalg.lstsq(matrix, p**2, rcond=None)
    if intercept <= 0.0 or slope >= 0.0:
        raise ValueError(
            f"the pressure profile is not a {shape} (p^2 = {intercept:g} + {slope:g} c^2)"
        )
    return math.sqrt(-intercept / slope), math.sqrt(intercept)


def second_moment_width(c: np.ndarray, force: np.ndarray, ratio: float) -> float:
    """The width w from w^2 = ratio * sum(c^2 f) / sum(f)."""
    total = float(np.sum(force))
    if total <= 0.0:
        raise ValueError("no compressive contact force: cannot estimate the contact width")
    return math.sqrt(ratio * float(np.sum(c**2 * force)) / total)


@dataclass(frozen=True)
class EllipticProfile:
    """The Hertz profile of one dimension: its name and the ratio of its second moment."""

    shape: str  # "semi-ellipse" (2D) or "half-ellipsoid" (3D)
    moment_ratio: float  # w^2 / (sum(c^2 f) / sum(f))

    def fit(self, c: np.ndarray, p: np.ndarray) -> tuple[float, float]:
        """(w, p0) of p^2 = p0^2 - (p0/w)^2 c^2 fitted in the least-squares sense."""
        return fit_elliptic_profile(c, p, self.shape)

    def moment_width(self, c: np.ndarray, force: np.ndarray) -> float:
        """The width w from the second moment of the nodal forces ``force`` at ``c``."""
        return second_moment_width(c, force, self.moment_ratio)


#: The 2D Hertz profile: sum(x^2 f) / sum(f) = b^2 / 4.
SEMI_ELLIPSE = EllipticProfile("semi-ellipse", 4.0)
#: The 3D Hertz profile: sum(r^2 f) / sum(f) = (2/5) a^2.
HALF_ELLIPSOID = EllipticProfile("half-ellipsoid", 2.5)


def effective_modulus(materials: Path) -> float:
    """E* with 1/E* = sum over the bodies of (1 - nu^2)/E, from a Kratos materials file."""
    data = json.loads(Path(materials).read_text(encoding="utf-8"))
    compliance = 0.0
    for block in data["properties"]:
        variables = block["Material"]["Variables"]
        compliance += (1.0 - variables["POISSON_RATIO"] ** 2) / variables["YOUNG_MODULUS"]
    return 1.0 / compliance


def example_inputs(workdir: Path, example_dir: Path) -> tuple[Path, Path]:
    """(ProjectParameters.json, materials.json): the working folder's, else the example's own."""
    found = []
    for name in ("ProjectParameters.json", "materials.json"):
        path = workdir / name
        found.append(path if path.exists() else example_dir / name)
    return found[0], found[1]


@contextlib.contextmanager
def working_directory(path: Path) -> Iterator[None]:
    """Run the block in ``path``: the inputs and outputs are relative to it (docs/running.md)."""
    previous = Path.cwd()
    os.chdir(path)
    try:
        yield
    finally:
        os.chdir(previous)


def load_script(name: str, path: Path):
    """The Python file ``path`` as the module ``name`` (loaded once).

    Every example folder has a make_mesh.py: a plain ``import make_mesh`` would reuse whichever one
    a process (pytest, say) imported first, so each is loaded under a name of its own.
    """
    if name not in sys.modules:
        spec = importlib.util.spec_from_file_location(name, path)
        module = importlib.util.module_from_spec(spec)
        assert spec.loader is not None
        sys.modules[name] = module
        spec.loader.exec_module(module)
    return sys.modules[name]


def mesh_script(folder: Path):
    """The make_mesh.py of the example ``folder``, loaded as ``<folder name>_make_mesh``.

    Under a name of its own (``load_script``): a plain ``import make_mesh`` returns whichever
    example's mesh script the process imported first (pytest running the 2D then the 3D runner
    wrote a 2D mesh for the 3D run).
    """
    return load_script(f"{folder.name}_make_mesh", folder / "make_mesh.py")


def output_names(folder: Path, figure: str) -> tuple[str, str, str]:
    """(mesh, plot, summary) file names of the example ``folder``, whose plot shows ``figure``.

    ``<name>.msh``, ``<name>_<figure>.png`` and ``<name>_summary.txt`` for the folder's name: the
    names the example tests look for.
    """
    name = folder.name
    return f"{name}.msh", f"{name}_{figure}.png", f"{name}_summary.txt"


#: The contact processes whose Parameters block the examples read (mu, pairs).
CONTACT_PROCESSES = ("alm_contact_process", "penalty_contact_process", "mpc_contact_process")


def contact_parameters(parameters: dict) -> dict:
    """The Parameters block of the ALM, penalty or MPC contact process of a parameters tree."""
    for process in parameters["processes"]["contact_process_list"]:
        if process["python_module"] in CONTACT_PROCESSES:
            return process["Parameters"]
    raise ValueError(f"none of {', '.join(CONTACT_PROCESSES)} in processes.contact_process_list")


def friction_coefficient(parameters: dict) -> float:
    """Mu of the pair "0" of the contact process."""
    return float(contact_parameters(parameters)["friction_coefficients"]["0"])


def mesh_level(
    path: Path,
    refinement: float | None,
    default_refinement: float,
    write_mesh: Callable[[Path, Any], object],
) -> tuple[float | None, Any]:
    """Write the mesh ``path`` at level ``refinement``: (the level, what ``write_mesh`` returned).

    When ``refinement`` is None: at ``default_refinement`` if no mesh exists, else the existing
    mesh is used: (None, None), the level unknown.
    """
    if refinement is None and not path.exists():
        refinement = default_refinement
    if refinement is None:
        return None, None
    return refinement, write_mesh(path, refinement)


def run_example(
    workdir: Path,
    refinement: int | None,
    mesh: str,
    default_refinement: int,
    write_mesh: Callable[[Path, int], object],
    example_dir: Path,
    analyse: Callable[[Path], Any],
    evaluate: Callable[[Any, Path], Any],
) -> Any:
    """Run an example in ``workdir`` and evaluate it; the result gets its refinement and time.

    The mesh ``mesh`` is written as ``mesh_level`` says, with ``default_refinement``. ``analyse``
    runs the analysis of a ProjectParameters.json in the working folder and returns it;
    ``evaluate(analysis, materials)`` makes the result.
    """
    workdir = Path(workdir).resolve()
    refinement, _ = mesh_level(workdir / mesh, refinement, default_refinement, write_mesh)
    parameters, materials = example_inputs(workdir, example_dir)
    with working_directory(workdir):
        start = time.perf_counter()
        analysis = analyse(parameters)
        elapsed = time.perf_counter() - start
    result = evaluate(analysis, materials)
    result.refinement = refinement  # None: an existing mesh of unknown level was reused
    result.wall_time = elapsed
    return result


def relative_error(value: float, reference: float) -> float:
    """|value - reference| / reference."""
    return abs(value - reference) / reference


class RelativeError:
    """A read-only attribute of a result: the relative error of one field against another.

    ``b_error = RelativeError("b", "b_analytic")`` is |b - b_analytic| / b_analytic.
    """

    def __init__(self, value: str, reference: str) -> None:
        self.value = value
        self.reference = reference

    def __get__(self, result: Any, owner: type | None = None) -> Any:
        if result is None:
            return self
        return relative_error(getattr(result, self.value), getattr(result, self.reference))


@dataclass(kw_only=True)
class HertzRun:
    """What a Hertz run measured in both dimensions; each runner adds its width w (b or a)."""

    refinement: int | None
    spacing: float  # slave surface interval at the contact point
    nodes: int
    elements: int
    load: float  # on the whole body: P' per unit length (2D), F (3D)
    effective_modulus: float
    p0_analytic: float
    p0: float
    active_nodes: int
    iterations: list[int]
    converged: bool
    wall_time: float
    profile: list[tuple[float, float, bool]] = field(default_factory=list)  # (c, p, active)

    p0_error = RelativeError("p0", "p0_analytic")


def newton_record(analysis: Any) -> dict[str, Any]:
    """``iterations`` (Newton, per step) and ``converged`` (every step) of a finished analysis."""
    steps = analysis.reporter.steps
    return {
        "iterations": [record.iterations for record in steps],
        "converged": bool(steps) and not analysis.reporter.non_converged_steps(),
    }


def refinement_text(result: Any) -> str:
    """The mesh line's ", refinement N" of a summary; empty for a reused mesh."""
    return "" if result.refinement is None else f", refinement {result.refinement}"


def hertz_summary(result: Any, lines: list[str], steps: Iterable[str] = ()) -> str:
    """The summary: ``lines``, the Newton iterations, ``steps`` (a line each), the wall time."""
    status = "all steps converged" if result.converged else "NOT CONVERGED"
    return "\n".join(
        [
            *lines,
            f"  Newton iterations: {sum(result.iterations)} "
            f"(per step {', '.join(map(str, result.iterations))}), {status}",
            *steps,
            f"  wall time: {result.wall_time:.2f} s",
        ]
    )


def elliptic_profile(p0: float, width: float, c: np.ndarray) -> np.ndarray:
    """p0 sqrt(1 - c^2/w^2), zero beyond w."""
    return p0 * np.sqrt(np.clip(1.0 - (c / width) ** 2, 0.0, None))


def plot_elliptic_profile(axis: Any, p0: float, width: float, style: str, label: str) -> None:
    """Draw p0 sqrt(1 - c^2/w^2) over [0, w] (w = ``width``) on ``axis``."""
    curve = np.linspace(0.0, width, 400)
    axis.plot(curve, elliptic_profile(p0, width, curve), style, label=label)


def new_figure(size: tuple[float, float]) -> tuple[Any, Any]:
    """(figure, axes) of a new plot of ``size`` inches, drawn off screen."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt.subplots(figsize=size)


def save_figure(
    fig: Any,
    path: Path,
    labels: tuple[str, str, str],
    xlim: tuple[float, float],
    ylim: tuple[float, float | None],
    **legend: Any,
) -> None:
    """Label (x, y, title), limit (None: automatic), grid and legend the axes; save; close.

    ``legend`` goes to the legend.
    """
    import matplotlib.pyplot as plt

    axis = fig.axes[0]
    xlabel, ylabel, title = labels
    axis.set_xlabel(xlabel)
    axis.set_ylabel(ylabel)
    axis.set_title(title)
    axis.set_xlim(*xlim)
    axis.set_ylim(*ylim)
    axis.grid(True, alpha=0.3)
    axis.legend(**legend)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def plot_pressure(
    path: Path,
    result: Any,
    width: float,
    draw_estimates: Callable[[Any], None],
    xlabel: str,
    title: str,
    **legend: Any,
) -> None:
    """Contact pressure of the slave nodes up to 2 w (w = ``width``, the analytic one).

    Draws the analytic profile of ``result.p0_analytic`` over ``width``, then
    ``draw_estimates(axis)`` (the measured profiles), then the active and inactive nodes of
    ``result.profile``; ``legend`` goes to the legend.
    """
    c_max = 2.0 * width
    shown = [(c, p, a) for c, p, a in result.profile if c <= c_max]
    fig, axis = new_figure((7.0, 4.5))
    plot_elliptic_profile(axis, result.p0_analytic, width, "k-", "Hertz (analytic)")
    draw_estimates(axis)
    axis.plot([c for c, _, a in shown if a], [p for _, p, a in shown if a], "C1o", label="active")
    axis.plot(
        [c for c, _, a in shown if not a],
        [p for _, p, a in shown if not a],
        "C2x",
        label="inactive",
    )
    labels = (xlabel, "contact pressure (MPa)", title)
    save_figure(fig, path, labels, (0.0, c_max), (0.0, None), **legend)


def write_outputs(
    result: Any,
    workdir: Path,
    summary: Callable[[Any], str],
    plot: Callable[[Any, Path], None],
    summary_name: str,
    plot_name: str,
) -> str:
    """Write the summary and the plot of ``result`` into ``workdir``; return the summary."""
    text = summary(result)
    (workdir / summary_name).write_text(text + "\n", encoding="utf-8")
    plot(result, workdir / plot_name)
    return text


def example_main(
    argv: list[str] | None,
    doc: str,
    run: Callable[..., Any],
    summary: Callable[[Any], str],
    plot: Callable[[Any, Path], None],
    summary_name: str,
    plot_name: str,
    refinement_type: type = int,
    ratio: tuple[str, float] | None = None,
) -> int:
    """Run, write the plot and the summary, print the summary; 1 if a step did not converge.

    The first line of ``doc`` (the runner's docstring) describes the command. ``ratio`` = (its
    name, its default) adds the option ``--ratio`` (Q/(mu P)), passed to ``run`` after the
    refinement.
    """
    parser = argparse.ArgumentParser(description=doc.splitlines()[0])
    parser.add_argument(
        "--refinement", type=refinement_type, help="write the mesh at this level (1 = coarsest)"
    )
    if ratio is not None:
        name, default = ratio
        parser.add_argument(
            "--ratio", type=float, default=default, help=f"{name}, in (0, 1) (default {default})"
        )
    parser.add_argument("--quiet", action="store_true", help="no step table")
    args = parser.parse_args(argv)
    workdir = Path.cwd()
    extra = () if ratio is None else (args.ratio,)
    result = run(workdir, args.refinement, *extra, quiet=args.quiet)
    text = write_outputs(result, workdir, summary, plot, summary_name, plot_name)
    print(text)
    print(f"outputs: {workdir / plot_name}, {workdir / summary_name}, {workdir / 'vtk_output'}")
    return 0 if result.converged else 1


class Example:
    """The folder of a Hertz runner, with the run and the command line every such runner has.

    Its mesh script (``make_mesh``), its output names and its default refinement.
    """

    def __init__(self, folder: Path, figure: str, default_refinement: int) -> None:
        self.folder = folder
        self.make_mesh = mesh_script(folder)
        self.mesh, self.plot, self.summary = output_names(folder, figure)
        self.default_refinement = default_refinement

    def run(
        self,
        workdir: Path,
        refinement: int | None,
        analyse: Callable[[Path], Any],
        evaluate: Callable[[Any, Path], Any],
    ) -> Any:
        """``run_example`` in ``workdir`` with this folder's mesh and inputs."""
        return run_example(
            workdir,
            refinement,
            self.mesh,
            self.default_refinement,
            self.make_mesh.write_mesh,
            self.folder,
            analyse,
            evaluate,
        )

    def main(
        self,
        argv: list[str] | None,
        doc: str,
        run: Callable[..., Any],
        summary: Callable[[Any], str],
        plot: Callable[[Any, Path], None],
    ) -> int:
        """``example_main`` with this folder's output names."""
        return example_main(argv, doc, run, summary, plot, self.summary, self.plot)


#: 2-point Gauss abscissae on [-1, 1].
GAUSS_2 = (-1.0 / math.sqrt(3.0), 1.0 / math.sqrt(3.0))


def quad_nodal_areas(corners: np.ndarray) -> np.ndarray:
    """Integrals of the bilinear shape functions over a (possibly warped) quad, shape (4,)."""
    areas = np.zeros(4)
    signs = np.array([[-1, -1], [1, -1], [1, 1], [-1, 1]], dtype=float)
    for xi in GAUSS_2:
        for eta in GAUSS_2:
            shape = 0.25 * (1 + signs[:, 0] * xi) * (1 + signs[:, 1] * eta)
            d_xi = 0.25 * signs[:, 0] * (1 + signs[:, 1] * eta) @ corners
            d_eta = 0.25 * signs[:, 1] * (1 + signs[:, 0] * xi) @ corners
            areas += shape * np.linalg.norm(np.cross(d_xi, d_eta))
    return areas


def lumped_line_lengths(part: Any) -> dict[int, float]:
    """Node id -> half the reference length of each line condition of ``part`` through it."""
    lengths: dict[int, float] = {}
    for condition in part.Conditions:
        nodes = condition.GetNodes()
        length = math.hypot(nodes[1].X0 - nodes[0].X0, nodes[1].Y0 - nodes[0].Y0)
        for node in nodes:
            lengths[node.Id] = lengths.get(node.Id, 0.0) + 0.5 * length
    return lengths
