#!/usr/bin/env python3
"""Writes the seed corpora of the fuzz targets: tests/fuzz/corpus/<target>/.

The targets decode any bytes into structured inputs (fuzz_scene.hpp), so a
seed need not be crafted: each is a deterministic pseudo-random byte string
(the generator is seeded with the target's name and the seed's number), in
lengths from a few bytes (the decoder's common cases: an exhausted input
reads as zeros) to a kilobyte (every choice made by the bytes). One seed is
empty. Reproducers of defects found by fuzzing are kept next to them as
regress-*; this script neither writes nor removes those.

Run from the repository root:  python3 tests/fuzz/make_seeds.py
"""
import os
import random

TARGETS = ["fuzz_segment_eval", "fuzz_pair_eval", "fuzz_handover", "fuzz_model_update",
           "fuzz_pair_line"]
LENGTHS = [0, 8, 24, 48, 96, 160, 256, 384, 512, 768, 1024]
PER_TARGET = 22


def main():
    root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus")
    for target in TARGETS:
        out = os.path.join(root, target)
        os.makedirs(out, exist_ok=True)
        for name in os.listdir(out):
            if name.startswith("seed-"):
                os.remove(os.path.join(out, name))
        for i in range(PER_TARGET):
            rng = random.Random(f"{target}-{i}")
            n = LENGTHS[i % len(LENGTHS)]
            data = bytes(rng.randrange(256) for _ in range(n))
            with open(os.path.join(out, f"seed-{i:02d}"), "wb") as f:
                f.write(data)


if __name__ == "__main__":
    main()
