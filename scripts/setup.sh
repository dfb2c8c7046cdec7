#!/usr/bin/env bash
# Installs what a clean machine lacks to build arch-enum: HiGHS (through good_lp's
# `highs` feature) is compiled from source and needs cmake, and highs-sys runs bindgen,
# which needs libclang.
set -euo pipefail
# A Rust toolchain is the one thing this script cannot install (no downloads but the package
# registries): say so plainly instead of failing deep in a build.
if ! command -v cargo >/dev/null 2>&1; then
  echo "setup: no Rust toolchain: install Rust >= $(sed -n 's/^rust-version = "\(.*\)"/\1/p' "$(dirname "$0")/../Cargo.toml") (cargo, with the rustfmt and clippy components)" >&2
  exit 1
fi
need=()
command -v cmake >/dev/null 2>&1 || need+=(cmake)
dpkg -s libclang-dev >/dev/null 2>&1 || need+=(libclang-dev)
if [ "${#need[@]}" -gt 0 ]; then
  echo "setup: installing ${need[*]}" >&2
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${need[@]}" >/dev/null
fi
# With --browser (scripts/test.sh): the explorer's browser test (tests/browser), Debian's
# chromium driven by playwright-core from npm (`npm ci` from the committed lock file).
if [ "${1:-}" = "--browser" ]; then
  if ! command -v npm >/dev/null 2>&1; then
    echo "setup: installing nodejs and npm" >&2
    SUDO=""
    [ "$(id -u)" -ne 0 ] && SUDO="sudo"
    $SUDO apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq nodejs npm >/dev/null
  fi
  if [ ! -x /usr/bin/chromium ]; then
    echo "setup: installing chromium" >&2
    SUDO=""
    [ "$(id -u)" -ne 0 ] && SUDO="sudo"
    $SUDO apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq chromium >/dev/null
  fi
  (cd "$(dirname "$0")/../tests/browser" && npm ci --no-audit --no-fund --loglevel=error >&2)
fi
