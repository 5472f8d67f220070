"""The peer benchmark's scenes, written for walls-sim, LAMMPS and LIGGGHTS alike.

The scenes (docs/performance.md, "Against LAMMPS and LIGGGHTS"), in SI units:

* ``drop``: N spheres (radius 1 mm, 2500 kg/m³) on a cubic lattice with gaps of 0.2 R,
  with small pseudo-random velocities (each component uniform in ±5 cm/s, from a fixed
  seed), under gravity in a box of five planes (a floor at z = 0 and four sides);
* ``oscillating``: the same box and spheres, its floor oscillating vertically with
  amplitude A = 0.5 mm at 40 Hz, as LAMMPS's ``wiggle`` moves it: z = A − A·cos(ωt),
  between 0 and 1 mm (walls-sim: origin A, phase 0.75; LIGGGHTS: ``viblin``, phase π);
* ``1e6``: the drop at 10⁶ spheres and 200 steps (its own name, so that its results are
  rows of their own beside the drop's sweep);
* ``cup``: an open cylinder of radius 30 R and height 54 R made of 5,100 triangles (its
  side 300 segments × 8 rings of two triangles, its bottom a fan of 300), holding up to
  10,640 spheres: a square lattice 2.2 R apart inside radius 28.4 R, 20 layers from
  z = 1.1 R, filled from the floor, each sphere moved by up to ±0.08 R in x and y, its
  velocity components in ±5 cm/s. walls-sim and LIGGGHTS only: LAMMPS has no mesh walls.
  With ``triangles``, the same cylinder is cut into about that many (``cup_shape``:
  S segments × K rings and a fan of S, S·(2K + 1) triangles, K/S as near 8/300 as whole
  numbers allow; 99 for 100, 999 for 1,000, 10,000 and 99,975 for 10⁵);
* ``poly``: spheres of radius uniform in [R/2, 2R] (mass from the density) on a lattice
  4.4 R apart (50 × 50 × 40 sites for 10⁵: a footprint 5/4 of the pile's height, filled
  layer by layer), velocity components in ±0.5 m/s, in the drop's box of five planes.

The contact law is a linear spring–dashpot: k_n = 1000 N/m, k_t = 2/7 k_n, normal
restitution 0.5, no tangential damping, static friction 0.5 (0 with ``--no-friction``),
no rolling or twisting friction; dt = 5e-6 s; a neighbour skin of 0.4 of the largest
radius.

``write(directory, scene)`` writes, for each tool that runs the scene (``tools``), its
input set into its own folder:

* ``walls-sim/``: ``box.walls`` (``cup.walls`` for the cup), ``particles.csv`` and
  ``args`` (the arguments of ``walls-sim run``, one per line);
* ``lammps/``: ``data.lmp`` and ``in.lmp`` (``lmp -in in.lmp``);
* ``liggghts/``: ``data.lig``, ``in.lig`` and, for the oscillating floor and the cup,
  ``floor.stl`` or ``cup.stl``.

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
GAP = 0.2 * RADIUS
SPEED = 0.05
SEED = 19
AMPLITUDE = 0.5e-3
FREQUENCY = 40.0

# The cup: its radius and height, its side's segments and rings, the lattice of spheres.
CUP_RADIUS = 30 * RADIUS
CUP_LAYERS = 20
CUP_SPACING = 2.2 * RADIUS
CUP_HEIGHT = CUP_LAYERS * CUP_SPACING + 10 * RADIUS
CUP_SEGMENTS = 300
CUP_RINGS = 8
CUP_REACH = 28.4 * RADIUS
CUP_JITTER = 0.08 * RADIUS

# The polydisperse box: radii uniform in [R/2, 2R] on a lattice 4.4 R apart.
POLY_RADII = (0.5 * RADIUS, 2.0 * RADIUS)
POLY_SPACING = 4.4 * RADIUS
POLY_SPEED = 0.5

FINAL_DUMP = "final.dump"
SCENES = ("drop", "oscillating", "1e6", "cup", "poly")
TOOLS = ("walls-sim", "lammps", "liggghts")
# Each scene's particles when none are asked for (the drop's and the floor's sweep is
# bench-peers' own).
DEFAULT_PARTICLES = {"drop": 1000, "oscillating": 1000, "1e6": 1_000_000, "cup": 10_640, "poly": 100_000}


def tools(kind: str) -> tuple[str, ...]:
    """The tools that run a scene: LAMMPS has no mesh walls, so not the cup."""
    return ("walls-sim", "liggghts") if kind == "cup" else TOOLS


@dataclass(frozen=True)
class Scene:
    """One scene: its kind, particle count, steps, friction, whether LAMMPS and
    LIGGGHTS dump the final state (for the check; not when timing), and the cup's
    triangles (about; none for its own 5,100)."""

    kind: str
    particles: int
    steps: int
    friction: bool = True
    final_dump: bool = False
    triangles: int | None = None

    def __post_init__(self) -> None:
        """The cup's triangles are checked here, before any folder is made."""
        if self.triangles is not None:
            if self.kind != "cup":
                raise ValueError(f"only the cup has triangles to choose, not the {self.kind} scene")
            cup_shape(self.triangles)

    @property
    def cup(self) -> tuple[int, int]:
        """The cup's segments and rings."""
        if self.triangles is None:
            return (CUP_SEGMENTS, CUP_RINGS)
        return cup_shape(self.triangles)

    @property
    def mu(self) -> float:
        """Static friction between spheres and with the walls."""
        return FRICTION if self.friction else 0.0

    @property
    def walls(self) -> str:
        """walls-sim's walls file: the cup's triangles or the box's planes."""
        return "cup.walls" if self.kind == "cup" else "box.walls"


