#!/usr/bin/env python3
"""Writes one seed of fuzz/corpus/render_small/ per combination class of fuzz/render_small.cpp:
class-K holds pseudo-random bytes (seeded by K, so the files are the same on every run) ending in the
two bytes the harness reads first, K (FuzzedDataProvider takes its integers from the end, most
significant byte last). A mesh the bytes make degenerate is replaced by the harness's facing quad, so
every seed draws.
Usage: fuzz/render_small_seeds.py fuzz/corpus/render_small"""
import os
import random
import sys

CLASS_COUNT = 5 * 3 * 2 * 2 * 3 * 5  # render_small.cpp's class_count


def main(folder):
    os.makedirs(folder, exist_ok=True)
    for k in range(CLASS_COUNT):
        rng = random.Random(k)
        body = bytes(rng.randrange(256) for _ in range(400))
        with open(os.path.join(folder, f"class-{k:03d}"), "wb") as f:
            f.write(body + bytes([k & 0xFF, k >> 8]))


if __name__ == "__main__":
    main(sys.argv[1])
