"""Shared helpers: the command-line binary the Python results are compared with.

The binary is ``$ARCH_ENUM_BIN``, else ``release/arch-enum`` under ``$CARGO_TARGET_DIR``
or the repository's ``target/`` (``cargo build --release`` makes it; scripts/test.sh
runs ``cargo test --release`` first). A missing binary fails the tests that need it.
"""

import json
import os
import subprocess
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]


def cli_binary() -> Path:
    env = os.environ.get("ARCH_ENUM_BIN")
    if env:
        return Path(env)
    target = Path(os.environ.get("CARGO_TARGET_DIR", REPO / "target"))
    return target / "release" / "arch-enum"


@pytest.fixture(scope="session")
def cli():
    """Runs ``arch-enum ARGS...``; returns (exit code, parsed JSON of standard output)."""
    binary = cli_binary()
    if not binary.is_file():
        pytest.fail(
            f"the arch-enum binary is needed for this test and is not at {binary}: run "
            "`cargo build --release` (or set ARCH_ENUM_BIN)"
        )

    def run(*args: str, parse: bool = True):
        out = subprocess.run([str(binary), *args], capture_output=True, text=True, timeout=600)
        return out.returncode, (json.loads(out.stdout) if parse else out.stdout)

    return run
