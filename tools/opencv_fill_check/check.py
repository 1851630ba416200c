#!/usr/bin/python3
"""Compares load_houseexpo()'s polygon fill (src/world/polygon_fill.hpp) with OpenCV's own
cv2.drawContours, as HouseExpo's PseudoSLAM draws plans (jsonReader.py: vertices * meter2pixel,
astype(int), shifted, filled contour), here with a one-pixel border as the loader adds.

Not part of the build or of `make test` (OpenCV is not a project dependency). To run it:
  apt-get install -y python3-opencv
  g++ -std=c++20 -O1 -I build/dev/include_roots/world -I build/dev/include_roots/core \\
      tools/opencv_fill_check/map_dump.cpp build/dev/libfsweep_world.a build/dev/libfsweep_core.a \\
      -lyaml-cpp -o /tmp/map_dump
  /usr/bin/python3 tools/opencv_fill_check/check.py /tmp/map_dump [--polygons 2000]
Prints the cells that differ per case; on 2026-12-03 (OpenCV 4.6): 0 of 2,000 random polygons
and 0 of the 10 plan/resolution pairs of tests/data/houseexpo differed.
"""
import argparse, glob, json, os, random, subprocess, tempfile
import cv2
import numpy as np


def opencv_rows(verts, cells_per_metre):
    v = (np.array(verts) * cells_per_metre).astype(int)
    x_min, y_min = v[:, 0].min(), v[:, 1].min()
    img = np.zeros((v[:, 1].max() - y_min + 3, v[:, 0].max() - x_min + 3), np.uint8)
    v[:, 0] -= x_min - 1
    v[:, 1] -= y_min - 1
    cv2.drawContours(img, [v.astype(np.int32)], 0, 255, -1)
    return ["".join("1" if c == 255 else "0" for c in row) for row in img]


def our_rows(dump, path, res):
    out = subprocess.run([dump, path, repr(res)], capture_output=True, text=True, check=True)
    return out.stdout.split()


def differing(a, b):
    if len(a) != len(b) or len(a[0]) != len(b[0]):
        return -1  # sizes differ
    return sum(x != y for ra, rb in zip(a, b) for x, y in zip(ra, rb))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("dump")
    ap.add_argument("--polygons", type=int, default=2000)
    ap.add_argument("--seed", type=int, default=1)
    args = ap.parse_args()
    root = os.path.join(os.path.dirname(__file__), "..", "..")
    bad = 0
    for path in sorted(glob.glob(os.path.join(root, "tests/data/houseexpo/*.json"))):
        for m2p in (25, 20, 10, 5, 4):
            verts = json.load(open(path))["verts"]
            d = differing(opencv_rows(verts, m2p), our_rows(args.dump, path, 1 / m2p))
            print(f"{os.path.basename(path)} at {1 / m2p} m: {d} cells differ")
            bad += d != 0
    rng = random.Random(args.seed)
    with tempfile.TemporaryDirectory() as tmp:
        plan = os.path.join(tmp, "p.json")
        for _ in range(args.polygons):
            verts = [[rng.randint(0, 40), rng.randint(0, 40)] for _ in range(rng.randint(3, 9))]
            json.dump({"verts": verts}, open(plan, "w"))
            d = differing(opencv_rows(verts, 1), our_rows(args.dump, plan, 1.0))
            if d != 0:
                bad += 1
                print(f"differs ({d} cells): {verts}")
    print(f"{bad} cases differ")
    return 1 if bad else 0


if __name__ == "__main__":
    raise SystemExit(main())
