"""The peer benchmark's scenes, written for walls-sim, LAMMPS and LIGGGHTS alike.

Two scenes (docs/performance.md, "Against LAMMPS and LIGGGHTS"), in SI units:

* ``drop``: N spheres (radius 1 mm, 2500 kg/m³) on a cubic lattice with gaps of 0.2 R,
  with small pseudo-random velocities (each component uniform in ±5 cm/s, from a fixed
  seed), under gravity in a box of five planes (a floor at z = 0 and four sides);
* ``oscillating``: the same box and spheres, its floor oscillating vertically with
  amplitude A = 0.5 mm at 40 Hz, as LAMMPS's ``wiggle`` moves it: z = A − A·cos(ωt),
  between 0 and 1 mm (walls-sim: origin A, phase 0.75; LIGGGHTS: ``viblin``, phase π).

The contact law is a linear spring–dashpot: k_n = 1000 N/m, k_t = 2/7 k_n, normal
restitution 0.5, no tangential damping, static friction 0.5 (0 with ``--no-friction``),
no rolling or twisting friction; dt = 5e-6 s; a neighbour skin of 0.4 R.

``write(directory, scene)`` writes, for each tool, its input set into its own folder:

* ``walls-sim/``: ``box.walls``, ``particles.csv`` and ``args`` (the arguments of
  ``walls-sim run``, one per line);
* ``lammps/``: ``data.lmp`` and ``in.lmp`` (``lmp -in in.lmp``);
* ``liggghts/``: ``data.lig``, ``in.lig`` and, for the oscillating floor, ``floor.stl``.

With ``final_dump``, LAMMPS and LIGGGHTS also write the final positions and velocities
to ``final.dump`` (walls-sim gives them with ``--json``).

Python 3.11, standard library only.
"""

from __future__ import annotations

import math
import random
from dataclasses import dataclass
from pathlib import Path

RADIUS = 1e-3
DENSITY = 2500.0
K_N = 1000.0
K_T = 2.0 / 7.0 * K_N
RESTITUTION = 0.5
FRICTION = 0.5
DT = 5e-6
GRAVITY = 9.81
SKIN = 0.4 * RADIUS
GAP = 0.2 * RADIUS
SPEED = 0.05
SEED = 19
AMPLITUDE = 0.5e-3
FREQUENCY = 40.0

FINAL_DUMP = "final.dump"
SCENES = ("drop", "oscillating")
TOOLS = ("walls-sim", "lammps", "liggghts")


@dataclass(frozen=True)
class Scene:
    """One scene: its kind, particle count, steps, friction, and whether LAMMPS and
    LIGGGHTS dump the final state (for the check; not when timing)."""

    kind: str
    particles: int
    steps: int
    friction: bool = True
    final_dump: bool = False

    @property
    def mu(self) -> float:
        """Static friction between spheres and with the walls."""
        return FRICTION if self.friction else 0.0


def mass() -> float:
    """A sphere's mass, computed as LAMMPS computes it from diameter and density."""
    return 4.0 * math.pi / 3.0 * RADIUS * RADIUS * RADIUS * DENSITY


def damping(eps: float, k: float, m_eff: float) -> float:
    """pkdgrav's normal dashpot C = −2 ln ε √(m_eff k / (π² + ln² ε)), in N·s/m."""
    ln = math.log(eps)
    return -2.0 * ln * math.sqrt(m_eff * k / (math.pi**2 + ln * ln))


@dataclass(frozen=True)
class Layout:
    """The lattice and the box: nx × ny columns of nz layers; the box is side × side."""

    nx: int
    ny: int
    nz: int
    spacing: float

    @property
    def side(self) -> float:
        """The box's inner width along x and y."""
        return self.nx * self.spacing

    def top(self, n: int) -> float:
        """The height of the highest sphere's centre."""
        layers = math.ceil(n / (self.nx * self.ny))
        return self.spacing / 2 + (layers - 1) * self.spacing


def layout(n: int) -> Layout:
    """A square footprint about as wide as the pile is high."""
    if n < 1:
        raise ValueError(f"the particle count must be at least 1, not {n}")
    nx = max(1, math.ceil(round(n ** (1.0 / 3.0), 9)))
    nz = math.ceil(n / (nx * nx))
    return Layout(nx, nx, nz, 2 * RADIUS + GAP)


