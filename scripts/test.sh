#!/usr/bin/env bash
# Sets the machine up if needed, then runs the whole test suite in release mode, then the
# explorer's end-to-end test in chromium (`node --test tests/browser/`, on the release
# binary just built), then the Python package's tests (scripts/test_python.sh: the wheel, a fresh virtual environment,
# pytest). Snapshots are never written here: a missing or changed snapshot fails.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --browser
INSTA_UPDATE=no cargo test --release
node --test tests/browser/
bash scripts/test_python.sh
