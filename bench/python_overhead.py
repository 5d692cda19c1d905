"""What the Python module costs over fb89's C++: a render of the demo through fb89.render()
against the same render done from C++ (the module's _bench_render), interleaved round by
round; and a stream of about a million commands read into numpy by fb89.Stream.open()
against the stream reader alone (_bench_read), interleaved. Prints medians and ratios.

    PYTHONPATH=build/python /usr/bin/python3 bench/python_overhead.py [--rounds N] [--scene S]

docs/PYTHON.md quotes its figures. Speed is measured here, never asserted in a test.
"""
import argparse
import os
import statistics
import tempfile
import time

import numpy as np

import fb89
from fb89 import _fb89


def render_overhead(scene, method, rounds):
    python, cpp = [], []
    fb89.render(scene, method=method)  # warm-up: the scene file in the page cache
    for i in range(rounds):
        def through_python():
            start = time.perf_counter()
            fb89.render(scene, method=method)
            python.append(time.perf_counter() - start)

        def from_cpp():
            cpp.extend(_fb89._bench_render(scene, method, 1))

        for run in ((through_python, from_cpp) if i % 2 == 0 else (from_cpp, through_python)):
            run()
    return statistics.median(python), statistics.median(cpp)


def stream_speed(rounds, folder):
    """A stream of about a million commands: the demo's frame repeated."""
    frame = fb89.render("demo", method="zbuffer").commands
    copies = 1_000_000 // len(frame) + 1
    rows = np.concatenate([frame] * copies)
    rows["frame"][rows["opcode"] == fb89.FRAME_BEGIN] = np.arange(copies)
    path = os.path.join(folder, "million.fb89")
    fb89.Stream(rows).save(path)
    opened, reader = [], []
    for i in range(rounds):
        def open_it():
            start = time.perf_counter()
            s = fb89.Stream.open(path)
            opened.append(len(s) / (time.perf_counter() - start))
            assert s.commands.shape == (len(rows),)

        def read_it():
            n, seconds = _fb89._bench_read(path)
            reader.append(n / seconds)

        for run in ((open_it, read_it) if i % 2 == 0 else (read_it, open_it)):
            run()
    return len(rows), statistics.median(opened), statistics.median(reader)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--rounds", type=int, default=41, help="interleaved rounds (median)")
    parser.add_argument("--scene", default="demo")
    parser.add_argument("--method", default="zbuffer")
    args = parser.parse_args()
    python, cpp = render_overhead(args.scene, args.method, args.rounds)
    print(f"render {args.scene} {args.method}: fb89.render() {python * 1e3:.3f} ms, "
          f"the same from C++ {cpp * 1e3:.3f} ms (medians of {args.rounds}): "
          f"Python adds {100 * (python / cpp - 1):+.2f}%")
    with tempfile.TemporaryDirectory() as folder:
        n, opened, reader = stream_speed(args.rounds, folder)
    print(f"stream of {n:,} commands: Stream.open() {opened / 1e6:.1f} M commands/s into numpy, "
          f"the reader alone {reader / 1e6:.1f} M/s (medians of {args.rounds})")


if __name__ == "__main__":
    main()
