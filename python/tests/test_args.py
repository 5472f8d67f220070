"""Every argument of the Python API is converted strictly (docs/python.md, "Arguments"):
a value of the wrong kind raises TypeError, a number out of range or that a double cannot
hold raises ValueError, each naming the argument, and every number is taken exactly (or
rounded once to the nearest double, as a walls file's decimal is).

The issue's reproductions first, then a table of every kind of value (Python's and
NumPy's, every dtype) against every kind of argument, then random values of every NumPy
dtype read back through the API."""

import math
from decimal import Decimal
from fractions import Fraction

import numpy as np
import pytest

import walls

I64 = "from -9223372036854775808 to 9223372036854775807"
U64 = "from 0 to 18446744073709551615"


def refused(call, error, message):
    with pytest.raises(error) as raised:
        call()
    assert type(raised.value) is error
    assert str(raised.value) == message


# The reproductions of the issue.


def test_an_integer_past_64_bits_is_refused_not_saturated():
    refused(lambda: walls.Wall(color=2**70), ValueError,
            f"color must be an integer {I64}, not 1180591620717411303424")
    refused(lambda: walls.Wall(color=1e20), ValueError, f"color must be an integer {I64}, not 1e+20")
    refused(lambda: walls.Wall().set("color", np.uint64(2**64 - 1)), ValueError,
            f"color must be an integer {I64}, not 18446744073709551615")
    refused(lambda: walls.dumps([walls.Wall()], defaults={"assembly": -(2**63) - 1}), ValueError,
            f"assembly must be an integer {I64}, not -9223372036854775809")
    assert walls.Wall(color=2**63 - 1)["color"] == 2**63 - 1
    assert walls.Wall(color=-(2.0**63))["color"] == -(2**63)


def test_a_complex_number_is_not_a_number_here():
    refused(lambda: walls.Wall(radius=np.complex128(1 + 2j)), TypeError,
            "radius must be a number, not numpy.complex128")
    refused(lambda: walls.Wall(radius=np.complex128(1)), TypeError,
            "radius must be a number, not numpy.complex128")
    refused(lambda: walls.Wall(color=3 + 0j), TypeError, "color must be an integer, not complex")


def test_a_number_a_double_cannot_hold_is_refused():
    refused(lambda: walls.Wall(radius=np.longdouble("1e-4000")), ValueError,
            "radius is 1e-4000, too small for a double: it would be read as 0 (write 0 if you mean 0)")
    refused(lambda: walls.Wall(radius=np.longdouble("1e4000")), ValueError,
            "radius is 1e+4000, too large for a double (at most 1.7976931348623157e308)")
    refused(lambda: walls.lint("", dt=Decimal("-1e-400")), ValueError,
            "dt is -1E-400, too small for a double: it would be read as 0 (write 0 if you mean 0)")
    refused(lambda: walls.scene("wall\n", time=10**400), ValueError,
            f"time is {'1' + '0' * 59}… (401 characters), too large for a double (at most 1.7976931348623157e308)")
    refused(lambda: walls.Wall(radius=2**20000), ValueError,
            "radius is an integer of 20001 bits, too large for a double (at most 1.7976931348623157e308)")
    # A subnormal is a double (S110 warns of it in the written file); so is -0.
    assert walls.Wall(radius=np.longdouble("1e-310"))["radius"] == 1e-310
    assert walls.Wall(radius=1e-320)["radius"] == 1e-320
    assert math.copysign(1, walls.Wall(radius=np.longdouble("-0"))["radius"]) == -1


def test_bytes_and_other_sequences_that_are_not_numbers_are_not_vectors():
    refused(lambda: walls.Wall(origin=b"abc"), TypeError, "origin must be a sequence of 3 numbers, not bytes")
    refused(lambda: walls.Wall(origin="abc"), TypeError, "origin must be a sequence of 3 numbers, not str")
    refused(lambda: walls.Wall(origin={1, 2, 3}), TypeError, "origin must be a sequence of 3 numbers, not set")
    refused(lambda: walls.Wall(origin=(x for x in (1, 2, 3))), TypeError,
            "origin must be a sequence of 3 numbers, not generator")
    refused(lambda: walls.Wall(origin=np.array(["1", "2", "3"])), TypeError, "origin[0] must be a number, not str")
    refused(lambda: walls.Wall(origin=[[1, 2, 3]]), TypeError,
            "origin must be a sequence of 3 numbers, not a sequence of 1")
    refused(lambda: walls.from_mesh([(0, 0, 0), (1, 0, 0), (0, 1, 0)], [b"\x00\x01\x02"]), TypeError,
            "faces[0] must be a sequence of 3 vertex indices, not bytes")
    assert walls.Wall(origin=range(3))["origin"] == (0.0, 1.0, 2.0)


