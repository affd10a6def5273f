"""The HTML report as a person opens it: headless Chromium (Debian's
`chromium`) loads report.html from disk with no network. The page must come
up with WebGL, one table row per region, a canvas showing the regions'
colours (checked on a screenshot), and GPU picking that finds the face under
a pixel with that face's label from the result."""

import base64
import json
import os
import re
import shutil
import subprocess
import unittest

from PIL import Image

import harness

# Chromium offline and quiet: without these it tries to reach Google's
# services and can hang. SwiftShader gives WebGL without a GPU.
CHROMIUM_FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
                  "--no-first-run", "--disable-background-networking",
                  "--disable-component-update", "--disable-sync",
                  "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
                  "--hide-scrollbars", "--force-device-scale-factor=1"]
WINDOW = (1280, 900)
# Rendering runs on virtual time; this bounds it.
VIRTUAL_TIME_MS = 10000
CHROMIUM_TIMEOUT_S = 120
# The page's canvas background (report.css / viewer.js clear colour).
BACKGROUND = (238, 241, 244)
# A region colour counts as shown when this many canvas pixels have its hue.
MIN_PIXELS_PER_COLOUR = 30


def chromium(url, profile, *args):
    exe = shutil.which("chromium")
    if exe is None:
        raise AssertionError("chromium is not installed (scripts/setup.sh installs it)")
    run = subprocess.run([exe, *CHROMIUM_FLAGS, f"--user-data-dir={profile}",
                          f"--window-size={WINDOW[0]},{WINDOW[1]}",
                          f"--virtual-time-budget={VIRTUAL_TIME_MS}", *args, url],
                         capture_output=True, text=True, timeout=CHROMIUM_TIMEOUT_S,
                         stdin=subprocess.DEVNULL)
    if run.returncode != 0:
        raise AssertionError(f"chromium exited {run.returncode}: {run.stderr[-2000:]}")
    return run.stdout


def body_attributes(dom):
    body = re.search(r"<body([^>]*)>", dom).group(1)
    return dict(re.findall(r'data-([a-z-]+)="([^"]*)"', body))


def embedded_colors(html):
    """The region colours the page carries (rgb per region index)."""
    data = re.search(r'id="meshseg-colors">([^<]*)<', html).group(1)
    raw = base64.b64decode(data)
    return [tuple(raw[i:i + 3]) for i in range(0, len(raw), 3)]


def chromaticity(rgb):
    s = float(sum(rgb)) or 1.0
    return (rgb[0] / s, rgb[1] / s)


class ReportInChromiumTest(harness.ScratchTestCase):
    @classmethod
    def setUpClass(cls):
        cls.work = harness.ScratchTestCase()
        cls.work.setUp()
        part = cls.work.path("test_piece.ply")
        harness.run_meshseg("generate", "test_piece", "-o", part, "--voxel-size", "1.0")
        cls.report = cls.work.path("report.html")
        harness.run_meshseg("segment", part, "-o", cls.work.path("result.json"), "--report",
                            cls.report)
        with open(cls.work.path("result.json")) as f:
            cls.result = json.load(f)
        with open(cls.report) as f:
            cls.html = f.read()
        # One load for the DOM, one for the screenshot, shared by the tests.
        cls.dom = chromium(cls.url(), cls.work.path("profile_dom"), "--dump-dom")
        cls.shot = cls.work.path("shot.png")
        chromium(cls.url(), cls.work.path("profile_shot"), f"--screenshot={cls.shot}")

    @classmethod
    def tearDownClass(cls):
        cls.work.doCleanups()

    @classmethod
    def url(cls, hash_=""):
        return "file://" + os.path.abspath(cls.report) + hash_

    def test_page_is_self_contained(self):
        self.assertNotRegex(self.html, r'(src|href)="(https?:)?//', "nothing from the network")
        self.assertIn('id="meshseg-positions"', self.html)

    def test_table_has_one_row_per_region_and_webgl_runs(self):
        dom = self.dom
        attrs = body_attributes(dom)
        self.assertEqual(attrs.get("state"), "ready", dom[-3000:])
        self.assertEqual(attrs.get("webgl"), "yes")
        regions = self.result["regions"]
        tbody = re.search(r'<table id="regions".*?<tbody>(.*?)</tbody>', dom, re.S).group(1)
        self.assertEqual(len(re.findall(r"<tr ", tbody)), len(regions))
        self.assertEqual(int(attrs["region-rows"]), len(regions))
        self.assertEqual(sorted(int(i) for i in re.findall(r'<tr data-region="(\d+)"', tbody)),
                         list(range(len(regions))))
        features = re.search(r'<ul id="features">(.*?)</ul>', dom, re.S).group(1)
        self.assertEqual(features.count("<li"), max(1, len(self.result.get("features", []))))

    def test_canvas_shows_the_region_colours(self):
        # The rectangle of the DOM load: the screenshot's viewport is at
        # least as tall, so it lies inside the canvas there too.
        x, y, w, h = map(int, body_attributes(self.dom)["canvas-rect"].split(","))
        image = Image.open(self.shot).convert("RGB")
        self.assertEqual(image.size, WINDOW)
        canvas = image.crop((x + 2, y + 2, x + w - 2, y + h - 2))
        pixels = list(canvas.getdata())
        model = [p for p in pixels if max(abs(p[c] - BACKGROUND[c]) for c in range(3)) > 6]
        self.assertGreater(len(model), 0.05 * len(pixels), "the model covers the canvas")

        # Shading scales a region's colour by 0.35..1: its hue (chromaticity)
        # stays. Colours of the same hue at other brightness count once.
        hues = {chromaticity(c) for c in embedded_colors(self.html)}
        counts = dict.fromkeys(hues, 0)
        for p in model:
            if max(p) < 40:
                continue  # sharp boundary curves are drawn near black
            q = chromaticity(p)
            nearest = min(hues, key=lambda u: (u[0] - q[0]) ** 2 + (u[1] - q[1]) ** 2)
            if (nearest[0] - q[0]) ** 2 + (nearest[1] - q[1]) ** 2 < 0.01 ** 2:
                counts[nearest] += 1
        shown = sum(1 for n in counts.values() if n >= MIN_PIXELS_PER_COLOUR)
        self.assertGreaterEqual(shown, min(5, len(hues)), f"{counts}")

    def test_pick_finds_the_face_and_its_region(self):
        _, _, w, h = map(int, body_attributes(self.dom)["canvas-rect"].split(","))
        regions = self.result["regions"]
        dom = chromium(self.url(f"#pick={w // 2},{h // 2}&select={regions[-1]['id']}"),
                       self.path("profile"), "--dump-dom")
        attrs = body_attributes(dom)
        face = int(attrs["pick-face"])
        # The generated part drops no face: mesh face i is input face i.
        self.assertGreaterEqual(face, 0, "the model is at the canvas centre")
        self.assertEqual(int(attrs["pick-region"]), self.result["face_labels"][face])
        kind = regions[-1]["type"].replace("SURFACE_TYPE_", "").lower()
        self.assertIn(f"Region {regions[-1]['id']}: {kind}", dom)


if __name__ == "__main__":
    unittest.main()
