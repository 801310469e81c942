#!/usr/bin/env bash
# Peer comparison: sets up bench/peers/.venv if needed, then runs run.py with the given options.
#   bench/peers/run.sh --sizes 64,128,256 --rounds 3
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
bash "$HERE/setup.sh" >&2
exec "$HERE/.venv/bin/python" "$HERE/run.py" "$@"
