"""Makes the freshly built package importable: PYTHONPATH=<build>/python is
the contract; STRATUM_BUILD may point elsewhere."""
import os
import sys

build = os.environ.get("STRATUM_BUILD")
if build:
    sys.path.insert(0, os.path.join(build, "python"))
