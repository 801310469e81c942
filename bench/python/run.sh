#!/usr/bin/env bash
# Python call overhead and Dask sweep overhead (issue 13; docs/PERFORMANCE.md "Python").
# Builds the extension in release into its own venv (target/bench-py-venv), runs the
# criterion benches of the same Rust calls, then bench/python/overhead.py, which times the
# Python calls and the local and Dask sweeps in one run and prints the ratios.
# Usage: bench/python/run.sh            (about 5 minutes on 2 cores, most of it the build)
set -euo pipefail
cd "$(dirname "$0")/../.."
target="${CARGO_TARGET_DIR:-$PWD/target}"
venv="$target/bench-py-venv"
if [[ ! -x "$venv/bin/python" ]]; then
  python3 -m venv "$venv"
  "$venv/bin/python" -m pip install -q --disable-pip-version-check \
    maturin==1.16.0 numpy==2.4.6 dask==2026.8.0 distributed==2026.8.0
fi
export VIRTUAL_ENV="$venv" PATH="$venv/bin:$PATH"
maturin develop --release --quiet -m crates/kontakt-py/Cargo.toml
cargo bench -q -p kontakt --bench hertz -- 'hertz_point/(solve_force_planned|force_from_approach_planned)' \
  --warm-up-time 1 --measurement-time 3 >/dev/null
python bench/python/overhead.py --criterion "$target/criterion"