def particles(n: int) -> list[tuple[float, float, float, float, float, float]]:
    """Positions and velocities (x, y, z, vx, vy, vz): the lattice filled layer by layer,
    the velocities from a fixed seed, so every tool starts from the same bytes."""
    lay = layout(n)
    rng = random.Random(SEED)
    out = []
    for k in range(n):
        i = k % lay.nx
        j = (k // lay.nx) % lay.ny
        layer = k // (lay.nx * lay.ny)
        x = lay.spacing / 2 + i * lay.spacing
        y = lay.spacing / 2 + j * lay.spacing
        z = lay.spacing / 2 + layer * lay.spacing
        v = [SPEED * (2.0 * rng.random() - 1.0) for _ in range(3)]
        out.append((x, y, z, v[0], v[1], v[2]))
    return out


def number(v: float) -> str:
    """A float as the shortest text that reads back exactly."""
    return repr(float(v))


def write(directory: Path, scene: Scene) -> dict[str, Path]:
    """Writes the three input sets under `directory`; returns each tool's folder."""
    if scene.kind not in SCENES:
        raise ValueError(f"unknown scene {scene.kind!r}: expected one of {', '.join(SCENES)}")
    if scene.steps < 1:
        raise ValueError(f"the step count must be at least 1, not {scene.steps}")
    parts = particles(scene.particles)
    lay = layout(scene.particles)
    folders = {tool: Path(directory) / tool for tool in TOOLS}
    for folder in folders.values():
        folder.mkdir(parents=True, exist_ok=True)
    write_walls_sim(folders["walls-sim"], scene, parts, lay)
    write_lammps(folders["lammps"], scene, parts, lay)
    write_liggghts(folders["liggghts"], scene, parts, lay)
    return folders


def omega() -> float:
    """The floor's angular frequency, in radians per second."""
    return 2.0 * math.pi * FREQUENCY


def write_walls_sim(folder: Path, scene: Scene, parts, lay: Layout) -> None:
    """The walls file, the particles CSV and the arguments of `walls-sim run`."""
    side = number(lay.side)
    floor = ["wall", "  type plane", "  origin 0 0 0", "  orient 0 0 1"]
    if scene.kind == "oscillating":
        # LAMMPS's wiggle: z = A − A·cos(ωt) = A + A·sin(ωt + 2π·0.75).
        floor = [
            "# The floor oscillates as LAMMPS's wiggle does: z = A - A cos(wt).",
            "wall",
            "  type plane",
            f"  origin 0 0 {number(AMPLITUDE)}",
            "  orient 0 0 1",
            f"  osc-ampl {number(AMPLITUDE)}",
            f"  osc-freq {number(omega())}",
            "  osc-phase 0.75",
            "  osc-vec 0 0 1",
        ]
    lines = [
        "# The peer benchmark's box (scripts/peers/scene.py): a floor and four sides.",
        "# Lengths in metres and times in seconds: the run has no self-gravity, so",
        "# pkdgrav's units are only labels (walls-sim run --units pkdgrav shows them bare).",
        "# The walls take the particles' material (epsn, epst 99; k_n, k_t, mu_* -1).",
        *floor,
        "",
        "wall",
        "  type plane",
        "  origin 0 0 0",
        "  orient 1 0 0",
        "",
        "wall",
        "  type plane",
        f"  origin {side} 0 0",
        "  orient -1 0 0",
        "",
        "wall",
        "  type plane",
        "  origin 0 0 0",
        "  orient 0 1 0",
        "",
        "wall",
        "  type plane",
        f"  origin 0 {side} 0",
        "  orient 0 -1 0",
    ]
    (folder / "box.walls").write_text("\n".join(lines) + "\n")
    m = number(mass())
    r = number(RADIUS)
    rows = ["mass,radius,x,y,z,vx,vy,vz"]
    rows += [",".join([m, r, *(number(c) for c in p)]) for p in parts]
    (folder / "particles.csv").write_text("\n".join(rows) + "\n")
    (folder / "args").write_text("\n".join(walls_sim_args(scene)) + "\n")


def walls_sim_args(scene: Scene) -> list[str]:
    """`walls-sim run`'s arguments, relative to its folder: pkdgrav's step and contact
    law (the default integrator), tangential restitution 1 (no tangential dashpot)."""
    return [
        "run",
        "box.walls",
        "--particles",
        "particles.csv",
        "--dt",
        number(DT),
        "--t-end",
        number(scene.steps * DT),
        "--gravity",
        "0",
        "0",
        number(-GRAVITY),
        "--k-n",
        number(K_N),
        "--k-t",
        number(K_T),
        "--epsn",
        number(RESTITUTION),
        "--epst",
        "1",
        "--mu-s",
        number(scene.mu),
        "--mu-r",
        "0",
        "--mu-t",
        "0",
        "--units",
        "pkdgrav",
    ]


def domain(lay: Layout, n: int) -> tuple[float, float, float, float, float, float]:
    """LAMMPS's and LIGGGHTS's simulation box: the walls' box with a margin, and room
    above the pile."""
    margin = 2 * RADIUS
    return (
        -margin,
        lay.side + margin,
        -margin,
        lay.side + margin,
        -margin - AMPLITUDE,
        lay.top(n) + 30 * RADIUS,
    )


def write_data(path: Path, parts, lay: Layout, types: int) -> None:
    """A `read_data` file for atom style sphere (LAMMPS) or granular (LIGGGHTS): id, type,
    diameter, density, x, y, z; then the velocities, with no spin."""
    xlo, xhi, ylo, yhi, zlo, zhi = domain(lay, len(parts))
    lines = [
        "peer benchmark (scripts/peers/scene.py)",
        "",
        f"{len(parts)} atoms",
        f"{types} atom types",
        "",
        f"{number(xlo)} {number(xhi)} xlo xhi",
        f"{number(ylo)} {number(yhi)} ylo yhi",
        f"{number(zlo)} {number(zhi)} zlo zhi",
        "",
        "Atoms",
        "",
    ]
    d = number(2 * RADIUS)
    rho = number(DENSITY)
    for k, p in enumerate(parts, start=1):
        lines.append(f"{k} 1 {d} {rho} {number(p[0])} {number(p[1])} {number(p[2])}")
    lines += ["", "Velocities", ""]
    for k, p in enumerate(parts, start=1):
        lines.append(f"{k} {number(p[3])} {number(p[4])} {number(p[5])} 0 0 0")
    path.write_text("\n".join(lines) + "\n")


def write_lammps(folder: Path, scene: Scene, parts, lay: Layout) -> None:
    """LAMMPS: gran/hooke/history between spheres, one wall/gran per plane, the dashpot
    per unit of effective mass (m/2 between spheres, m against a wall)."""
    write_data(folder / "data.lmp", parts, lay, 1)
    m = mass()
    kn, kt, mu = number(K_N), number(K_T), number(scene.mu)
    g_pair = number(damping(RESTITUTION, K_N, m / 2) / (m / 2))
    g_wall = number(damping(RESTITUTION, K_N, m) / m)
    wall = f"wall/gran hooke/history {kn} {kt} {g_wall} 0.0 {mu} 0"
    side = number(lay.side)
    wiggle = ""
    if scene.kind == "oscillating":
        wiggle = f" wiggle z {number(AMPLITUDE)} {number(1.0 / FREQUENCY)}"
    lines = [
        f"# The peer benchmark, scene {scene.kind} (scripts/peers/scene.py).",
        "units si",
        "atom_style sphere",
        "boundary f f f",
        # On several MPI ranks, the box is cut across, never along gravity: the pile
        # lies at the bottom, and one rank would hold it all.
        "processors * * 1",
        "newton off",
        "comm_modify vel yes",
        "read_data data.lmp",
        "neighbor " + number(SKIN) + " bin",
        "neigh_modify delay 0 every 1 check yes",
        f"pair_style gran/hooke/history {kn} {kt} {g_pair} 0.0 {mu} 0",
        "pair_coeff * *",
        f"timestep {number(DT)}",
        f"fix gravity all gravity {number(GRAVITY)} vector 0 0 -1",
        f"fix floor all {wall} zplane 0.0 NULL{wiggle}",
        f"fix xlo all {wall} xplane 0.0 NULL",
        f"fix xhi all {wall} xplane NULL {side}",
        f"fix ylo all {wall} yplane 0.0 NULL",
        f"fix yhi all {wall} yplane NULL {side}",
        "fix integrate all nve/sphere",
        "thermo 0",
        f"run {scene.steps}",
    ]
    if scene.final_dump:
        lines.append(f"write_dump all custom {FINAL_DUMP} id x y z vx vy vz modify format float %.17g")
    (folder / "in.lmp").write_text("\n".join(lines) + "\n")


def write_liggghts(folder: Path, scene: Scene, parts, lay: Layout) -> None:
    """LIGGGHTS: hooke/stiffness with absolute dashpots (N·s/m: type 1 the spheres,
    type 2 the walls), primitive walls, or a mesh floor moved by move/mesh."""
    write_data(folder / "data.lig", parts, lay, 2)
    m = mass()
    c_pair = number(damping(RESTITUTION, K_N, m / 2))
    c_wall = number(damping(RESTITUTION, K_N, m))
    kn, kt, mu = number(K_N), number(K_T), number(scene.mu)
    model = "model hooke/stiffness tangential history"
    settings = "absolute_damping on tangential_damping off limitForce off"
    side = number(lay.side)
    lines = [
        f"# The peer benchmark, scene {scene.kind} (scripts/peers/scene.py).",
        "atom_style granular",
        "atom_modify map array",
        "boundary f f f",
        "processors * * 1",
        "newton off",
        "communicate single vel yes",
        "units si",
        "read_data data.lig",
        "neighbor " + number(SKIN) + " bin",
        "neigh_modify delay 0 every 1 check yes",
        f"fix kn all property/global kn peratomtypepair 2 {kn} {kn} {kn} {kn}",
        f"fix kt all property/global kt peratomtypepair 2 {kt} {kt} {kt} {kt}",
        "fix gn all property/global gamman_abs peratomtypepair 2 "
        f"{c_pair} {c_wall} {c_wall} {c_wall}",
        "fix gt all property/global gammat_abs peratomtypepair 2 0 0 0 0",
        f"fix mu all property/global coefficientFriction peratomtypepair 2 {mu} {mu} {mu} {mu}",
        f"pair_style gran {model} {settings}",
        "pair_coeff * *",
        f"timestep {number(DT)}",
        f"fix gravity all gravity {number(GRAVITY)} vector 0 0 -1",
    ]
    if scene.kind == "oscillating":
        write_floor_stl(folder / "floor.stl", lay.side)
        lines += [
            "fix floormesh all mesh/surface file floor.stl type 2",
            f"fix floor all wall/gran {model} mesh n_meshes 1 meshes floormesh {settings}",
            # z = A·(cos(ωt + π) − cos π) = A − A·cos(ωt), as LAMMPS's wiggle.
            "fix shake all move/mesh mesh floormesh viblin axis 0 0 1 order 1 "
            f"amplitude {number(AMPLITUDE)} phase {number(math.pi)} "
            f"period {number(1.0 / FREQUENCY)}",
        ]
    else:
        lines.append(f"fix floor all wall/gran {model} primitive type 2 zplane 0.0 {settings}")
    lines += [
        f"fix xlo all wall/gran {model} primitive type 2 xplane 0.0 {settings}",
        f"fix xhi all wall/gran {model} primitive type 2 xplane {side} {settings}",
        f"fix ylo all wall/gran {model} primitive type 2 yplane 0.0 {settings}",
        f"fix yhi all wall/gran {model} primitive type 2 yplane {side} {settings}",
        "fix integrate all nve/sphere",
        "thermo 0",
    ]
    if scene.final_dump:
        lines += [
            f"dump final all custom {scene.steps} {FINAL_DUMP} id x y z vx vy vz",
            'dump_modify final format "%d %.17g %.17g %.17g %.17g %.17g %.17g"',
        ]
    lines.append(f"run {scene.steps}")
    (folder / "in.lig").write_text("\n".join(lines) + "\n")


def write_floor_stl(path: Path, side: float) -> None:
    """The floor as one triangle (ASCII STL) covering the box with room to spare: a mesh
    edge under the spheres would be met as an edge, not as the plane the others see."""
    lo, hi = number(-side), number(4 * side)
    lines = [
        "solid floor",
        "  facet normal 0 0 1",
        "    outer loop",
        f"      vertex {lo} {lo} 0",
        f"      vertex {hi} {lo} 0",
        f"      vertex {lo} {hi} 0",
        "    endloop",
        "  endfacet",
        "endsolid floor",
    ]
    path.write_text("\n".join(lines) + "\n")
