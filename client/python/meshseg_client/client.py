"""Client of the meshseg.v1.Segmentation service.

    client = meshseg_client.Client("127.0.0.1:50051")
    result = client.segment("part.stl", progress=print)
    result.message.regions[0].type      # the generated message
    result.to_dict()["regions"][0]      # the same JSON as `meshseg segment`
"""

import hashlib
import os

import grpc
from google.protobuf import json_format

from . import errors
from ._stubs import pb, service_grpc, service_pb
from .progress import Progress, ProgressTracker
from .result import Result

_CHUNK_BYTES = 1 << 20
# Result chunks are at most 4 MiB (service.proto): room for one with headers.
_MAX_RECEIVE_BYTES = 8 << 20
# UploadHeader fields the client fills itself from the file.
_HEADER_FIELDS_FROM_FILE = {"file_name", "total_size", "sha256", "options"}

_TERMINAL = {"JOB_STATE_SUCCEEDED", "JOB_STATE_FAILED", "JOB_STATE_CANCELLED"}


def state_name(job):
    """Returns "RUNNING" for a Job in JOB_STATE_RUNNING, and so on."""
    return service_pb.JobState.Name(job.state).replace("JOB_STATE_", "")


def _read_tls_ca(tls_ca):
    if tls_ca is True:
        return None  # gRPC's default roots
    if isinstance(tls_ca, bytes):
        return tls_ca
    with open(tls_ca, "rb") as f:
        return f.read()


def _set_field(message, name, value):
    """Sets field `name` of `message` from a Python value: a scalar, an enum
    name or number, a message or a dict of one."""
    field = message.DESCRIPTOR.fields_by_name[name]
    if field.message_type is not None:
        target = getattr(message, name)
        if isinstance(value, dict):
            json_format.ParseDict(value, target)
        else:
            target.CopyFrom(value)
    elif field.enum_type is not None and isinstance(value, str):
        setattr(message, name, field.enum_type.values_by_name[value].number)
    else:
        setattr(message, name, value)


def _sha256(path):
    digest = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(_CHUNK_BYTES), b""):
            digest.update(block)
    return digest.hexdigest()


