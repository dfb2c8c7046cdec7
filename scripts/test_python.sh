#!/usr/bin/env bash
# The Python package: builds the wheel with maturin in the workspace's target directory
# (release profile, so the library's dependencies compiled by `cargo test --release` are
# reused), installs it in a fresh virtual environment and runs python/tests with pytest.
# First with only the wheel, numpy and pytest (the import test: no optional dependency
# present), then with compas, pandas, matplotlib and jsonschema (everything else). Fails if
# pytest fails. PYTHON picks the interpreter (default python3, >= 3.9).
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
py=${PYTHON:-python3}
target_dir=$(cargo metadata --format-version 1 --no-deps |
  "$py" -c 'import json, sys; print(json.load(sys.stdin)["target_directory"])')
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$py" -m venv "$work/venv"
bin="$work/venv/bin"
pip=("$bin/python" -m pip install --quiet --disable-pip-version-check)
"${pip[@]}" maturin numpy pytest
echo "python: venv + maturin numpy pytest: $((SECONDS - start)) s" >&2
t=$SECONDS
"$bin/maturin" build --release --quiet -m python/Cargo.toml -i "$bin/python" -o "$work/dist" >&2
echo "python: wheel: $((SECONDS - t)) s" >&2
"${pip[@]}" "$work"/dist/arch_enum-*.whl
ARCH_ENUM_NO_OPTIONAL=1 "$bin/python" -m pytest -q -p no:cacheprovider python/tests/test_import.py
t=$SECONDS
"${pip[@]}" compas pandas matplotlib jsonschema
echo "python: compas pandas matplotlib jsonschema: $((SECONDS - t)) s" >&2
ARCH_ENUM_BIN="$target_dir/release/arch-enum" "$bin/python" -m pytest -q -p no:cacheprovider python/tests
echo "python: all steps: $((SECONDS - start)) s" >&2
