#!/usr/bin/env python3
"""Runs a command and prints its wall and CPU (user + system) seconds, to the microsecond.

    python3 benches/embree/timeproc.py COMMAND [ARGS...]

`/usr/bin/time` rounds to 10 ms, the size of a whole tetra render; this reads the child's
rusage instead. The command's output goes where this process's goes; a failing command
makes this exit with its status.
"""

import resource
import subprocess
import sys
import time


def main():
    if len(sys.argv) < 2:
        sys.exit("usage: timeproc.py COMMAND [ARGS...]")
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    code = subprocess.call(sys.argv[1:])
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    if code != 0:
        sys.exit(code)
    print(f"{wall:.6f} {cpu:.6f}")


if __name__ == "__main__":
    main()
