#!/usr/bin/env python3
"""Same results, face for face: segments generated parts with two meshseg
binaries and compares the result JSONs (every face label, and every other
field: region types, surface parameters, rms, topology), and their bytes. A
speed change that keeps the arithmetic prints "differ 0" and "bytes same" on
every line.

usage: same_results.py OLD_MESHSEG NEW_MESHSEG [DIR]
  parts test_piece small_block stepped_shaft plate_boss rounded_prism
  torus_ring at noise 0, 0.05 and 0.15 h (default voxel size), and the
  1M-face test_piece (--voxel-size 0.21 --noise 0.05). Meshes and the old
  binary's results are kept in DIR (default /tmp/same_results) and reused.
"""
import json
import os
import subprocess
import sys

PARTS = ["test_piece", "small_block", "stepped_shaft", "plate_boss", "rounded_prism", "torus_ring"]
NOISES = ["0", "0.05", "0.15"]


def differences(a, b, path, out):
    """Appends (path, what) for every field where a and b differ."""
    if isinstance(a, dict) and isinstance(b, dict):
        for k in sorted(set(a) | set(b)):
            if k not in a or k not in b:
                out.append((path + "/" + k, "missing on one side"))
            else:
                differences(a[k], b[k], path + "/" + k, out)
    elif isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            out.append((path, "length %d vs %d" % (len(a), len(b))))
            return
        for i, (x, y) in enumerate(zip(a, b)):
            differences(x, y, "%s[%d]" % (path, i), out)
    elif a != b:
        out.append((path, "%r vs %r" % (a, b)))


def run(args):
    subprocess.run(["nice"] + args, check=True, stdout=subprocess.DEVNULL)


def main():
    if len(sys.argv) < 3:
        print(__doc__)
        return 2
    old, new = sys.argv[1], sys.argv[2]
    work = sys.argv[3] if len(sys.argv) > 3 else "/tmp/same_results"
    os.makedirs(work, exist_ok=True)
    cases = [(p + "_" + n, ["generate", p, "--noise", n]) for p in PARTS for n in NOISES]
    cases.append(("test_piece_1M", ["generate", "test_piece", "--voxel-size", "0.21", "--noise",
                                    "0.05"]))
    failed = 0
    for name, generate in cases:
        mesh = os.path.join(work, name + ".ply")
        before = os.path.join(work, name + ".old.json")
        after = os.path.join(work, name + ".new.json")
        if not os.path.exists(mesh):
            run([old] + generate + ["-o", mesh])
        if not os.path.exists(before):
            run([old, "segment", mesh, "-o", before])
        run([new, "segment", mesh, "-o", after])
        a, b = json.load(open(before)), json.load(open(after))
        fa, fb = a.get("face_labels", []), b.get("face_labels", [])
        faces = sum(x != y for x, y in zip(fa, fb)) + abs(len(fa) - len(fb))
        out = []
        differences(a, b, "", out)
        same_bytes = open(before, "rb").read() == open(after, "rb").read()
        print("%-20s faces %8d  labels differ %d  fields differ %d  bytes %s" %
              (name, len(fa), faces, len(out), "same" if same_bytes else "DIFFER"))
        for path, what in out[:5]:
            print("    %s: %s" % (path, what))
        failed += bool(out) or not same_bytes
    print("SAME" if failed == 0 else "%d cases DIFFER" % failed)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
