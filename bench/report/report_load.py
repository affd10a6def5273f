#!/usr/bin/env python3
"""Timing tool: how a large HTML report loads and responds in Chromium.

    python3 bench/report/report_load.py REPORT.html [--frames N]

Opens the report in headless Chromium (Debian's `chromium`, software WebGL
through SwiftShader: no GPU) with #bench=N and prints the file size, the time
from navigation to the page being ready (decoding the base64 buffers,
uploading them, the first frame), the mean time of an orbit frame and of a
pick right after the view moved. A browser on a GPU draws much faster than
SwiftShader; the load time is mostly JavaScript and holds there too.
Make a large report with e.g.
    build/bin/meshseg generate test_piece -o big.ply --voxel-size 0.1
    build/bin/meshseg segment big.ply -o big.json --report big.html
"""

import argparse
import os
import re
import shutil
import subprocess
import tempfile
import time

FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync",
         "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--window-size=1280,900",
         "--force-device-scale-factor=1", "--virtual-time-budget=600000", "--dump-dom"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("report")
    parser.add_argument("--frames", type=int, default=10)
    args = parser.parse_args()
    faces = 0
    with open(args.report) as f:
        m = re.search(r'"face_count":"?(\d+)', f.read(1 << 20))
        faces = int(m.group(1)) if m else 0
    with tempfile.TemporaryDirectory() as profile:
        start = time.monotonic()
        run = subprocess.run([shutil.which("chromium"), *FLAGS, f"--user-data-dir={profile}",
                              "file://" + os.path.abspath(args.report) + f"#bench={args.frames}"],
                             capture_output=True, text=True, timeout=900)
        wall = time.monotonic() - start
    body = dict(re.findall(r'data-([a-z-]+)="([^"]*)"', re.search(r"<body([^>]*)>",
                                                                  run.stdout).group(1)))
    print(f"report      {os.path.getsize(args.report) / 2**20:.1f} MiB, {faces} faces")
    print(f"state       {body.get('state')} (webgl {body.get('webgl')})")
    print(f"load        {body.get('load-ms')} ms (navigation to ready)")
    print(f"frame       {body.get('frame-ms')} ms (orbit, mean of {args.frames})")
    print(f"pick        {body.get('pick-ms')} ms (after a view change, mean of {args.frames})")
    print(f"chromium    {wall:.1f} s wall in all")


if __name__ == "__main__":
    main()
