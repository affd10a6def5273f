"""The Python stubs generated from proto/meshseg/v1 at build time.

The build (target `meshseg_python`) runs Debian's protoc and
grpc_python_plugin over proto/meshseg/v1/*.proto into build/python, next to
a copy of this package, so the stubs always match the proto.
"""

try:
    from meshseg.v1 import segmentation_pb2 as pb  # noqa: F401
    from meshseg.v1 import service_pb2 as service_pb  # noqa: F401
    from meshseg.v1 import service_pb2_grpc as service_grpc  # noqa: F401
except ImportError as e:  # pragma: no cover - depends on the installation
    raise ImportError(
        "meshseg_client: the generated stubs (meshseg.v1.*_pb2) or their runtime are missing "
        f"({e}); build the target meshseg_python (cmake --build build --target meshseg_python), "
        "put build/python on PYTHONPATH, and install python3-grpcio and python3-protobuf "
        "(scripts/setup.sh)") from e