class Client:
    """A connection to meshseg-server at `address` ("HOST:PORT").

    token:   sent with every call as `authorization: Bearer <token>` metadata.
    tls_ca:  TLS instead of plaintext: a path to the CA's PEM file, its PEM
             bytes, or True for the system's root certificates.
    timeout: deadline in seconds of the unary calls (job, jobs, cancel).

    Every method raises a meshseg_client.MeshsegError subclass named after the
    gRPC status code (InvalidArgumentError, NotFoundError, ...) on failure;
    a local file that cannot be read raises OSError.
    """

    def __init__(self, address, token=None, tls_ca=None, timeout=30.0):
        options = [("grpc.max_receive_message_length", _MAX_RECEIVE_BYTES)]
        if tls_ca:
            credentials = grpc.ssl_channel_credentials(root_certificates=_read_tls_ca(tls_ca))
            self._channel = grpc.secure_channel(address, credentials, options=options)
        else:
            self._channel = grpc.insecure_channel(address, options=options)
        self._stub = service_grpc.SegmentationStub(self._channel)
        self._metadata = (("authorization", f"Bearer {token}"),) if token else ()
        self._timeout = timeout
        self.address = address

    def close(self):
        self._channel.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    # --- the calls -------------------------------------------------------

    def submit(self, path, **options):
        """Uploads the file at `path` and returns its job id (the job is
        queued). `options` are fields of SegmentOptions
        (distance_tolerance=0.5, angle_tolerance_deg=20, ...) or of
        UploadHeader (format_hint="stl", ...); TypeError names unknown ones."""
        header = self._upload_header(path, options)

        def requests():
            yield service_pb.UploadRequest(header=header)
            with open(path, "rb") as f:
                for chunk in iter(lambda: f.read(_CHUNK_BYTES), b""):
                    yield service_pb.UploadRequest(chunk=chunk)

        response = self._call(self._stub.Upload, requests(), timeout=None)
        return response.job_id

    def watch(self, job_id, progress=None, timeout=None):
        """Follows the job until it ends and returns its terminal Job
        (SUCCEEDED, FAILED or CANCELLED; a failed job is returned, not
        raised). `progress` is called with a Progress for every event;
        `timeout` (seconds) bounds the whole watch."""
        tracker = ProgressTracker()
        last = None
        try:
            for event in self._stub.WatchJob(service_pb.WatchJobRequest(job_id=job_id),
                                             metadata=self._metadata, timeout=timeout):
                last = event.job
                if progress is not None:
                    progress(_progress_of(event, tracker))
        except grpc.RpcError as e:
            raise errors.from_rpc_error(e) from None
        if last is None:
            raise errors.InternalError(f"watch: no event for job {job_id}")
        return last

    def result(self, job_id):
        """Returns the Result of a SUCCEEDED job (FailedPreconditionError for
        a job that has not succeeded, NotFoundError for an unknown one)."""
        data = self.result_bytes(job_id)
        message = pb.SegmentationResult()
        try:
            message.ParseFromString(data)
        except Exception as e:  # google.protobuf.message.DecodeError
            raise errors.DataLossError(
                f"result: job {job_id}: {len(data)} bytes do not parse ({e})") from None
        return Result(message)

    def result_bytes(self, job_id, **request_fields):
        """Returns the bytes GetResult streams for the job, reassembled.
        `request_fields` are further GetResultRequest fields (a result format
        such as STEP, where the server's API has one)."""
        request = service_pb.GetResultRequest(job_id=job_id)
        for name, value in request_fields.items():
            if name not in request.DESCRIPTOR.fields_by_name:
                raise TypeError(f"GetResultRequest has no field {name!r}")
            _set_field(request, name, value)
        data = bytearray()
        try:
            for chunk in self._stub.GetResult(request, metadata=self._metadata):
                if chunk.offset != len(data):
                    raise errors.DataLossError(
                        f"result: job {job_id}: chunk at offset {chunk.offset}, "
                        f"expected {len(data)}")
                data += chunk.data
        except grpc.RpcError as e:
            raise errors.from_rpc_error(e) from None
        return bytes(data)

    def job(self, job_id):
        """Returns the job's current state (a meshseg.v1.Job)."""
        return self._call(self._stub.GetJob, service_pb.GetJobRequest(job_id=job_id))

    def jobs(self):
        """Returns every job the server knows, oldest first."""
        return list(self._call(self._stub.ListJobs, service_pb.ListJobsRequest()).jobs)

    def cancel(self, job_id):
        """Cancels a queued or running job; returns its state after the
        request (a running job reaches CANCELLED shortly after)."""
        return self._call(self._stub.CancelJob, service_pb.CancelJobRequest(job_id=job_id))

    def segment(self, path, progress=None, timeout=None, **options):
        """Uploads, watches and fetches: returns the Result of segmenting the
        file at `path`. A job that ends FAILED or CANCELLED raises the error
        of its code (e.g. InvalidArgumentError for a malformed file), with
        the Job in the exception's `job`."""
        job_id = self.submit(path, **options)
        job = self.watch(job_id, progress=progress, timeout=timeout)
        if state_name(job) != "SUCCEEDED":
            raise errors.error_for(
                job.error_code or grpc.StatusCode.UNKNOWN,
                job.error_message or f"job {job_id} {state_name(job)}", job=job)
        result = self.result(job_id)
        result.job = job
        return result

    # --- helpers ----------------------------------------------------------

    def _call(self, method, request, timeout=0):
        try:
            return method(request, metadata=self._metadata,
                          timeout=self._timeout if timeout == 0 else timeout)
        except grpc.RpcError as e:
            raise errors.from_rpc_error(e) from None

    @staticmethod
    def _upload_header(path, options):
        size = os.path.getsize(path)  # OSError for a missing file, before any call
        header = service_pb.UploadHeader(file_name=os.path.basename(path), total_size=size,
                                         sha256=_sha256(path))
        segment_fields = header.options.DESCRIPTOR.fields_by_name
        header_fields = set(header.DESCRIPTOR.fields_by_name) - _HEADER_FIELDS_FROM_FILE
        for name, value in options.items():
            if value is None:
                continue
            if name in segment_fields:
                _set_field(header.options, name, value)
            elif name in header_fields:
                _set_field(header, name, value)
            else:
                known = sorted(set(segment_fields) | header_fields)
                raise TypeError(f"unknown option {name!r} (known: {', '.join(known)})")
        return header


def _progress_of(event, tracker):
    job = event.job
    state = state_name(job)
    if state == "RUNNING" and job.stage:
        tracker.update(job.stage, job.fraction)
    elif state == "SUCCEEDED":
        tracker.finish()
    return Progress(state=state, stage=job.stage, fraction=job.fraction,
                    overall=tracker.overall, eta_seconds=tracker.eta_seconds(),
                    elapsed_seconds=tracker.elapsed_seconds(),
                    queue_position=job.queue_position, message=event.message, job=job)
