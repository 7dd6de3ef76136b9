"""The example runs (a short sweep) and its row equals the validation report's."""

import pathlib
import subprocess
import sys

EXAMPLE = pathlib.Path(__file__).resolve().parents[1] / "examples" / "sweep_speed_sea.py"


def test_the_sweep_example_runs_and_reproduces_its_validation_row():
    p = subprocess.run([sys.executable, str(EXAMPLE), "--duration", "10"], capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, p.stderr
    lines = p.stdout.splitlines()
    # A header and one line per run (3 sea states x 3 speeds), every number finite.
    table = lines[1:10]
    assert len(table) == 9 and all(len(line.split()) == 5 for line in table)
    assert not any(w in p.stdout.lower() for w in ("nan", "inf"))
    assert "ours 0.9498 (+- 0.01: within)" in p.stdout and "docs/validation.md prints: reference 0.95 -, ours 0.9498" in p.stdout