def test_a_count_out_of_range_is_a_value_error_as_documented():
    refused(lambda: walls.dumps([], max_walls=-1), ValueError, f"max_walls must be an integer {U64}, not -1")
    refused(lambda: walls.lint("", max_walls=-1), ValueError, f"max_walls must be an integer {U64}, not -1")
    refused(lambda: walls.lint("", max_walls=2**64), ValueError,
            f"max_walls must be an integer {U64}, not 18446744073709551616")
    refused(lambda: walls.format("", indent_width=17), ValueError,
            "indent_width must be an integer from 0 to 16, not 17")
    refused(lambda: walls.from_mesh([], [(0, 1, 2)]), ValueError,
            "faces[0][0] must be an index of vertices, which is empty, not 0")
    refused(lambda: walls.from_mesh([(0, 0, 0)] * 3, [(0, 1, 3)]), ValueError,
            "faces[0][2] must be an index of vertices, from 0 to 2, not 3")


# Every kind of value against every kind of argument.

def strict(v):
    """Whether `scene(strict=v)` refuses a file with an error."""
    try:
        walls.scene("wall\n  raduis 1\n", strict=v)
    except walls.WallsError:
        return True
    return False


# Each kind of argument: a call with the value, and what the call gives back.
SLOTS = {
    "real token": lambda v: walls.Wall(radius=v)["radius"],
    "integer token": lambda v: walls.Wall(color=v)["color"],
    "vector token": lambda v: walls.Wall(origin=(0, v, 0))["origin"][1],
    "number": lambda v: walls.scene("wall\n  velocity 1 0 0\n", time=v)["walls"][0]["position"][0],
    "count": lambda v: walls.format("wall\nradius 1\n", indent_width=v).index("radius") - len("wall\n"),
    "vertex": lambda v: walls.from_mesh([(0, 0, 0), (v, 0, 0), (0, 1, 0)], [(0, 1, 2)])[0]["vertex1"][0],
    "index": lambda v: walls.from_mesh([(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)], [(0, 1, v)])[0]["vertex2"],
    "flag": lambda v: strict(v),
    "word": lambda v: walls.dumps([walls.Wall()], comment=v),
}
NUMBERS = ["real token", "vector token", "number", "vertex"]
INTEGERS = ["integer token", "count", "index"]


def kinds():
    """(value, the slots that take it, its type's name as a TypeError shows it)."""
    every = set(SLOTS)
    yield True, {"flag"}, "bool"
    yield np.bool_(False), {"flag"}, "numpy.bool"
    yield 3, set(NUMBERS + INTEGERS), "int"
    yield 3.0, set(NUMBERS) | {"integer token"}, "float"
    yield Fraction(3), set(NUMBERS) | {"integer token"}, "fractions.Fraction"
    yield Decimal(3), set(NUMBERS) | {"integer token"}, "decimal.Decimal"
    for t in [np.int8, np.int16, np.int32, np.int64, np.uint8, np.uint16, np.uint32, np.uint64]:
        yield t(3), set(NUMBERS + INTEGERS), f"numpy.{t.__name__}"
        yield np.array(3, dtype=t), set(NUMBERS + INTEGERS), "numpy.ndarray"
    for t in [np.float16, np.float32, np.float64, np.longdouble]:
        yield t(3), set(NUMBERS) | {"integer token"}, f"numpy.{t.__name__}"
        yield np.array(3, dtype=t), set(NUMBERS) | {"integer token"}, "numpy.ndarray"
    for t in [np.complex64, np.complex128, np.clongdouble]:
        yield t(3), set(), f"numpy.{t.__name__}"
    yield 3 + 0j, set(), "complex"
    yield "3", {"word"}, "str"
    yield np.str_("3"), {"word"}, "numpy.str_"
    yield b"3", set(), "bytes"
    yield np.bytes_(b"3"), set(), "numpy.bytes_"
    yield np.datetime64(3, "ns"), set(), "numpy.datetime64"
    yield np.timedelta64(3, "s"), set(), "numpy.timedelta64"
    yield np.void(b"\x03"), set(), "numpy.void"
    yield np.array(3, dtype=object), set(NUMBERS + INTEGERS), "numpy.ndarray"
    # None is the default of the optional arguments (time=None, indent_width=None).
    yield None, set(), "NoneType"
    yield [3], set(), "list"
    assert every


