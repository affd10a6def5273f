"""Errors of the meshseg client: one exception class per gRPC status code.

Every failed call raises a MeshsegError subclass carrying the gRPC status
code (`code`, a grpc.StatusCode) and the server's one-line message
(`details`). A job that ends FAILED or CANCELLED raises the class of the
job's error code, with the job attached (`job`).

    try:
        client.segment("part.stl")
    except meshseg_client.InvalidArgumentError as e:
        print(e.code, e.details)   # StatusCode.INVALID_ARGUMENT, "read_mesh: ..."
"""

import grpc


class MeshsegError(Exception):
    """A call or job that did not succeed; `code` is its grpc.StatusCode."""

    code = grpc.StatusCode.UNKNOWN

    def __init__(self, details, code=None, job=None):
        super().__init__(details)
        if code is not None:
            self.code = code
        self.details = details
        self.job = job  # the meshseg.v1.Job of a failed job, else None

    def __str__(self):
        return f"{self.code.name}: {self.details}"


class CancelledError(MeshsegError):
    code = grpc.StatusCode.CANCELLED


class UnknownError(MeshsegError):
    code = grpc.StatusCode.UNKNOWN


class InvalidArgumentError(MeshsegError):
    code = grpc.StatusCode.INVALID_ARGUMENT


class DeadlineExceededError(MeshsegError):
    code = grpc.StatusCode.DEADLINE_EXCEEDED


class NotFoundError(MeshsegError):
    code = grpc.StatusCode.NOT_FOUND


class AlreadyExistsError(MeshsegError):
    code = grpc.StatusCode.ALREADY_EXISTS


class PermissionDeniedError(MeshsegError):
    code = grpc.StatusCode.PERMISSION_DENIED


class ResourceExhaustedError(MeshsegError):
    code = grpc.StatusCode.RESOURCE_EXHAUSTED


class FailedPreconditionError(MeshsegError):
    code = grpc.StatusCode.FAILED_PRECONDITION


class AbortedError(MeshsegError):
    code = grpc.StatusCode.ABORTED


class OutOfRangeError(MeshsegError):
    code = grpc.StatusCode.OUT_OF_RANGE


class UnimplementedError(MeshsegError):
    code = grpc.StatusCode.UNIMPLEMENTED


class InternalError(MeshsegError):
    code = grpc.StatusCode.INTERNAL


class UnavailableError(MeshsegError):
    code = grpc.StatusCode.UNAVAILABLE


class DataLossError(MeshsegError):
    code = grpc.StatusCode.DATA_LOSS


class UnauthenticatedError(MeshsegError):
    code = grpc.StatusCode.UNAUTHENTICATED


__all__ = ["MeshsegError", "CancelledError", "UnknownError", "InvalidArgumentError",
           "DeadlineExceededError", "NotFoundError", "AlreadyExistsError", "PermissionDeniedError",
           "ResourceExhaustedError", "FailedPreconditionError", "AbortedError", "OutOfRangeError",
           "UnimplementedError", "InternalError", "UnavailableError", "DataLossError",
           "UnauthenticatedError", "error_for", "from_rpc_error"]

_BY_CODE = {
    cls.code: cls
    for cls in (CancelledError, UnknownError, InvalidArgumentError, DeadlineExceededError,
                NotFoundError, AlreadyExistsError, PermissionDeniedError,
                ResourceExhaustedError, FailedPreconditionError, AbortedError, OutOfRangeError,
                UnimplementedError, InternalError, UnavailableError, DataLossError,
                UnauthenticatedError)
}
_BY_NUMBER = {code.value[0]: code for code in grpc.StatusCode}


def error_for(code, details, job=None):
    """Returns the MeshsegError subclass instance for `code` (a
    grpc.StatusCode or its google.rpc.Code number)."""
    if not isinstance(code, grpc.StatusCode):
        code = _BY_NUMBER.get(int(code), grpc.StatusCode.UNKNOWN)
    return _BY_CODE.get(code, MeshsegError)(details, code=code, job=job)


def from_rpc_error(error):
    """Returns the MeshsegError for a grpc.RpcError raised by a stub call."""
    return error_for(error.code(), error.details() or str(error))
