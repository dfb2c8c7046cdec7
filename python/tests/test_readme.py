"""The Python examples stay true: the ```python block of README.md's section
"Python: `import arch_enum`" and of docs/python.md's "A worked example" and "Every
command" are each run as a
script, and what each prints must equal the ```text block after it (trailing blanks
ignored); the worked example must write its two figures."""

import os
import subprocess
import sys

from conftest import REPO


def blocks(text, start):
    """The ```python block after `start` and the ```text block after it."""
    rest = text[text.index(start):]
    code = rest.split("```python\n", 1)[1].split("```\n", 1)[0]
    after = rest.split("```python\n", 1)[1].split("```\n", 1)[1]
    printed = after.split("```text\n", 1)[1].split("```\n", 1)[0]
    return code, printed


def run_block(page, start, tmp_path):
    """Runs the ```python block after `start` on `page` and compares what it prints."""
    text = (REPO / page).read_text(encoding="utf-8")
    code, printed = blocks(text, start)
    script = tmp_path / "example.py"
    script.write_text(code, encoding="utf-8")
    env = dict(os.environ, MPLBACKEND="Agg")
    out = subprocess.run([sys.executable, str(script)], cwd=tmp_path, env=env,
                         capture_output=True, text=True, timeout=600)
    assert out.returncode == 0, out.stderr
    got = [line.rstrip() for line in out.stdout.splitlines()]
    want = [line.rstrip() for line in printed.splitlines()]
    assert got == want


def test_readme_python_example(tmp_path):
    run_block("README.md", "## Python: `import arch_enum`", tmp_path)


def test_docs_worked_example(tmp_path):
    run_block("docs/python.md", "## A worked example", tmp_path)
    assert (tmp_path / "eta_mu.png").stat().st_size > 1000
    assert (tmp_path / "arch.svg").read_text(encoding="utf-8").count("<svg") >= 1


def test_docs_every_command_example(tmp_path):
    run_block("docs/python.md", "## Every command: `run`", tmp_path)
