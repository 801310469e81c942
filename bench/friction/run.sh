#!/usr/bin/env bash
# Side-by-side timing of the friction integral over a 64 x 64 pressure map: kontakt
# (criterion, `friction/map_64x64_coulomb_ellipse`) against the same integral in NumPy
# (friction_numpy.py), on the same case; prints both results and the time ratio.
#   bash bench/friction/run.sh
# Needs Python 3 with venv; creates bench/friction/.venv with the pinned numpy.
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
VENV="${VENV:-$HERE/.venv}"
if ! "$VENV/bin/python" -c 'import numpy' 2>/dev/null; then
  python3 -m venv "$VENV"
  "$VENV/bin/pip" install -q -r "$HERE/requirements.txt"
fi
cd "$ROOT"
cargo bench -q -p kontakt --bench friction -- 'friction/map_64x64_coulomb_ellipse' 2>"$HERE/.rust-case.txt" >/dev/null
RUST_NS=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["mean"]["point_estimate"])' \
  target/criterion/friction/map_64x64_coulomb_ellipse/new/estimates.json)
NUMPY=$("$VENV/bin/python" "$HERE/friction_numpy.py")
python3 - "$RUST_NS" "$NUMPY" "$HERE/.rust-case.txt" <<'PY'
import json, sys
rust_us = float(sys.argv[1]) / 1e3
numpy = json.loads(sys.argv[2])
rust_case = open(sys.argv[3]).read().strip().splitlines()
print("case: Hertz ellipse 700 MPa, 1.2 x 0.3 mm, 64 x 64 cells; spin 300 rad/s about a pivot 2.76 mm away; Coulomb mu = 0.1")
for line in rust_case:
    if line.startswith("kontakt case:"):
        print(line)
print(f"numpy {numpy['numpy']} case: F = [{numpy['force_n'][0]:.6f}, {numpy['force_n'][1]:.6f}] N, "
      f"M = {numpy['moment_nmm']:.6f} N mm, P = {numpy['power_w']:.6f} W")
print(f"| implementation | time per map | ratio |")
print(f"|---|---:|---:|")
print(f"| kontakt grid_friction (1 thread) | {rust_us:.2f} us | 1 |")
print(f"| NumPy, vectorised | {numpy['time_us']:.2f} us | {numpy['time_us'] / rust_us:.1f} |")
PY
