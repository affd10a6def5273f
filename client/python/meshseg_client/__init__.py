"""meshseg_client: a Python client of meshseg-server (meshseg.v1.Segmentation).

    import meshseg_client
    with meshseg_client.Client("127.0.0.1:50051") as client:
        result = client.segment("part.stl", progress=lambda p: print(p.stage, p.overall))
        print(result.to_dict()["regions"][0]["type"])

The generated messages are in meshseg_client.pb (segmentation.proto) and
meshseg_client.service_pb (service.proto).
"""

from ._stubs import pb, service_pb
from .client import Client, state_name
from .errors import *  # noqa: F401,F403  (one class per gRPC status code)
from .errors import __all__ as _error_names
from .progress import Progress, ProgressTracker
from .result import Result, message_to_dict

__all__ = ["Client", "Result", "Progress", "ProgressTracker", "message_to_dict", "state_name",
           "pb", "service_pb", *_error_names]
