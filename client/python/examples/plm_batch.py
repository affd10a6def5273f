#!/usr/bin/env python3
"""A PLM batch job: segment every part in a folder on a meshseg server.

    PYTHONPATH=build/python python3 client/python/examples/plm_batch.py \\
        127.0.0.1:50051 parts/ out/ [--token T] [--tls-ca ca.pem]

Submits every mesh or point cloud in FOLDER (STL, OBJ, OFF, PLY, XYZ, PWN)
at once, so the server's queue keeps its workers busy, then follows each job
with one progress line per stage and writes, per part:
  out/<part>.json   the result, the same JSON as `meshseg segment`
  out/<part>.step   the B-rep, when the server's API offers STEP export
and out/summary.json: per part its job id, state, region count or error.
Exit code 0 when every part succeeded, 1 otherwise.
"""

import argparse
import json
import os
import sys

import meshseg_client
from meshseg_client import service_pb

EXTENSIONS = (".stl", ".obj", ".off", ".ply", ".xyz", ".pwn")


def step_request_fields():
    """Returns the GetResultRequest fields that ask for a STEP file, or None
    when this API (the generated meshseg.v1) has no STEP export: a bool field
    named like "step", or an enum field with a value named like "STEP"."""
    for field in service_pb.GetResultRequest.DESCRIPTOR.fields:
        if field.enum_type is not None:
            for value in field.enum_type.values:
                if "STEP" in value.name:
                    return {field.name: value.number}
        elif field.type == field.TYPE_BOOL and "step" in field.name:
            return {field.name: True}
    return None


def progress_printer(name):
    last = {}

    def show(p):
        key = (p.state, p.stage)
        if key == last.get("key"):
            return
        last["key"] = key
        eta = "--" if p.eta_seconds is None else f"{p.eta_seconds:.0f} s"
        where = f"{p.stage} " if p.stage else ""
        print(f"{name}: {p.state.lower()} {where}job {100 * p.overall:.0f}% ETA {eta}",
              flush=True)

    return show


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("server", help="HOST:PORT of meshseg-server")
    parser.add_argument("folder", help="folder of parts to segment")
    parser.add_argument("out", help="folder for the results")
    parser.add_argument("--token", help="bearer token, when the server asks for one")
    parser.add_argument("--tls-ca", help="CA certificate (PEM) of a TLS server")
    args = parser.parse_args()

    parts = sorted(f for f in os.listdir(args.folder) if f.lower().endswith(EXTENSIONS))
    if not parts:
        sys.exit(f"plm_batch: no {'/'.join(EXTENSIONS)} files in {args.folder}")
    os.makedirs(args.out, exist_ok=True)
    step = step_request_fields()
    if step is None:
        print("plm_batch: this server's API has no STEP export yet; writing the JSON only")

    # The server writes a STEP file only for uploads that ask for one.
    upload_fields = {f.name for f in service_pb.UploadHeader.DESCRIPTOR.fields}
    upload_step = {"step": True} if step is not None and "step" in upload_fields else {}

    summary = {}
    with meshseg_client.Client(args.server, token=args.token, tls_ca=args.tls_ca) as client:
        jobs = {}
        for part in parts:
            try:
                jobs[part] = client.submit(os.path.join(args.folder, part), **upload_step)
            except meshseg_client.MeshsegError as e:
                summary[part] = {"state": "REJECTED", "error": str(e)}
        for part, job_id in jobs.items():
            stem = os.path.splitext(part)[0]
            job = client.watch(job_id, progress=progress_printer(part))
            state = meshseg_client.state_name(job)
            summary[part] = {"job_id": job_id, "state": state}
            if state != "SUCCEEDED":
                summary[part]["error"] = job.error_message
                continue
            result = client.result(job_id)
            result.save_json(os.path.join(args.out, stem + ".json"))
            summary[part]["regions"] = len(result.regions)
            if step is not None:
                try:
                    data = client.result_bytes(job_id, **step)
                except meshseg_client.MeshsegError as e:
                    summary[part]["step_error"] = str(e)
                else:
                    with open(os.path.join(args.out, stem + ".step"), "wb") as f:
                        f.write(data)
                    summary[part]["step_bytes"] = len(data)

    with open(os.path.join(args.out, "summary.json"), "w") as f:
        json.dump(summary, f, indent=2)
    failed = [p for p, s in summary.items() if s["state"] != "SUCCEEDED"]
    print(f"plm_batch: {len(parts) - len(failed)} of {len(parts)} parts segmented; "
          f"summary in {os.path.join(args.out, 'summary.json')}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
