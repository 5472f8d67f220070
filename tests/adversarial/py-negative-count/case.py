# Attack: a count out of range, `walls.lint(text, max_walls=-1)` (and 2**70, and an
# indent width of -1). Before: OverflowError ("can't convert negative int to unsigned"),
# naming no argument, where docs/python.md says a bad value raises ValueError. Now:
# ValueError naming the argument and its range.
import walls

for call, message in [
    (lambda: walls.lint("", max_walls=-1), "max_walls must be an integer from 0 to 18446744073709551615, not -1"),
    (lambda: walls.lint("", max_walls=2**70),
     "max_walls must be an integer from 0 to 18446744073709551615, not 1180591620717411303424"),
    (lambda: walls.dumps([], max_walls=-1), "max_walls must be an integer from 0 to 18446744073709551615, not -1"),
    (lambda: walls.format("", indent_width=-1), "indent_width must be an integer from 0 to 16, not -1"),
    (lambda: walls.from_mesh([(0, 0, 0)] * 3, [(0, 1, -1)]),
     "faces[0][2] must be an index of vertices, from 0 to 2, not -1"),
]:
    try:
        got = call()
    except ValueError as e:
        assert str(e) == message, e
    else:
        raise AssertionError(f"accepted, gave {got!r}; expected ValueError: {message}")
