"""Job progress as the CLI shows it: the whole job's fraction and an ETA.

The pipeline reports (stage, fraction of that stage). The stages, their
order and their typical share of a job's time are in progress_stages.txt,
the file the C++ CLI embeds (client/progress_stages.txt), so both clients
compute the same whole-job fraction from the same events.
"""

import collections
import os
import time

Stage = collections.namedtuple("Stage", "name weight always")

# One event for a progress callback.
#   state           "QUEUED", "RUNNING", "SUCCEEDED", "FAILED", "CANCELLED"
#   stage           the stage as the pipeline names it ("segment",
#                   "reconstruct: octree"); "" while queued
#   fraction        of that stage, 0..1
#   overall         of the whole job, 0..1 (never decreases)
#   eta_seconds     time left, extrapolated from the time so far; None until
#                   the job has run long enough to tell
#   elapsed_seconds since the job started running (0 while queued)
#   queue_position  jobs ahead while QUEUED, else -1
#   message         the server's summary of the change ("" offline)
#   job             the meshseg.v1.Job of the event (None offline)
Progress = collections.namedtuple(
    "Progress", "state stage fraction overall eta_seconds elapsed_seconds queue_position "
    "message job")


def load_stages(path=None):
    """Returns the stages of progress_stages.txt in pipeline order."""
    path = path or os.path.join(os.path.dirname(__file__), "progress_stages.txt")
    stages = []
    with open(path, encoding="utf-8") as f:
        for line in f:
            words = line.split("#", 1)[0].split()
            if not words:
                continue
            if len(words) != 3 or words[2] not in ("always", "sometimes"):
                raise ValueError(f"{path}: bad stage line {line.strip()!r}")
            stages.append(Stage(words[0], float(words[1]), words[2] == "always"))
    return stages


class ProgressTracker:
    """Turns (stage, fraction) reports into the whole job's fraction, an ETA
    and the wall time of each stage.

    A stage reported as "name: step" counts as stage `name`; its steps'
    fractions are of the step, so only "name" itself moves the fraction.
    Stages marked `sometimes` (reconstruction of a point cloud, remeshing of
    a CAD export) count once reported; before that the job is planned
    without them. The ETA is the time so far scaled by the fraction left:
    elapsed * (1 - overall) / overall.
    """

    # An ETA needs this much of the job and of the wall time behind it.
    MIN_OVERALL = 0.02
    MIN_ELAPSED_S = 0.5

    def __init__(self, stages=None, clock=time.monotonic):
        self._stages = stages if stages is not None else load_stages()
        self._order = {s.name: i for i, s in enumerate(self._stages)}
        self._clock = clock
        self._seen = set()
        self._start = None
        self._current = None  # index into stages
        self._fraction = 0.0
        self._overall = 0.0
        self._end = None
        self._current_since = None  # when the running stage last started
        self._stage_time = {}  # closed spans per stage name

    @property
    def overall(self):
        return self._overall

    def stage_seconds(self):
        """Returns {stage: wall seconds} of the stages seen, in pipeline
        order: the sum of the spans each was the running stage (a stage can
        run again, as remesh inside reconstruct); the running one counts up
        to now."""
        now = self._clock()
        times = dict(self._stage_time)
        if self._current is not None and self._end is None:
            times[self._stages[self._current].name] += now - self._current_since
        return {name: times[name] for name in sorted(times, key=self._order.get)}

    def update(self, stage, fraction):
        """Records a report; returns (overall, eta_seconds or None)."""
        now = self._clock()
        if self._start is None:
            self._start = now
        name = stage.split(":", 1)[0].strip()
        index = self._order.get(name)
        if index is not None:
            if index != self._current:
                if self._current is not None:
                    self._stage_time[self._stages[self._current].name] += now - self._current_since
                self._stage_time.setdefault(name, 0.0)
                self._current = index
                self._current_since = now
                self._fraction = 0.0
            self._seen.add(name)
            if name == stage:
                self._fraction = min(max(float(fraction), 0.0), 1.0)
            self._overall = max(self._overall, self._planned_fraction())
        return self._overall, self.eta_seconds()

    def finish(self):
        """Marks the job done: overall 1, the running stage ended."""
        if self._end is not None:
            return
        self._end = self._clock()
        if self._current is not None:
            self._stage_time[self._stages[self._current].name] += self._end - self._current_since
        self._overall = 1.0

    def elapsed_seconds(self):
        """Seconds from the first report to now, or to finish()."""
        if self._start is None:
            return 0.0
        return (self._end if self._end is not None else self._clock()) - self._start

    def eta_seconds(self):
        elapsed = self.elapsed_seconds()
        if self._overall >= 1.0:
            return 0.0
        if self._overall < self.MIN_OVERALL or elapsed < self.MIN_ELAPSED_S:
            return None
        return elapsed * (1.0 - self._overall) / self._overall

    def _planned_fraction(self):
        planned = [i for i, s in enumerate(self._stages) if s.always or s.name in self._seen]
        total = sum(self._stages[i].weight for i in planned)
        done = sum(self._stages[i].weight for i in planned if i < self._current)
        done += self._stages[self._current].weight * self._fraction
        return min(done / total, 1.0) if total > 0 else 0.0
