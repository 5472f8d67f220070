# Attack: a vector with no end, `walls.Wall(origin=itertools.count())`, or one far too long,
# `walls.Wall(origin=np.zeros(10**8))`. Before: the extension read every item it was given
# before saying a vector has 3: itertools.count() without end (the process grew by 4 MB a
# second), np.zeros(3 * 10**7) in 61 s and 946 MB. Now: a vector is a sequence whose
# length is asked first: an iterator is refused at once, a length other than 3 without
# reading an item.
import itertools
import resource
import time

import numpy as np

import walls

start = time.monotonic()
for value, message in [
    (itertools.count(), "origin must be a sequence of 3 numbers, not itertools.count"),
    (np.zeros(10**8), "origin must be a sequence of 3 numbers, not a sequence of 100000000"),
]:
    try:
        walls.Wall(origin=value)
    except TypeError as e:
        assert str(e) == message, e
    else:
        raise AssertionError(f"Wall(origin={value!r}) was accepted")
took = time.monotonic() - start
assert took < 1, f"took {took:.1f} s"
peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
assert peak < 500, f"peak {peak:.0f} MB"