@pytest.mark.parametrize("slot", sorted(SLOTS))
def test_every_kind_of_value_is_taken_exactly_or_refused(slot):
    what = {
        "real token": "radius must be a number",
        "integer token": "color must be an integer",
        "vector token": "origin[1] must be a number",
        "number": "time must be a number",
        "count": "indent_width must be an integer",
        "vertex": "vertices[1][0] must be a number",
        "index": "faces[0][2] must be an integer",
        "flag": "strict must be True or False",
        "word": "comment must be a str",
    }[slot]
    for value, takes, name in kinds():
        if value is None and slot in ("number", "count", "word"):
            continue
        if slot in takes:
            got = SLOTS[slot](value)
            if slot == "index":
                assert got == (0.0, 0.0, 1.0), (value, got)
            elif slot == "word":
                assert got == "# 3\n\nwall\n", (value, got)
            elif slot == "flag":
                assert got is bool(value)
            else:
                assert got == 3 and type(got) in (int, float), (value, got)
        else:
            with pytest.raises(TypeError) as raised:
                SLOTS[slot](value)
            assert str(raised.value) == f"{what}, not {name}", value


@pytest.mark.parametrize("slot", NUMBERS + ["integer token"])
@pytest.mark.parametrize("value", [float("nan"), float("inf"), -np.inf, np.float32("nan"),
                                   np.longdouble("inf"), Decimal("NaN"), Decimal("sNaN")])
def test_nan_and_infinities_are_value_errors(slot, value):
    with pytest.raises(ValueError, match="must be a finite number, not "):
        SLOTS[slot](value)


def test_a_fraction_is_not_an_integer():
    refused(lambda: walls.Wall(color=12.5), ValueError,
            "color must be an integer, not 12.5 (pkdgrav would read it with atoi, dropping the fraction)")
    # Rounding to a double would make it whole: the value is refused as it is.
    near = np.longdouble(3) + np.longdouble(2) ** -60
    refused(lambda: walls.Wall(color=near), ValueError,
            f"color must be an integer, not {str(near)} (pkdgrav would read it with atoi, dropping the fraction)")
    refused(lambda: walls.Wall(color=Fraction(7, 2)), ValueError,
            "color must be an integer, not 7/2 (pkdgrav would read it with atoi, dropping the fraction)")
    refused(lambda: walls.from_mesh([(0, 0, 0)] * 3, np.array([(0.0, 1.0, 2.0)])), TypeError,
            "faces[0][0] must be an integer, not float")


def test_numpy_arrays_of_every_dtype():
    for dtype in [np.int8, np.uint16, np.int64, np.uint64, np.float16, np.float32, np.float64,
                  np.longdouble, object]:
        wall = walls.Wall(origin=np.array([1, 2, 3], dtype=dtype))
        assert wall["origin"] == (1.0, 2.0, 3.0), dtype
    for dtype, name in [(bool, "bool"), (complex, "complex"), (np.clongdouble, "numpy.clongdouble"),
                        ("U1", "str"), ("S1", "bytes")]:
        refused(lambda: walls.Wall(origin=np.ones(3, dtype=dtype)), TypeError,
                f"origin[0] must be a number, not {name}")
    for dtype in ["M8[D]", "m8[s]", [("x", "f8")]]:
        refused(lambda: walls.Wall(origin=np.zeros(3, dtype=dtype)), TypeError,
                "origin must be a sequence of 3 numbers, not numpy.ndarray")
    # A masked item is no number; a 0-d object array holding itself is not followed.
    refused(lambda: walls.Wall(origin=np.ma.array([1, 2, 3], mask=[0, 1, 0])), TypeError,
            "origin[1] must be a number, not NoneType")
    itself = np.empty((), dtype=object)
    itself[()] = itself
    refused(lambda: walls.Wall(radius=itself), TypeError, "radius must be a number, not numpy.ndarray")
    # Meshes: any integer dtype for faces, any real dtype for vertices.
    for faces in [np.array([[0, 1, 2]], dtype=t) for t in (np.uint8, np.int32, np.uint64)]:
        (wall,) = walls.from_mesh(np.eye(3, dtype=np.float32), faces)
        assert wall["vertex1"] == (-1.0, 1.0, 0.0)


