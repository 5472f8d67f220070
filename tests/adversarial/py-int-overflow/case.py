# Attack: an integer token past 64 bits, `walls.Wall(color=2**70)` (or 1e20, or NumPy's
# uint64 2**64-1). Before: the builder saturated it and reported 9223372036854775807, a
# number nobody wrote. Now: ValueError naming the token and the range it must be in.
import numpy as np

import walls

RANGE = "from -9223372036854775808 to 9223372036854775807"
for value, shown in [(2**70, "1180591620717411303424"), (-(2**70), "-1180591620717411303424"),
                     (1e20, "1e+20"), (np.uint64(2**64 - 1), "18446744073709551615")]:
    try:
        wall = walls.Wall(color=value)
    except ValueError as e:
        assert str(e) == f"color must be an integer {RANGE}, not {shown}", e
    else:
        raise AssertionError(f"Wall(color={value!r}) gave {wall['color']}")
# The largest integer that fits is kept as it is.
assert walls.Wall(color=2**63 - 1)["color"] == 2**63 - 1
