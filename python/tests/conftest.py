"""What the tests share: the command line they compare with (``AES_SIM``, or the release build of
this checkout, which ``./build.sh`` makes) and a way to run it."""

import json
import os
import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def cli():
    """Runs ``aes-sim ARGS``; returns (exit status, stdout, stderr)."""
    exe = os.environ.get("AES_SIM", str(ROOT / "target" / "release" / "aes-sim"))
    if not os.access(exe, os.X_OK):
        pytest.fail(f"{exe}: no aes-sim command to compare with (cargo build --release -p aes-cli, or set AES_SIM)")

    def call(*args):
        p = subprocess.run([exe, *map(str, args)], capture_output=True, text=True, timeout=600)
        return p.returncode, p.stdout, p.stderr

    return call


@pytest.fixture(scope="session")
def cli_json(cli):
    """Runs ``aes-sim ARGS`` that must succeed and parses the JSON it prints."""

    def call(*args):
        code, out, err = cli(*args)
        assert code == 0, err
        return json.loads(out)

    return call
