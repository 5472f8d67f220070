"""Runs, pkdgrav ``.ss`` files and previews as NumPy arrays (docs/python.md, "Analysis").

The work is the command-line tools' own, in the extension: ``walls.run`` is ``walls-sim
run``, ``walls.read_ss`` and ``walls.write_ss`` its ``.ss`` reader and writer,
``walls.preview`` the page of ``walls-sim preview --out page.html``. This module turns
their bytes into arrays and arrays into the files they read.
"""

import html
import os
import tempfile
import warnings
from typing import Any, Dict, List, Optional, Tuple, Union

import numpy as np
import numpy.typing as npt

from walls import _walls

Path = Union[str, "os.PathLike[str]"]

#: A pkdgrav ``.ss`` record as a NumPy dtype: the fields of pkdgrav's ``SSDATA`` in the
#: file's order, native-endian and packed (96 bytes).
SS_DTYPE = np.dtype(
    [
        ("mass", "f8"),
        ("radius", "f8"),
        ("pos", "f8", (3,)),
        ("vel", "f8", (3,)),
        ("spin", "f8", (3,)),
        ("color", "i4"),
        ("org_idx", "i4"),
    ]
)
assert SS_DTYPE.itemsize == 96

#: The columns of a particles array that is not structured: those of ``walls-sim run
#: --particles`` CSV files, the first 8, 11 or all 12 of them.
CSV_COLUMNS = ("mass", "radius", "x", "y", "z", "vx", "vy", "vz", "wx", "wy", "wz", "color")


def _error(message: str) -> "_walls.WallsError":
    error = _walls.WallsError(message)
    error.diagnostics = []
    return error


def read_ss(path: Path) -> Tuple[float, "npt.NDArray[np.void]"]:
    """Read a pkdgrav ``.ss`` file as ``walls-sim run --particles`` reads it.

    Returns the header's time and the particles as a structured array of
    ``walls.SS_DTYPE`` (``mass``, ``radius``, ``pos``, ``vel``, ``spin``, ``color``,
    ``org_idx``). A reduced file's velocities and spins are 0. A file that cannot be read
    or is not a ``.ss`` file pkdgrav reads raises ``walls.WallsError`` naming the path and
    the byte; subnormal numbers give a ``UserWarning`` (W701).
    """
    time, records, notes = _walls._read_ss(path)
    for note in notes:
        warnings.warn(note, stacklevel=2)
    return time, np.frombuffer(records, dtype=SS_DTYPE).copy()


def _records(particles: Any, name: str) -> "npt.NDArray[np.void]":
    """``particles``, a structured array with the fields of ``SS_DTYPE``, as one of it."""
    array = np.asarray(particles)
    fields = array.dtype.names
    if fields is None:
        raise TypeError(f"{name} must be a structured array with the fields of walls.SS_DTYPE")
    missing = [f for f in SS_DTYPE.names or () if f not in fields]
    if missing:
        raise TypeError(f"{name} has no field {', '.join(missing)} (walls.SS_DTYPE has them all)")
    if array.ndim != 1:
        raise ValueError(f"{name} must be one-dimensional, not of shape {array.shape}")
    out = np.zeros(array.shape, dtype=SS_DTYPE)
    for field in SS_DTYPE.names or ():
        given = np.asarray(array[field])
        integers = out[field].dtype.kind == "i"
        kinds = "iu" if integers else "iuf"
        if given.dtype.kind not in kinds or given.shape != out[field].shape:
            raise TypeError(
                f"{name}[{field!r}] must be {'integers' if integers else 'numbers'} "
                f"of shape {out[field].shape}, not {given.dtype} of shape {given.shape}"
            )
        if integers and given.size and (given.min() < -(2**31) or given.max() >= 2**31):
            raise ValueError(f"{name}[{field!r}] must fit 32 bits")
        out[field] = given
    return out


def write_ss(path: Path, time: float, particles: Any) -> None:
    """Write ``particles`` as a pkdgrav ``.ss`` file at ``path`` with the header's ``time``.

    ``particles`` is a structured array with the fields of ``walls.SS_DTYPE`` (what
    ``read_ss`` gives); the file is made by the tools' one ``.ss`` writer, which
    ``read_ss`` reads back exactly. Particles ``walls-sim run`` would refuse (a mass or
    radius not positive, a number not finite) raise ``walls.WallsError`` before anything
    is written. A regular file at ``path`` is replaced (as ``numpy.save`` does), whole
    or not at all; a device, a FIFO, a folder or a file with hard links is refused with
    ``walls.WallsError``, as the command-line tools refuse them.
    """
    data = _walls._ss_bytes(time, _records(particles, "particles").tobytes())
    _walls._write(path, data)