def test_random_values_of_every_numpy_dtype_read_back_exactly():
    rng = np.random.default_rng(40)
    for t in [np.int8, np.int16, np.int32, np.int64, np.uint8, np.uint16, np.uint32, np.uint64]:
        info = np.iinfo(t)
        for x in rng.integers(info.min, info.max, size=200, dtype=t, endpoint=True):
            if info.min <= x <= 2**63 - 1:
                assert walls.Wall(color=x)["color"] == int(x)
            else:
                with pytest.raises(ValueError, match=f"color must be an integer {I64}"):
                    walls.Wall(color=x)
            assert walls.Wall(radius=x)["radius"] == float(int(x))
    for t in [np.float16, np.float32, np.float64]:
        bits = rng.integers(0, 2 ** (8 * np.dtype(t).itemsize), size=500, dtype=np.uint64)
        for x in bits.astype({2: np.uint16, 4: np.uint32, 8: np.uint64}[np.dtype(t).itemsize]).view(t):
            if np.isfinite(x):
                assert walls.Wall(radius=x)["radius"] == float(x)
                assert walls.Wall(origin=np.array([x, 0, 0], dtype=t))["origin"][0] == float(x)
            else:
                with pytest.raises(ValueError, match="must be a finite number"):
                    walls.Wall(radius=x)
    # longdouble: from far below the smallest subnormal double to far above the largest.
    for exponent in rng.integers(-4900, 4900, size=500):
        x = np.longdouble(rng.random()) * np.longdouble(2) ** int(exponent)
        nearest = float(x) if abs(x) <= np.finfo(np.float64).max else math.inf
        if nearest == 0 and x != 0:
            with pytest.raises(ValueError, match="too small for a double"):
                walls.Wall(radius=x)
        elif math.isinf(nearest):
            with pytest.raises(ValueError, match="too large for a double"):
                walls.Wall(radius=x)
        else:
            assert walls.Wall(radius=x)["radius"] == nearest


def test_flags_and_names_take_only_their_kind():
    refused(lambda: walls.scene("wall\n", strict=None), TypeError, "strict must be True or False, not NoneType")
    refused(lambda: walls.format("", keep_blank_lines=0), TypeError,
            "keep_blank_lines must be True or False, not int")
    refused(lambda: walls.from_mesh([], [], merge_rectangles=1), TypeError,
            "merge_rectangles must be True or False, not int")
    refused(lambda: walls.lint("", mode=b"ssdem"), TypeError, 'mode must be "ssdem" or "hsdem", not bytes')
    refused(lambda: walls.lint("", mode="SSDEM"), ValueError, 'mode must be "ssdem" or "hsdem", not "SSDEM"')
    refused(lambda: walls.dumps([], mode=None), TypeError, 'mode must be "ssdem" or "hsdem", not NoneType')
    refused(lambda: walls.from_mesh([], [], orientation=b"keep"), TypeError,
            'orientation must be "keep", "outward" or "inward", not bytes')
    refused(lambda: walls.Wall(type=b"disk"), TypeError, "type must be a wall type name, not bytes")
    refused(lambda: walls.Wall().set(b"radius", 1), TypeError, "a token's name must be a str, not bytes")
    refused(lambda: walls.Wall()[0], TypeError, "a token's name must be a str, not int")
    refused(lambda: walls.dumps([], defaults={1: 2}), TypeError, "a token's name must be a str, not int")
    refused(lambda: walls.dumps([], units=b"cm"), TypeError,
            "units must be a length unit's name or a dict of unit tokens, not bytes")
    refused(lambda: walls.dumps(walls.Wall()), TypeError, "walls must be an iterable of Wall objects, not walls.Wall")
    refused(lambda: walls.dumps([walls.Wall(), {}]), TypeError, "walls[1] must be a Wall, not dict")
    refused(lambda: walls.read_mesh(b"hull.stl"), TypeError, "path must be a str or an os.PathLike, not bytes")
    # None keeps the default where the signature says None.
    assert walls.format("wall\n", indent_width=None, keep_blank_lines=None) == "wall\n"
    assert walls.lint("wall\n", max_walls=None, min_radius=None, dt=None) == []


