"""meshseg_client against a live meshseg-server on 127.0.0.1 (ephemeral
port): the same result as `meshseg segment` offline, progress events,
submit / watch / result / jobs / cancel, and errors as typed exceptions that
carry the gRPC status code."""

import json
import os
import shutil
import subprocess
import sys
import tempfile
import threading
import unittest

import grpc
import meshseg_client

import harness

# A small CT-like part: coarse enough to segment in about a second.
SMALL_VOXEL = 1.5
# A part that takes a few seconds, long enough to be cancelled while running
# or to hold another job in the queue behind it (one worker).
LARGE_VOXEL = 0.4


def generate(path, voxel_size):
    harness.run_meshseg("generate", "test_piece", "-o", path, "--voxel-size", voxel_size)
    return path


class ClientTest(harness.ScratchTestCase):
    @classmethod
    def setUpClass(cls):
        cls.spool = tempfile.mkdtemp(prefix="meshseg_py_spool_")
        cls.server = harness.ServerProcess("--workers", "1", "--spool-dir", cls.spool)
        cls.client = meshseg_client.Client(cls.server.address, timeout=10)

    @classmethod
    def tearDownClass(cls):
        cls.client.close()
        cls.server.stop()
        shutil.rmtree(cls.spool, ignore_errors=True)

    def test_segment_gives_the_cli_json_and_progress_to_the_end(self):
        part = generate(self.path("part.ply"), SMALL_VOXEL)
        harness.run_meshseg("segment", part, "-o", self.path("offline.json"))
        with open(self.path("offline.json")) as f:
            offline = json.load(f)

        events = []
        result = self.client.segment(part, progress=events.append)

        self.assertEqual(result.to_dict(), offline, "the CLI's JSON, compared as parsed values")
        self.assertEqual(json.loads(result.to_json()), offline)
        self.assertEqual(len(result.message.face_labels), len(offline["face_labels"]))
        self.assertIsInstance(result.message, meshseg_client.pb.SegmentationResult)
        self.assertEqual(meshseg_client.state_name(result.job), "SUCCEEDED")
        self.assertGreater(len(offline["regions"]), 3)
        self.assertTrue(events, "at least the terminal event")
        self.assertEqual(events[-1].state, "SUCCEEDED")
        self.assertEqual(events[-1].overall, 1.0)
        self.assertEqual(events[-1].eta_seconds, 0.0)
        overall = [e.overall for e in events]
        self.assertEqual(overall, sorted(overall), "the job's fraction never goes back")

    def test_options_reach_the_server(self):
        part = generate(self.path("part.ply"), SMALL_VOXEL)
        harness.run_meshseg("segment", part, "-o", self.path("loose.json"),
                            "--distance-tolerance", "0.9")
        with open(self.path("loose.json")) as f:
            offline = json.load(f)
        result = self.client.segment(part, distance_tolerance=0.9, format_hint="ply")
        self.assertEqual(result.to_dict(), offline)
        default = self.client.segment(part)
        self.assertNotEqual(default.message.estimates.distance_tolerance,
                            result.message.estimates.distance_tolerance)
        with self.assertRaisesRegex(TypeError, "unknown option 'distance_tol'.*distance_tolerance"):
            self.client.submit(part, distance_tol=0.9)

    def test_cancel_a_queued_and_a_running_job(self):
        large = generate(self.path("large.ply"), LARGE_VOXEL)
        small = generate(self.path("small.ply"), SMALL_VOXEL)
        running = self.client.submit(large)
        queued = self.client.submit(small)  # one worker: waits behind `running`

        self.assertEqual(meshseg_client.state_name(self.client.cancel(queued)), "CANCELLED")
        self.assertEqual(meshseg_client.state_name(self.client.watch(queued, timeout=30)),
                         "CANCELLED")

        cancelled = threading.Event()

        def cancel_once_running(progress):
            if progress.state == "RUNNING" and not cancelled.is_set():
                cancelled.set()
                self.client.cancel(running)

        job = self.client.watch(running, progress=cancel_once_running, timeout=60)
        self.assertTrue(cancelled.is_set(), "the large job was seen running")
        self.assertEqual(meshseg_client.state_name(job), "CANCELLED")
        with self.assertRaises(meshseg_client.FailedPreconditionError) as e:
            self.client.result(running)
        self.assertEqual(e.exception.code, grpc.StatusCode.FAILED_PRECONDITION)
        with self.assertRaises(meshseg_client.FailedPreconditionError):
            self.client.cancel(running)  # already finished
        listed = [j.job_id for j in self.client.jobs()]
        self.assertLess(listed.index(running), listed.index(queued), "oldest first")

    def test_bad_file_raises_invalid_argument_with_the_failed_job(self):
        bad = self.path("nan_vertex.obj")
        with open(bad, "w") as f:
            f.write("v 0 0 0\nv 1 0 nan\nv 0 1 0\nf 1 2 3\n")
        with self.assertRaises(meshseg_client.InvalidArgumentError) as e:
            self.client.segment(bad)
        self.assertEqual(e.exception.code, grpc.StatusCode.INVALID_ARGUMENT)
        self.assertIn("nan_vertex.obj", e.exception.details)
        self.assertIsInstance(e.exception, meshseg_client.MeshsegError)
        self.assertEqual(meshseg_client.state_name(e.exception.job), "FAILED")

    def test_call_errors_carry_their_status_code(self):
        with self.assertRaises(meshseg_client.NotFoundError) as e:
            self.client.job("no-such-job")
        self.assertEqual(e.exception.code, grpc.StatusCode.NOT_FOUND)
        self.assertIn("no-such-job", e.exception.details)
        with self.assertRaises(meshseg_client.NotFoundError):
            self.client.result("no-such-job")
        with self.assertRaises(FileNotFoundError):
            self.client.submit(self.path("missing.stl"))
        unknown_format = self.path("part.step")
        with open(unknown_format, "w") as f:
            f.write("ISO-10303-21;\n")
        with self.assertRaises(meshseg_client.InvalidArgumentError) as e:
            self.client.segment(unknown_format)
        self.assertIn("part.step", e.exception.details)

    def test_plm_batch_example_writes_the_cli_json_per_part(self):
        parts = self.path("parts")
        os.makedirs(parts)
        harness.write_box_off(os.path.join(parts, "box.off"))
        harness.write_box_off(os.path.join(parts, "flat.off"), n=2, size=(3.0, 2.0, 0.2))
        # A machined block the B-rep stage closes into a solid: its STEP must come back.
        harness.run_meshseg("generate", "small_block", "-o", os.path.join(parts, "block.ply"),
                            "--voxel-size", "1.5")
        with open(os.path.join(parts, "broken.obj"), "w") as f:
            f.write("v 0 0 0\nv 1 0 0\nf 1 2 3\n")  # index 3 does not exist
        out = self.path("out")
        example = os.path.join(os.path.dirname(__file__), "..", "..", "..", "client", "python",
                               "examples", "plm_batch.py")
        run = subprocess.run([sys.executable, example, self.server.address, parts, out],
                             capture_output=True, text=True, timeout=harness.COMMAND_TIMEOUT_S)
        self.assertEqual(run.returncode, 1, "one part failed: " + run.stderr)
        self.assertIn("3 of 4 parts segmented", run.stdout)
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
        self.assertEqual({p: s["state"] for p, s in summary.items()},
                         {"box.off": "SUCCEEDED", "flat.off": "SUCCEEDED",
                          "block.ply": "SUCCEEDED", "broken.obj": "FAILED"})
        self.assertIn("broken.obj", summary["broken.obj"]["error"])
        # The API has a STEP export, so the example asks for it: the JSON then
        # carries the B-rep report, as `meshseg segment --step` writes it (which
        # exits 1, JSON written, when no STEP file can be built).
        for part in ("box.off", "flat.off", "block.ply"):
            stem = os.path.splitext(part)[0]
            cli = harness.run_meshseg("segment", os.path.join(parts, part), "-o",
                                      self.path(stem + ".json"), "--step",
                                      self.path(stem + ".step"), check=False)
            with open(self.path(stem + ".json")) as a, open(os.path.join(out, stem + ".json")) as b:
                self.assertEqual(json.load(b), json.load(a), stem)
            step_path = os.path.join(out, stem + ".step")
            if cli.returncode != 0:
                self.assertIn("no STEP file written", cli.stderr, stem)
                self.assertIn("step_error", summary[part], stem)
                self.assertFalse(os.path.exists(step_path), stem)
                continue
            with open(step_path, "rb") as f:
                step = f.read()
            self.assertTrue(step.startswith(b"ISO-10303-21;"), stem)
            self.assertEqual(summary[part]["step_bytes"], len(step), stem)
        self.assertIn("step_bytes", summary["block.ply"], "the block's STEP was written")

    def test_no_server_is_unavailable(self):
        # A port nobody listens on: the server just stopped.
        gone = harness.ServerProcess("--spool-dir", self.path("spool"))
        address = gone.address
        gone.stop()
        with meshseg_client.Client(address, timeout=2) as client:
            with self.assertRaises(meshseg_client.UnavailableError) as e:
                client.jobs()
        self.assertEqual(e.exception.code, grpc.StatusCode.UNAVAILABLE)


if __name__ == "__main__":
    unittest.main()
