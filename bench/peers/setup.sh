#!/usr/bin/env bash
# Create bench/peers/.venv with the peer solvers at versions known to work together on
# Python 3.11: tamaas 2.9.0, ContactMechanics 1.8.3, slippy 0.5.2 on numpy 2.4 (requirements.txt).
# Idempotent: a venv whose stamp matches requirements.txt is left alone.
#
#   bash bench/peers/setup.sh              # create or update
#   FORCE=1 bash bench/peers/setup.sh      # reinstall the pinned set
#   VENV=$HOME/peers-venv bash bench/peers/setup.sh  # another location
set -euo pipefail

HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
VENV="${VENV:-$HERE/.venv}"
PYTHON="${PYTHON:-python3}"
REQ="$HERE/requirements.txt"
SLIPPY="slippy==0.5.2"
STAMP="$VENV/.kontakt-peers-stamp"
STAMP_TEXT="$(cat "$REQ"; echo "$SLIPPY")"

check() {
  "$VENV/bin/python" -c 'import numpy, scipy, tamaas, ContactMechanics, slippy.core' 2>/dev/null
}

if [[ -z "${FORCE:-}" && -f "$STAMP" && "$(cat "$STAMP")" == "$STAMP_TEXT" ]] && check; then
  echo "peers venv $VENV is up to date"
  exit 0
fi

if [[ ! -x "$VENV/bin/python" ]]; then
  "$PYTHON" -c 'import sys; sys.exit(0 if sys.version_info[:2] == (3, 11) else 1)' \
    || echo "warning: $("$PYTHON" --version 2>&1); the pins were made on Python 3.11" >&2
  echo "creating $VENV with $("$PYTHON" --version 2>&1)"
  "$PYTHON" -m venv "$VENV"
fi
PIP=("$VENV/bin/python" -m pip --disable-pip-version-check --no-input -q)

"${PIP[@]}" install -r "$REQ"
# slippy 0.5.2 declares numpy<1.21 (no wheel for Python 3.11) and flake8, scikit-image, wheel,
# none of which slippy.core needs: install it without its dependency list.
"${PIP[@]}" install --no-deps "$SLIPPY"

check || { echo "error: the peers do not import in $VENV" >&2; exit 1; }
"$VENV/bin/python" - <<'PY'
from importlib.metadata import version
print("peers venv ready:", ", ".join(f"{p} {version(p)}" for p in
      ("numpy", "scipy", "tamaas", "ContactMechanics", "slippy", "pyFFTW", "numba")))
PY
printf '%s' "$STAMP_TEXT" > "$STAMP"
