#!/usr/bin/env bash
# Sets the machine up if needed, then runs arch-enum (release build) with the given arguments.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
exec cargo run --release --quiet -- "$@"