def _text_of(walls: Union[Path, bytes]) -> Optional[bytes]:
    """The walls file's text when ``walls`` is one rather than a path: ``bytes``, or a
    ``str`` with a line break."""
    if isinstance(walls, bytes):
        return walls
    if isinstance(walls, str) and "\n" in walls:
        return walls.encode()
    return None


class RunResult:
    """What ``walls.run`` returns: the particles at every output (arrays) and the report.

    * ``times``: the time of each output, shape ``(outputs,)``; the first is the start;
    * ``positions``, ``velocities``, ``spins``: shape ``(outputs, particles, 3)``, NaN
      for a particle the run deleted (a death wall);
    * ``particles``: the particles the run started with (``walls.SS_DTYPE``);
    * ``report``: the dict ``walls-sim run --json`` prints (final states, steps, model);
      ``events``, ``energy``, ``stopped`` and ``warnings`` are its entries.
    """

    times: "npt.NDArray[np.float64]"
    positions: "npt.NDArray[np.float64]"
    velocities: "npt.NDArray[np.float64]"
    spins: "npt.NDArray[np.float64]"
    particles: "npt.NDArray[np.void]"
    report: Dict[str, Any]

    def __init__(
        self,
        times: "npt.NDArray[np.float64]",
        states: "npt.NDArray[np.float64]",
        particles: "npt.NDArray[np.void]",
        report: Dict[str, Any],
    ) -> None:
        self.times = times
        self.positions = np.ascontiguousarray(states[:, :, 0, :])
        self.velocities = np.ascontiguousarray(states[:, :, 1, :])
        self.spins = np.ascontiguousarray(states[:, :, 2, :])
        self.particles = particles
        self.report = report

    @property
    def events(self) -> List[Dict[str, Any]]:
        """What happened at walls, as ``walls-sim run --json`` lists it."""
        events: List[Dict[str, Any]] = self.report["events"]
        return events

    @property
    def energy(self) -> Dict[str, float]:
        """The energy at the start and the end (``initial``, ``final``)."""
        energy: Dict[str, float] = self.report["energy"]
        return energy

    @property
    def stopped(self) -> Optional[str]:
        """Why the run stopped early, or None when it ran to its end."""
        stopped: Optional[str] = self.report["stopped"]
        return stopped

    @property
    def warnings(self) -> List[Any]:
        """pkdgrav's warnings about the run, as ``walls-sim run --json`` lists them."""
        found: List[Any] = self.report["warnings"]
        return found

    def __repr__(self) -> str:
        outputs, count = self.positions.shape[:2]
        return (
            f"<walls.RunResult: {count} particles, {outputs} outputs to t = {float(self.times[-1])!r}, "
            f"stopped={self.stopped!r}>"
        )


def _particles_file(particles: Any, folder: str) -> str:
    """A file of ``particles`` in ``folder``: a structured array as a ``.ss`` file, an
    array of the CSV columns as a CSV file, for ``walls-sim run --particles`` to read."""
    array = np.asarray(particles)
    if array.dtype.names is not None:
        path = os.path.join(folder, "particles.ss")
        write_ss(path, 0.0, array)
        return path
    if array.dtype.kind not in "iuf":
        raise TypeError(
            f"particles must be a path, a structured array of walls.SS_DTYPE or an array of numbers, not of {array.dtype}"
        )
    columns = array.shape[1] if array.ndim == 2 else 0
    if columns not in (8, 11, 12):
        raise ValueError(
            "particles must be of shape (n, 8), (n, 11) or (n, 12), the columns "
            f"{','.join(CSV_COLUMNS)}, not {array.shape}"
        )
    path = os.path.join(folder, "particles.csv")
    header = ",".join(CSV_COLUMNS[:columns])
    formats = ["%.17g"] * min(columns, 11) + ["%d"] * (columns - 11)
    np.savetxt(path, array, delimiter=",", header=header, comments="", fmt=formats)
    return path