def test_the_builders_refusals_are_value_errors():
    refused(lambda: walls.Wall(raduis=1), ValueError, "unknown keyword `raduis`: did you mean `radius`?")
    refused(lambda: walls.Wall(raduis=1 + 2j), ValueError, "unknown keyword `raduis`: did you mean `radius`?")
    refused(lambda: walls.Wall(type="trangle"), ValueError, "unknown wall type `trangle`: did you mean `triangle`?")
    refused(lambda: walls.dumps([], units={"mass": 1}), ValueError,
            "`mass` is not a unit: the units are lengthunit, massunit and timeunit")


def test_a_sequence_is_measured_before_it_is_read():
    # A vector given 10**8 numbers is refused without a list of them.
    refused(lambda: walls.Wall(origin=np.zeros(10**8)), TypeError,
            "origin must be a sequence of 3 numbers, not a sequence of 100000000")
    # A Sequence whose items never end (or end early) is not read past its length.
    from collections.abc import Sequence

    class Endless(Sequence):
        def __len__(self):
            return 3

        def __getitem__(self, i):
            return 1.0

    class Short(Endless):
        def __getitem__(self, i):
            if i >= 2:
                raise IndexError(i)
            return 1.0

    refused(lambda: walls.Wall(origin=Endless()), TypeError,
            "origin must be a sequence of 3 numbers: its length is 3 but it holds more items")
    refused(lambda: walls.Wall(origin=Short()), TypeError,
            "origin must be a sequence of 3 numbers: its length is 3 but it holds fewer items")
    refused(lambda: walls.Wall(origin=__import__("itertools").count()), TypeError,
            "origin must be a sequence of 3 numbers, not itertools.count")


def test_text_that_is_not_utf8_and_paths_with_nul_are_named():
    for call, name in [
        (lambda: walls.lint("wall\ud800\n"), "text"),
        (lambda: walls.format("wall\ud800\n"), "text"),
        (lambda: walls.dumps([walls.Wall()], comment="\ud800"), "comment"),
        (lambda: walls.Wall(type="\udcff"), "type"),
        (lambda: walls.lint("", mode="\ud800"), "mode"),
    ]:
        with pytest.raises(ValueError) as raised:
            call()
        assert str(raised.value).startswith(f"{name} is not UTF-8 text: 'utf-8' codec can't encode"), raised.value
    refused(lambda: walls.read_mesh("hull\x00.stl"), ValueError, "path must not hold a NUL character")
    refused(lambda: walls.lint(bytearray(b"wall\n")), TypeError, "text must be str or bytes, not bytearray")
    # bytes and str subclasses are bytes and str (NumPy's bytes_ and str_).
    assert walls.lint(np.bytes_(b"wall\n")) == walls.lint(np.str_("wall\n")) == []


def test_the_console_scripts_entry_takes_only_a_tools_name():
    from walls._walls import run_tool

    refused(lambda: run_tool("walls-x", ["walls-x"]), ValueError,
            'tool must be "walls-lint", "walls-fmt", "walls-sim", "walls-mesh" or "walls-lsp", not "walls-x"')
    refused(lambda: run_tool(b"walls-lint", ["walls-lint"]), TypeError,
            'tool must be "walls-lint", "walls-fmt", "walls-sim", "walls-mesh" or "walls-lsp", not bytes')
