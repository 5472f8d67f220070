"""A binary STL of N triangles: a relief of squares, each as two triangles."""
import struct
import sys

n, out = int(sys.argv[1]), sys.argv[2]
side = 500
with open(out, "wb") as f:
    f.write(b"\0" * 80 + struct.pack("<I", n))
    k = i = 0
    while k < n:
        x, y = (i % side) * 0.25, (i // side) * 0.25
        z = 0.001 * ((x * 28 + y * 52) % 17)
        a, b = (x, y, z), (x + 0.25, y, z)
        c, d = (x, y + 0.25, z + 0.01), (x + 0.25, y + 0.25, z)
        for t in ((a, b, c), (b, d, c))[: n - k]:
            f.write(struct.pack("<3f", 0, 0, 1))
            for v in t:
                f.write(struct.pack("<3f", *v))
            f.write(b"\0\0")
            k += 1
        i += 1