def mass(radius: float = RADIUS) -> float:
    """A sphere's mass, computed as LAMMPS computes it from diameter and density."""
    return 4.0 * math.pi / 3.0 * radius * radius * radius * DENSITY


def damping(eps: float, k: float, m_eff: float) -> float:
    """pkdgrav's normal dashpot C = −2 ln ε √(m_eff k / (π² + ln² ε)), in N·s/m."""
    ln = math.log(eps)
    return -2.0 * ln * math.sqrt(m_eff * k / (math.pi**2 + ln * ln))


def tsuji(e: float) -> float:
    """LAMMPS's `damping tsuji` factor α(e): its dashpot is α(e)·√(m_eff k_n)."""
    return 1.2728 - 4.2783 * e + 11.087 * e**2 - 22.348 * e**3 + 27.467 * e**4 - 18.022 * e**5 + 4.8218 * e**6


def tsuji_restitution() -> float:
    """The e' whose α(e') is pkdgrav's −2 ln ε / √(π² + ln² ε) for ε = 0.5 (0.41140; α
    falls from 1.27 to 0 over [0, 1]), so that LAMMPS's `tsuji` dashpot is pkdgrav's C
    for every effective mass. LAMMPS 29 Sep 2021 has no `coeff_restitution` damping."""
    target = damping(RESTITUTION, 1.0, 1.0)
    lo, hi = 0.0, 1.0
    for _ in range(100):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if tsuji(mid) > target else (lo, mid)
    return lo


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


def layout(n: int, kind: str = "drop") -> Layout:
    """A square footprint about as wide as the pile is high (the poly box: 5/4 of its
    height, 50 × 50 × 40 sites for 10⁵)."""
    if n < 1:
        raise ValueError(f"the particle count must be at least 1, not {n}")
    if n > MAX_PARTICLES:
        raise ValueError(
            f"at most {MAX_PARTICLES:,} particles (about 300 bytes of input files each), not {n:,}"
        )
    if kind == "poly":
        nx = max(1, math.ceil(round((1.25 * n) ** (1.0 / 3.0), 9)))
        spacing = POLY_SPACING
    else:
        nx = max(1, math.ceil(round(n ** (1.0 / 3.0), 9)))
        spacing = 2 * RADIUS + GAP
    nz = math.ceil(n / (nx * nx))
    return Layout(nx, nx, nz, spacing)


