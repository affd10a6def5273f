"""meshseg_client.ProgressTracker: the whole job's fraction and ETA from the
pipeline's (stage, fraction) reports, with the weights of
progress_stages.txt, and that file naming every stage the pipeline reports."""

import re
import unittest

import meshseg_client
from meshseg_client.progress import Stage, load_stages

import harness

STAGES = [Stage("read", 1.0, True), Stage("reconstruct", 4.0, False),
          Stage("remesh", 2.0, False), Stage("segment", 5.0, True),
          Stage("topology", 2.0, True)]


class Clock:
    def __init__(self):
        self.now = 100.0

    def __call__(self):
        return self.now


class ProgressTrackerTest(unittest.TestCase):
    def test_mesh_path_weights_stages_that_run(self):
        clock = Clock()
        t = meshseg_client.ProgressTracker(STAGES, clock)
        # read + segment + topology = 8: reconstruct and remesh never ran.
        self.assertEqual(t.update("read", 1.0)[0], 1 / 8)
        clock.now += 2.0
        overall, eta = t.update("segment", 0.5)
        self.assertAlmostEqual(overall, (1 + 2.5) / 8)
        self.assertAlmostEqual(eta, 2.0 * (1 - overall) / overall)
        clock.now += 1.0
        self.assertAlmostEqual(t.update("topology", 0.5)[0], (1 + 5 + 1) / 8)
        t.finish()
        self.assertEqual(t.overall, 1.0)
        self.assertEqual(t.eta_seconds(), 0.0)
        self.assertEqual(t.stage_seconds(), {"read": 2.0, "segment": 1.0, "topology": 0.0})

    def test_cloud_steps_count_as_their_stage(self):
        clock = Clock()
        t = meshseg_client.ProgressTracker(STAGES, clock)
        t.update("read", 1.0)
        # reconstruct joins the plan: read + reconstruct + segment + topology = 12.
        self.assertAlmostEqual(t.update("reconstruct", 0.5)[0], (1 + 2) / 12)
        # A step's fraction is of the step, not of reconstruct.
        self.assertAlmostEqual(t.update("reconstruct: octree", 0.9)[0], (1 + 2) / 12)
        self.assertAlmostEqual(t.update("segment", 0.0)[0], (1 + 4) / 12)

    def test_a_stage_that_runs_again_adds_its_spans(self):
        clock = Clock()
        t = meshseg_client.ProgressTracker(STAGES, clock)
        t.update("reconstruct", 0.0)
        clock.now += 1.0
        t.update("remesh", 0.0)  # a remesh inside reconstruct
        clock.now += 2.0
        t.update("reconstruct", 0.9)
        clock.now += 1.0
        t.update("segment", 0.0)
        clock.now += 2.0
        self.assertEqual(t.stage_seconds(), {"reconstruct": 2.0, "remesh": 2.0, "segment": 2.0})

    def test_never_goes_back_and_waits_before_an_eta(self):
        clock = Clock()
        t = meshseg_client.ProgressTracker(STAGES, clock)
        t.update("segment", 0.8)
        clock.now += 0.1
        self.assertIsNone(t.update("segment", 0.9)[1], "0.1 s is too short to extrapolate")
        before = t.overall
        # A remesh after segmenting once (a CAD export retried on a remesh)
        # grows the plan; the fraction holds instead of dropping.
        self.assertEqual(t.update("remesh", 0.0)[0], before)
        self.assertEqual(t.update("unknown stage", 1.0)[0], before)

    def test_stage_file_parses(self):
        stages = load_stages()
        self.assertEqual([s.name for s in stages][:1], ["read"])
        self.assertTrue(all(s.weight > 0 for s in stages))


class StageFileCoversThePipelineTest(harness.ScratchTestCase):
    def test_every_stage_segment_reports_has_a_weight(self):
        box = self.path("box.off")
        harness.write_box_off(box)
        run = harness.run_meshseg("segment", box, "-o", self.path("box.json"))
        reported = {m.split(":")[0] for m in re.findall(r"^progress: ([a-z: ]+?) \d+%", run.stdout,
                                                       re.MULTILINE)}
        self.assertTrue({"read", "segment"} <= reported, run.stdout)
        self.assertLessEqual(reported, {s.name for s in load_stages()},
                             "a stage without a weight in client/progress_stages.txt")


if __name__ == "__main__":
    unittest.main()
