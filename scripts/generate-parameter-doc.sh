#!/usr/bin/env bash
# Regenerate doc/user/parameters.md from the code (the test
# core_parameter_reference_is_current fails when it is stale).
set -euo pipefail
cd "$(dirname "$0")/.."
exe="${1:-build/particulate}"
"$exe" --print-parameters=markdown > doc/user/parameters.md
echo "wrote doc/user/parameters.md"
