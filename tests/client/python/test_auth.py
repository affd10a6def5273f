"""The Client's token and TLS options, seen from a real gRPC server on
127.0.0.1: a Python server of the generated meshseg.v1.Segmentation service
that records each call's metadata, plaintext and with a self-signed
certificate made by openssl for this test."""

import concurrent.futures
import subprocess
import unittest

import grpc
import meshseg_client
from meshseg_client import service_pb
from meshseg.v1 import service_pb2_grpc

import harness


class RecordingService(service_pb2_grpc.SegmentationServicer):
    """Answers ListJobs with no jobs and records the caller's metadata."""

    def __init__(self):
        self.metadata = []

    def ListJobs(self, request, context):
        self.metadata.append(dict(context.invocation_metadata()))
        return service_pb.ListJobsResponse()


def start_server(service, credentials=None):
    server = grpc.server(concurrent.futures.ThreadPoolExecutor(max_workers=2))
    service_pb2_grpc.add_SegmentationServicer_to_server(service, server)
    if credentials is None:
        port = server.add_insecure_port("127.0.0.1:0")
    else:
        port = server.add_secure_port("127.0.0.1:0", credentials)
    server.start()
    return server, f"127.0.0.1:{port}"


class AuthTest(harness.ScratchTestCase):
    def self_signed(self):
        """Returns (certificate PEM, key PEM) for 127.0.0.1 and localhost."""
        cert, key = self.path("cert.pem"), self.path("key.pem")
        subprocess.run(["openssl", "req", "-x509", "-newkey", "ec", "-pkeyopt",
                        "ec_paramgen_curve:prime256v1", "-nodes", "-days", "1",
                        "-subj", "/CN=localhost", "-addext",
                        "subjectAltName=IP:127.0.0.1,DNS:localhost",
                        "-keyout", key, "-out", cert],
                       check=True, capture_output=True, timeout=60)
        with open(cert, "rb") as c, open(key, "rb") as k:
            return c.read(), k.read()

    def test_token_is_sent_as_bearer_metadata(self):
        service = RecordingService()
        server, address = start_server(service)
        self.addCleanup(server.stop, None)
        with meshseg_client.Client(address, token="s3cret", timeout=5) as client:
            self.assertEqual(client.jobs(), [])
        with meshseg_client.Client(address, timeout=5) as client:
            client.jobs()
        self.assertEqual(service.metadata[0].get("authorization"), "Bearer s3cret")
        self.assertNotIn("authorization", service.metadata[1], "no token, no header")

    def test_tls_with_the_ca_and_token(self):
        cert, key = self.self_signed()
        service = RecordingService()
        server, address = start_server(service, grpc.ssl_server_credentials([(key, cert)]))
        self.addCleanup(server.stop, None)
        with meshseg_client.Client(address, token="t0ken", tls_ca=self.path("cert.pem"),
                                   timeout=5) as client:
            self.assertEqual(client.jobs(), [])
        with meshseg_client.Client(address, tls_ca=cert, timeout=5) as client:  # PEM bytes
            client.jobs()
        self.assertEqual([m.get("authorization") for m in service.metadata],
                         ["Bearer t0ken", None])
        # Plaintext to a TLS port, and TLS trusting the system roots only,
        # both fail the handshake: UNAVAILABLE.
        for options in ({}, {"tls_ca": True}):
            with meshseg_client.Client(address, timeout=2, **options) as client:
                with self.assertRaises(meshseg_client.UnavailableError):
                    client.jobs()
        self.assertEqual(len(service.metadata), 2)


if __name__ == "__main__":
    unittest.main()
