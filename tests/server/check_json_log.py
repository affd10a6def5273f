"""Checks a meshseg-server log written with --log-format json.

Usage: python3 check_json_log.py LOG_FILE EVENT...
Every line must parse with json.loads as an object holding time, level,
event, job_id, tenant, stage and duration with their types; each EVENT named
must occur. Prints what failed and exits 1, or prints a summary and exits 0.
"""
import json
import re
import sys

REQUIRED = {"time": str, "level": str, "event": str, "job_id": str, "tenant": str, "stage": str}


def main():
    path, wanted = sys.argv[1], sys.argv[2:]
    events = {}
    errors = []
    with open(path, "rb") as f:
        lines = f.read().split(b"\n")
    if lines and lines[-1] == b"":
        lines.pop()
    for number, raw in enumerate(lines, 1):
        try:
            entry = json.loads(raw.decode("utf-8"))
        except (UnicodeDecodeError, json.JSONDecodeError) as e:
            errors.append("line %d is not JSON (%s): %r" % (number, e, raw[:200]))
            continue
        if not isinstance(entry, dict):
            errors.append("line %d is not an object" % number)
            continue
        for key, kind in REQUIRED.items():
            if not isinstance(entry.get(key), kind):
                errors.append("line %d: %s missing or not a %s" % (number, key, kind.__name__))
        if "duration" not in entry or not (entry["duration"] is None or
                                           isinstance(entry["duration"], (int, float))):
            errors.append("line %d: duration missing or neither a number nor null" % number)
        if entry.get("level") not in ("info", "warn", "error"):
            errors.append("line %d: level %r" % (number, entry.get("level")))
        if not re.fullmatch(r"\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d\.\d{3}Z", entry.get("time", "")):
            errors.append("line %d: time %r is not RFC 3339 UTC" % (number, entry.get("time")))
        event = entry.get("event", "")
        events.setdefault(event, []).append(entry)
        if event in ("job_queued", "job_started", "job_finished", "stage_done") and \
                not entry.get("job_id", "").startswith("job-"):
            errors.append("line %d: %s without job_id" % (number, event))
        if event == "stage_done" and (not entry.get("stage") or
                                      not isinstance(entry.get("duration"), (int, float))):
            errors.append("line %d: stage_done without stage or duration" % number)
        if event == "job_finished" and entry.get("state") == "SUCCEEDED" and \
                not isinstance(entry.get("duration"), (int, float)):
            errors.append("line %d: job_finished without duration" % number)
    for event in wanted:
        if event not in events:
            errors.append("no %s line" % event)
    if not lines:
        errors.append("empty log")
    if errors:
        print("\n".join(errors[:20]))
        return 1
    print("%d lines, all JSON; events: %s" % (len(lines), ", ".join(
        "%s x%d" % (e, len(v)) for e, v in sorted(events.items()))))
    return 0


if __name__ == "__main__":
    sys.exit(main())
