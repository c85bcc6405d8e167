"""The type stubs (`__init__.pyi`) say what the module has: mypy's
stubtest compares every class, method, parameter and property of the
stub with the native module and fails on any difference."""

import subprocess
import sys

import pytest


def test_stubs_match_the_module():
    pytest.importorskip("mypy", reason="stubtest needs mypy (pip install mypy)")
    run = subprocess.run(
        [sys.executable, "-m", "mypy.stubtest", "planar_mechanism"],
        capture_output=True,
        text=True,
        check=False,
    )
    assert run.returncode == 0, run.stdout + run.stderr
