# swap.py A B SECONDS: exchanges the names A and B (renameat2 RENAME_EXCHANGE), over and
# over, for SECONDS.
import ctypes, sys, time
libc = ctypes.CDLL(None, use_errno=True)
a, b, end = sys.argv[1].encode(), sys.argv[2].encode(), time.time() + float(sys.argv[3])
while time.time() < end:
    libc.renameat2(-100, a, -100, b, 2)