def run(
    walls: Union[Path, bytes, None],
    particles: Any = None,
    *,
    par: Optional[Path] = None,
    **options: Any,
) -> RunResult:
    """Run particles against the walls as ``walls-sim run`` does, with its options.

    ``walls`` is a walls file's path, or its text (a ``str`` with a line break, or
    ``bytes``); None takes the ``par`` file's achWallsFile. ``particles`` is a path (a
    ``.csv`` or ``.ss`` file), a structured array with the fields of ``walls.SS_DTYPE``,
    or an array of shape (n, 8), (n, 11) or (n, 12) of the CSV columns
    ``mass,radius,x,y,z,vx,vy,vz,wx,wy,wz,color``; None is the command's default (the
    ``par`` file's achInFile, else nine particles dropped onto the scene). ``par`` is a
    pkdgrav ``.par`` file. The keywords are ``walls-sim run``'s options by their long
    names, ``-`` written ``_`` (``t_end=0.5``, ``dt=1e-4``, ``every=10``, ``epsn=0.8``,
    ``gravity=(0, 0, -1)``, ``pkdgrav_build="DEM"``, ``no_edges=True``), with its
    meanings, defaults and checks; None keeps the default.

    Returns a ``walls.RunResult``. Raises ``TypeError`` for an unknown keyword or a
    value of the wrong kind, ``ValueError`` for one the command refuses, and
    ``walls.WallsError`` for input it cannot run (a walls file with errors, with its
    diagnostics; particles or a ``.par`` file it refuses).
    """
    with tempfile.TemporaryDirectory(prefix="walls-run-") as folder:
        walls_path: Optional[Path] = None
        text = None if walls is None else _text_of(walls)
        if text is not None:
            walls_path = os.path.join(folder, "walls.walls")
            with open(walls_path, "wb") as f:
                f.write(text)
        elif walls is not None and not isinstance(walls, bytes):
            walls_path = walls
        particles_path: Optional[Path] = None
        if isinstance(particles, (str, os.PathLike)):
            particles_path = particles
        elif particles is not None:
            particles_path = _particles_file(particles, folder)
        try:
            report, times, states, initial = _walls._run(walls_path, particles_path, par, options)
        except _walls.WallsError as e:
            # The temporary files by what they were made of.
            message = str(e).replace(folder + os.sep + "walls.walls", "<walls text>")
            for name in ("particles.csv", "particles.ss"):
                message = message.replace(folder + os.sep + name, "<particles array>")
            error = _error(message)
            error.diagnostics = e.diagnostics
            raise error from None
    start = np.frombuffer(initial, dtype=SS_DTYPE).copy()
    time = np.frombuffer(times, dtype=np.float64).copy()
    state = np.frombuffer(states, dtype=np.float64).reshape(len(time), len(start), 3, 3)
    return RunResult(time, state, start, report)


class Preview:
    """The interactive page of ``walls.preview``: shown inline by Jupyter
    (``_repr_html_``), written by ``save``; ``html`` is the page."""

    html: str
    height: int

    def __init__(self, page: str, height: int = 520) -> None:
        self.html = page
        self.height = height

    def _repr_html_(self) -> str:
        """The page in an iframe (``srcdoc``): self-contained, its script apart from the
        notebook's."""
        return (
            f'<iframe srcdoc="{html.escape(self.html, quote=True)}" '
            f'style="width: 100%; height: {self.height}px; border: 0" '
            'sandbox="allow-scripts" title="walls preview"></iframe>'
        )

    def save(self, path: Path) -> None:
        """Write the page to ``path`` (an ``.html`` file that needs no network).

        A regular file at ``path`` is replaced, whole or not at all; a device, a FIFO, a
        folder or a file with hard links raises ``walls.WallsError``, as ``write_ss``.
        """
        _walls._write(path, self.html.encode("utf-8"))

    def __repr__(self) -> str:
        return f"<walls.Preview: {len(self.html)} characters of HTML>"


def preview(
    walls: Union[Path, bytes],
    particles: Any = None,
    *,
    until: Optional[float] = None,
    frames: Optional[int] = None,
) -> Preview:
    """The interactive 3D page of ``walls-sim preview --out page.html``.

    ``walls`` is a walls file's path or text (as ``walls.run`` takes it). ``particles``
    is None, a ``walls.RunResult`` (a movie of its outputs), or a structured array with
    the fields of ``walls.SS_DTYPE`` (drawn still). The page covers the times 0 to
    ``until`` (default: a run's last output time, else 0, the walls at rest) in
    ``frames`` frames (default: one per output of a run, at most 300 as
    ``walls-sim preview`` makes a movie, else 101), the walls where their motion puts them and the particles interpolated between their times. A walls file
    with errors raises ``walls.WallsError``.
    """
    text = _text_of(walls)
    if text is None and not isinstance(walls, bytes):
        # As the tools read a walls file: at most their limit, a regular file only.
        text = _walls._read_walls(walls)
    given: Optional[Tuple[List[float], List[int], List[float], bytes]] = None
    if isinstance(particles, RunResult):
        times: List[float] = particles.times.tolist()
        positions = np.ascontiguousarray(particles.positions, dtype=np.float64)
        given = (
            particles.particles["radius"].tolist(),
            particles.particles["color"].tolist(),
            times,
            positions.tobytes(),
        )
        if until is None:
            until = times[-1]
        if frames is None:
            # At most a few hundred, as walls-sim preview makes a movie by default.
            frames = min(len(times), _walls.MOVIE_FRAMES)
    elif particles is not None:
        records = _records(particles, "particles")
        given = (
            records["radius"].tolist(),
            records["color"].tolist(),
            [0.0],
            np.ascontiguousarray(records["pos"], dtype=np.float64).tobytes(),
        )
    page = _walls._preview(
        text or b"",
        given,
        0.0 if until is None else until,
        101 if frames is None else frames,
    )
    return Preview(page)
