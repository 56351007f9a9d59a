#!/usr/bin/env bash
# Installs the dependencies, builds fabvdb and runs the whole test suite
# (ctest: unit tests per module, C API tests, command-line tests).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
echo "== running the tests"
ctest --test-dir build --output-on-failure -j 2 --timeout 600
