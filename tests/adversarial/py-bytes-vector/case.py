# Attack: bytes for a vector, `walls.Wall(origin=b"abc")` (a bytes object is a sequence
# of small ints), and sets, whose order is Python's. Before: the origin was
# (97, 98, 99), and from_mesh took b"abc" as a point. Now: TypeError naming the token:
# bytes, str and other non-number sequences are not vectors.
import walls

for value, kind in [(b"abc", "bytes"), (bytearray(b"abc"), "bytearray"), (memoryview(b"abc"), "memoryview"),
                    ("abc", "str"), ({1.0, 2.0, 3.0}, "set"), (iter([1, 2, 3]), "list_iterator")]:
    try:
        wall = walls.Wall(origin=value)
    except TypeError as e:
        assert str(e) == f"origin must be a sequence of 3 numbers, not {kind}", e
    else:
        raise AssertionError(f"Wall(origin={value!r}) gave {wall['origin']}")
try:
    walls.from_mesh([b"abc", (1, 0, 0), (0, 1, 0)], [(0, 1, 2)])
except TypeError as e:
    assert str(e) == "vertices[0] must be a sequence of 3 numbers, not bytes", e
else:
    raise AssertionError("from_mesh took b'abc' for a point")