# A particle: x, y, z, vx, vy, vz and its radius.
Particle = tuple[float, float, float, float, float, float, float]


def particles(n: int, kind: str = "drop") -> list[Particle]:
    """Positions, velocities and radii: the lattice filled layer by layer, the random
    numbers from a fixed seed, so every tool starts from the same bytes."""
    if kind == "cup":
        return cup_particles(n)
    lay = layout(n, kind)
    rng = random.Random(SEED)
    out = []
    for k in range(n):
        i = k % lay.nx
        j = (k // lay.nx) % lay.ny
        layer = k // (lay.nx * lay.ny)
        x = lay.spacing / 2 + i * lay.spacing
        y = lay.spacing / 2 + j * lay.spacing
        z = lay.spacing / 2 + layer * lay.spacing
        r = RADIUS
        speed = SPEED
        if kind == "poly":
            r = POLY_RADII[0] + (POLY_RADII[1] - POLY_RADII[0]) * rng.random()
            speed = POLY_SPEED
        v = [speed * (2.0 * rng.random() - 1.0) for _ in range(3)]
        out.append((x, y, z, v[0], v[1], v[2], r))
    return out


def cup_sites() -> list[tuple[float, float]]:
    """One layer of the cup's lattice: the points (i + ½, j + ½)·2.2 R within 28.4 R of
    the axis, row by row (532 of them)."""
    half = math.ceil(CUP_REACH / CUP_SPACING)
    out = []
    for j in range(-half, half):
        for i in range(-half, half):
            x, y = (i + 0.5) * CUP_SPACING, (j + 0.5) * CUP_SPACING
            if math.hypot(x, y) <= CUP_REACH:
                out.append((x, y))
    return out


def cup_particles(n: int) -> list[Particle]:
    """The cup's first `n` spheres, layer by layer from the floor, each moved by up to
    ±0.08 R in x and y."""
    if n < 1:
        raise ValueError(f"the particle count must be at least 1, not {n}")
    sites = cup_sites()
    if n > len(sites) * CUP_LAYERS:
        raise ValueError(f"the cup holds at most {len(sites) * CUP_LAYERS} particles, not {n}")
    rng = random.Random(SEED)
    out = []
    for k in range(n):
        x, y = sites[k % len(sites)]
        z = CUP_SPACING / 2 + (k // len(sites)) * CUP_SPACING
        x += CUP_JITTER * (2.0 * rng.random() - 1.0)
        y += CUP_JITTER * (2.0 * rng.random() - 1.0)
        v = [SPEED * (2.0 * rng.random() - 1.0) for _ in range(3)]
        out.append((x, y, z, v[0], v[1], v[2], RADIUS))
    return out


# The most particles a scene holds: ten times the largest the benchmark runs, its three
# input sets about 3 GB.
MAX_PARTICLES = 10_000_000

# The most triangles a cup is cut into: ten times the sweep's largest, its walls file
# about 210 MB and its STL about 310 MB.
MAX_CUP_TRIANGLES = 1_000_000


def cup_shape(triangles: int) -> tuple[int, int]:
    """The segments S and rings K of a cup of about `triangles` triangles, S·(2K + 1),
    its rings as tall against its segments' width as the 5,100's (K/S near 8/300): K the
    nearest whole number to √(triangles · 8/600), at least 1, then S the nearest to
    triangles / (2K + 1), at least 3."""
    if triangles < 9:
        raise ValueError(f"the cup needs at least 9 triangles, not {triangles}")
    if triangles > MAX_CUP_TRIANGLES:
        raise ValueError(
            f"the cup takes at most {MAX_CUP_TRIANGLES:,} triangles (about 520 bytes of "
            f"walls file and STL each), not {triangles:,}"
        )
    rings = max(1, round(math.sqrt(triangles * CUP_RINGS / (2 * CUP_SEGMENTS))))
    return (max(3, round(triangles / (2 * rings + 1))), rings)


def cup_size(segments: int, rings: int) -> int:
    """The triangles of a cup of `segments` and `rings`: two a segment of each ring, and
    the bottom's fan of one a segment."""
    return segments * (2 * rings + 1)


def cup_triangles(
    segments: int = CUP_SEGMENTS, rings: int = CUP_RINGS
) -> list[tuple[tuple[float, float, float], ...]]:
    """The cup's triangles (5,100 by default), each (a, b, c) with its normal
    (b − a) × (c − a) into the cup: the side's `segments` × `rings`, two triangles each,
    then the bottom's fan of `segments` around the axis. Neighbouring triangles share
    their vertices bit for bit."""
    ring = [
        (CUP_RADIUS * math.cos(2 * math.pi * s / segments), CUP_RADIUS * math.sin(2 * math.pi * s / segments))
        for s in range(segments)
    ]
    heights = [CUP_HEIGHT * k / rings for k in range(rings + 1)]

    def point(s: int, k: int) -> tuple[float, float, float]:
        x, y = ring[s % segments]
        return (x, y, heights[k])

    out = []
    for k in range(rings):
        for s in range(segments):
            a, b, c, d = point(s, k), point(s + 1, k), point(s + 1, k + 1), point(s, k + 1)
            out += [(a, d, c), (a, c, b)]
    centre = (0.0, 0.0, 0.0)
    out += [(centre, point(s, 0), point(s + 1, 0)) for s in range(segments)]
    return out


def number(v: float) -> str:
    """A float as the shortest text that reads back exactly."""
    return repr(float(v))


def skin(parts: list[Particle]) -> str:
    """The peers' neighbour skin: 0.4 of the largest radius, as walls-sim takes it (0.4 mm;
    0.8 mm in the poly box)."""
    return number(0.4 * max(p[6] for p in parts))


def write(directory: Path, scene: Scene) -> dict[str, Path]:
    """Writes the three input sets under `directory`; returns each tool's folder."""
    if scene.kind not in SCENES:
        raise ValueError(f"unknown scene {scene.kind!r}: expected one of {', '.join(SCENES)}")
    if scene.steps < 1:
        raise ValueError(f"the step count must be at least 1, not {scene.steps}")
    parts = particles(scene.particles, scene.kind)
    lay = layout(scene.particles, scene.kind)
    folders = {tool: Path(directory) / tool for tool in tools(scene.kind)}
    for folder in folders.values():
        folder.mkdir(parents=True, exist_ok=True)
    write_walls_sim(folders["walls-sim"], scene, parts, lay)
    if "lammps" in folders:
        write_lammps(folders["lammps"], scene, parts, lay)
    write_liggghts(folders["liggghts"], scene, parts, lay)
    return folders


def omega() -> float:
    """The floor's angular frequency, in radians per second."""
    return 2.0 * math.pi * FREQUENCY


def write_walls_sim(folder: Path, scene: Scene, parts: list[Particle], lay: Layout) -> None:
    """The walls file, the particles CSV and the arguments of `walls-sim run`."""
    if scene.kind == "cup":
        write_cup_walls(folder / scene.walls, *scene.cup)
    else:
        write_box_walls(folder / scene.walls, scene, lay)
    rows = ["mass,radius,x,y,z,vx,vy,vz"]
    rows += [",".join([number(mass(p[6])), number(p[6]), *(number(c) for c in p[:6])]) for p in parts]
    (folder / "particles.csv").write_text("\n".join(rows) + "\n")
    (folder / "args").write_text("\n".join(walls_sim_args(scene)) + "\n")


def write_box_walls(path: Path, scene: Scene, lay: Layout) -> None:
    """The box: a floor (oscillating or not) and four sides, planes that take the
    particles' material."""
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
    path.write_text("\n".join(lines) + "\n")


def write_cup_walls(path: Path, segments: int, rings: int) -> None:
    """The cup's triangles as triangle walls: origin a, vertex1 b − a, vertex2 c − a."""
    total = cup_size(segments, rings)
    lines = [
        f"# The peer benchmark's cup (scripts/peers/scene.py): an open cylinder of {total:,}",
        f"# triangles, its side {segments} segments x {rings} ring{'s' * (rings != 1)} of two, its bottom a fan of {segments}.",
        "# Lengths in metres and times in seconds (walls-sim run --units pkdgrav).",
        "# The walls take the particles' material (epsn, epst 99; k_n, k_t, mu_* -1).",
    ]
    for a, b, c in cup_triangles(segments, rings):
        lines += [
            "wall",
            "  type triangle",
            "  origin " + " ".join(number(v) for v in a),
            "  vertex1 " + " ".join(number(v - w) for v, w in zip(b, a)),
            "  vertex2 " + " ".join(number(v - w) for v, w in zip(c, a)),
        ]
    path.write_text("\n".join(lines) + "\n")


def walls_sim_args(scene: Scene) -> list[str]:
    """`walls-sim run`'s arguments, relative to its folder: pkdgrav's step and contact
    law (the default integrator), tangential restitution 1 (no tangential dashpot)."""
    return [
        "run",
        scene.walls,
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


def domain(scene: Scene, lay: Layout) -> tuple[float, float, float, float, float, float]:
    """LAMMPS's and LIGGGHTS's simulation box: the walls' box with a margin, and room
    above the pile; the cup with a margin."""
    margin = 2 * RADIUS
    if scene.kind == "cup":
        side = CUP_RADIUS + margin
        return (-side, side, -side, side, -margin, CUP_HEIGHT + 10 * RADIUS)
    n = scene.particles
    return (
        -margin,
        lay.side + margin,
        -margin,
        lay.side + margin,
        -margin - AMPLITUDE,
        lay.top(n) + 30 * RADIUS,
    )


def write_data(path: Path, scene: Scene, parts: list[Particle], lay: Layout, types: int) -> None:
    """A `read_data` file for atom style sphere (LAMMPS) or granular (LIGGGHTS): id, type,
    diameter, density, x, y, z; then the velocities, with no spin."""
    xlo, xhi, ylo, yhi, zlo, zhi = domain(scene, lay)
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
    rho = number(DENSITY)
    for k, p in enumerate(parts, start=1):
        lines.append(f"{k} 1 {number(2 * p[6])} {rho} {number(p[0])} {number(p[1])} {number(p[2])}")
    lines += ["", "Velocities", ""]
    for k, p in enumerate(parts, start=1):
        lines.append(f"{k} {number(p[3])} {number(p[4])} {number(p[5])} 0 0 0")
    path.write_text("\n".join(lines) + "\n")


def write_lammps(folder: Path, scene: Scene, parts: list[Particle], lay: Layout) -> None:
    """LAMMPS: gran/hooke/history between spheres, one wall/gran per plane, the dashpot
    per unit of effective mass (m/2 between spheres, m against a wall). The poly box's
    masses differ, so it takes `granular` with a dashpot α·√(m_eff k_n) of each contact's
    effective mass, pkdgrav's law for every pair (`tsuji_restitution`)."""
    write_data(folder / "data.lmp", scene, parts, lay, 1)
    m = mass()
    kn, kt, mu = number(K_N), number(K_T), number(scene.mu)
    g_pair = number(damping(RESTITUTION, K_N, m / 2) / (m / 2))
    g_wall = number(damping(RESTITUTION, K_N, m) / m)
    wall = f"wall/gran hooke/history {kn} {kt} {g_wall} 0.0 {mu} 0"
    pair = f"pair_style gran/hooke/history {kn} {kt} {g_pair} 0.0 {mu} 0"
    coeff = "pair_coeff * *"
    if scene.kind == "poly":
        # hooke k_n e', the tangential spring with no dashpot (x_gamma_t 0), and the
        # normal dashpot alpha(e') sqrt(m_eff k_n), pkdgrav's.
        law = (
            f"hooke {kn} {number(tsuji_restitution())} tangential linear_history {kt} 0.0 {mu} "
            "damping tsuji"
        )
        wall = f"wall/gran granular {law}"
        pair = "pair_style granular"
        coeff = f"pair_coeff * * {law}"
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
        f"neighbor {skin(parts)} bin",
        "neigh_modify delay 0 every 1 check yes",
        pair,
        coeff,
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


def write_liggghts(folder: Path, scene: Scene, parts: list[Particle], lay: Layout) -> None:
    """LIGGGHTS: hooke/stiffness with absolute dashpots (N·s/m: type 1 the spheres,
    type 2 the walls), primitive walls, a mesh floor moved by move/mesh, or the cup's
    mesh. hooke/stiffness has no dashpot that follows √m_eff as pkdgrav's does, so the
    poly box's is per unit of effective mass, LAMMPS's gran/hooke/history's: right for a
    pair of spheres of radius R, and against a wall for a sphere of radius R."""
    write_data(folder / "data.lig", scene, parts, lay, 2)
    m = mass()
    c_pair = number(damping(RESTITUTION, K_N, m / 2))
    c_wall = number(damping(RESTITUTION, K_N, m))
    gamman, gammat, absolute = "gamman_abs", "gammat_abs", "on"
    if scene.kind == "poly":
        c_pair = number(damping(RESTITUTION, K_N, m / 2) / (m / 2))
        c_wall = number(damping(RESTITUTION, K_N, m) / m)
        gamman, gammat, absolute = "gamman", "gammat", "off"
    kn, kt, mu = number(K_N), number(K_T), number(scene.mu)
    model = "model hooke/stiffness tangential history"
    settings = f"absolute_damping {absolute} tangential_damping off limitForce off"
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
        f"neighbor {skin(parts)} bin",
        "neigh_modify delay 0 every 1 check yes",
        f"fix kn all property/global kn peratomtypepair 2 {kn} {kn} {kn} {kn}",
        f"fix kt all property/global kt peratomtypepair 2 {kt} {kt} {kt} {kt}",
        f"fix gn all property/global {gamman} peratomtypepair 2 {c_pair} {c_wall} {c_wall} {c_wall}",
        f"fix gt all property/global {gammat} peratomtypepair 2 0 0 0 0",
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
    elif scene.kind == "cup":
        write_cup_stl(folder / "cup.stl", *scene.cup)
        lines += [
            "fix cupmesh all mesh/surface file cup.stl type 2",
            f"fix cup all wall/gran {model} mesh n_meshes 1 meshes cupmesh {settings}",
        ]
    else:
        lines.append(f"fix floor all wall/gran {model} primitive type 2 zplane 0.0 {settings}")
    if scene.kind != "cup":
        lines += [
            f"fix xlo all wall/gran {model} primitive type 2 xplane 0.0 {settings}",
            f"fix xhi all wall/gran {model} primitive type 2 xplane {side} {settings}",
            f"fix ylo all wall/gran {model} primitive type 2 yplane 0.0 {settings}",
            f"fix yhi all wall/gran {model} primitive type 2 yplane {side} {settings}",
        ]
    lines += [
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


def write_cup_stl(path: Path, segments: int, rings: int) -> None:
    """The cup's triangles as an ASCII STL, each facet's normal (b − a) × (c − a) made a
    unit vector."""
    lines = ["solid cup"]
    for a, b, c in cup_triangles(segments, rings):
        u = [q - p for p, q in zip(a, b)]
        v = [q - p for p, q in zip(a, c)]
        n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
        size = math.sqrt(sum(x * x for x in n))
        lines += [
            "  facet normal " + " ".join(number(x / size) for x in n),
            "    outer loop",
            *("      vertex " + " ".join(number(x) for x in corner) for corner in (a, b, c)),
            "    endloop",
            "  endfacet",
        ]
    lines.append("endsolid cup")
    path.write_text("\n".join(lines) + "\n")
