"""Shared helpers for the tests of bench/run_collection.py and bench/report.py."""
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
BENCH = REPO / "bench"
FIXTURES = Path(__file__).resolve().parent / "fixtures"
sys.dont_write_bytecode = True  # no __pycache__ beside the bench scripts
sys.path.insert(0, str(BENCH))


@pytest.fixture
def fake_tool(tmp_path):
    """An executable copy of fixtures/fake_compare.py (a checkout may drop the x bit)."""
    tool = tmp_path / "bin" / "fake_compare.py"
    tool.parent.mkdir()
    shutil.copy(FIXTURES / "fake_compare.py", tool)
    tool.chmod(0o755)
    return tool


def make_meshes(folder, names):
    """Tiny placeholder mesh files; the fake tool only looks at names and sizes."""
    for name in names:
        path = Path(folder) / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(f"mesh {name}\n")
    return Path(folder)


def run_script(name, *args, env=None, timeout=60):
    full_env = dict(os.environ, **(env or {}))
    return subprocess.run([sys.executable, str(BENCH / name), *map(str, args)],
                          capture_output=True, text=True, env=full_env, timeout=timeout)
