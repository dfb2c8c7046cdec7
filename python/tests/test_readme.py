"""README.md's Python example stays true: the ```python block of the section
"Python: `import arch_enum`" is run as a script and what it prints must equal the
```text block after it (trailing blanks ignored); it must write its two figures."""

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


def test_readme_python_example(tmp_path):
    text = (REPO / "README.md").read_text(encoding="utf-8")
    code, printed = blocks(text, "## Python: `import arch_enum`")
    script = tmp_path / "example.py"
    script.write_text(code, encoding="utf-8")
    env = dict(os.environ, MPLBACKEND="Agg")
    out = subprocess.run([sys.executable, str(script)], cwd=tmp_path, env=env,
                         capture_output=True, text=True, timeout=600)
    assert out.returncode == 0, out.stderr
    got = [line.rstrip() for line in out.stdout.splitlines()]
    want = [line.rstrip() for line in printed.splitlines()]
    assert got == want
    assert (tmp_path / "eta_mu.png").stat().st_size > 1000
    assert (tmp_path / "arch.svg").read_text(encoding="utf-8").count("<svg") >= 1
