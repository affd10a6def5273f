"""What the Python client tests share: the built binaries (MESHSEG_BIN_DIR),
a scratch directory per test, `meshseg` as a subprocess, and meshseg-server
as a child process on 127.0.0.1 with an ephemeral port."""

import os
import queue
import shutil
import signal
import subprocess
import tempfile
import threading
import unittest

BIN_DIR = os.environ.get("MESHSEG_BIN_DIR", "")
MESHSEG = os.path.join(BIN_DIR, "meshseg")
MESHSEG_SERVER = os.path.join(BIN_DIR, "meshseg-server")

# Bounds of every wait, so a broken server fails a test instead of hanging it.
START_TIMEOUT_S = 10
STOP_TIMEOUT_S = 10
COMMAND_TIMEOUT_S = 120


def run_meshseg(*args, check=True):
    """Runs `meshseg args...`; returns the CompletedProcess (text)."""
    env = {k: v for k, v in os.environ.items() if k != "MESHSEG_SERVER"}
    run = subprocess.run([MESHSEG, *map(str, args)], capture_output=True, text=True, env=env,
                         timeout=COMMAND_TIMEOUT_S, stdin=subprocess.DEVNULL)
    if check and run.returncode != 0:
        raise AssertionError(f"meshseg {' '.join(map(str, args))} exited {run.returncode}: "
                             f"{run.stderr.strip()}")
    return run


class ServerProcess:
    """meshseg-server --listen 127.0.0.1:0 flags..., its address read from its
    "listening on HOST:PORT" line; its log (stderr) collected as it comes."""

    def __init__(self, *flags):
        self.log = []
        self.process = subprocess.Popen(
            [MESHSEG_SERVER, "--listen", "127.0.0.1:0", *map(str, flags)],
            stdout=subprocess.PIPE, stderr=subprocess.PIPE, stdin=subprocess.DEVNULL, text=True)
        lines = queue.Queue()
        threading.Thread(target=lambda: lines.put(self.process.stdout.readline()),
                         daemon=True).start()
        threading.Thread(target=self._collect_log, daemon=True).start()
        try:
            first = lines.get(timeout=START_TIMEOUT_S)
        except queue.Empty:
            first = ""
        prefix = "listening on "
        if not first.startswith(prefix):
            self.stop()
            raise AssertionError(f"meshseg-server did not start: {first!r} {''.join(self.log)}")
        self.address = first[len(prefix):].strip()

    def _collect_log(self):
        for line in self.process.stderr:
            self.log.append(line)

    def stop(self):
        """SIGTERM, then SIGKILL if it has not exited in STOP_TIMEOUT_S."""
        if self.process.poll() is None:
            self.process.send_signal(signal.SIGTERM)
            try:
                self.process.wait(timeout=STOP_TIMEOUT_S)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait()
        for stream in (self.process.stdout, self.process.stderr):
            stream.close()


class ScratchTestCase(unittest.TestCase):
    """A test with a fresh directory `self.dir`, removed afterwards."""

    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix=f"meshseg_{type(self).__name__}_")
        self.addCleanup(shutil.rmtree, self.dir, ignore_errors=True)

    def path(self, name):
        return os.path.join(self.dir, name)


def write_box_off(path, n=3, size=(2.0, 1.0, 0.5)):
    """Writes a closed box with each side split n x n (12 n^2 triangles),
    the shape of tests/server/test_files.h's SplitBox."""
    index, vertices, faces = {}, [], []

    def vertex(g):
        if g not in index:
            index[g] = len(vertices)
            vertices.append(tuple(size[c] * g[c] / n for c in range(3)))
        return index[g]

    for axis in range(3):
        for side in (0, 1):
            for a in range(n):
                for b in range(n):
                    def at(da, db):
                        g = [0, 0, 0]
                        g[axis] = side * n
                        g[(axis + 1) % 3] = a + da
                        g[(axis + 2) % 3] = b + db
                        return vertex(tuple(g))
                    p00, p10, p11, p01 = at(0, 0), at(1, 0), at(1, 1), at(0, 1)
                    if side == 1:
                        faces += [(p00, p10, p11), (p00, p11, p01)]
                    else:
                        faces += [(p00, p11, p10), (p00, p01, p11)]
    with open(path, "w") as f:
        f.write(f"OFF\n{len(vertices)} {len(faces)} 0\n")
        for v in vertices:
            f.write(" ".join(repr(c) for c in v) + "\n")
        for t in faces:
            f.write(f"3 {t[0]} {t[1]} {t[2]}\n")
    return len(faces)
