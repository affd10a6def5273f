"""A segmentation result: the generated message, and the same JSON as the CLI."""

import json

from google.protobuf import json_format

# The options of proto/src/result_json.cc's C++ printer (the contract in
# DESIGN.md "Result JSON"): original snake_case names, fields at their default
# value printed too, enums as names.
_JSON_OPTIONS = dict(including_default_value_fields=True, preserving_proto_field_name=True,
                     use_integers_for_enums=False)


def message_to_dict(message):
    """Returns `message` as the dict the CLI's JSON parses to (int64 fields are
    strings there and here, as the protobuf JSON mapping prints them)."""
    return json_format.MessageToDict(message, **_JSON_OPTIONS)


class Result:
    """The SegmentationResult of one job.

    `message` is the generated meshseg.v1.SegmentationResult; `to_dict()`
    equals json.load() of the file `meshseg segment -o RESULT.json` writes for
    the same input (values compared after parsing: the two printers may spell
    a float differently, e.g. 1e-06 and 1E-6, never with another value).
    `job` is the meshseg.v1.Job it came from (None if not known).
    """

    def __init__(self, message, job=None):
        self.message = message
        self.job = job

    @property
    def regions(self):
        return self.message.regions

    @property
    def face_labels(self):
        return self.message.face_labels

    def to_dict(self):
        return message_to_dict(self.message)

    def to_json(self):
        """Returns the result as one line of JSON (the CLI's field names and
        values) ending in a newline."""
        return json.dumps(self.to_dict(), separators=(",", ":")) + "\n"

    def save_json(self, path):
        with open(path, "w", encoding="utf-8") as f:
            f.write(self.to_json())

    def __repr__(self):
        return (f"Result({len(self.message.regions)} regions, "
                f"{len(self.message.face_labels)} face labels)")
