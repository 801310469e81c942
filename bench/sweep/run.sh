#!/usr/bin/env bash
# Local sweep timings (docs/PERFORMANCE.md): 10^6 Hertz cases and 10^4 PimP cases on the
# local cores, release build, from scratch (the output folders are removed first).
# Usage: bench/sweep/run.sh [THREADS]   (default 2); writes into target/bench-sweep/.
set -euo pipefail
cd "$(dirname "$0")/../.."
THREADS=${1:-2}
cargo build --release -q -p kontakt-cli
BIN=${CARGO_TARGET_DIR:-target}/release/kontakt
OUT=${CARGO_TARGET_DIR:-target}/bench-sweep
mkdir -p "$OUT"
date -u
lscpu | grep -E '^(Model name|CPU\(s\)|Thread|Core)' || true
for s in hertz_1m pimp_10k; do
  rm -rf "${OUT:?}/$s"
  echo "== $s ($THREADS threads)"
  /usr/bin/time -f "wall %e s, user %U s, sys %S s, max RSS %M kB" \
    "$BIN" sweep "bench/sweep/$s.toml" --out "$OUT/$s" --threads "$THREADS" --quiet
  du -sh "$OUT/$s/chunks" "$OUT/$s/results.parquet"
  # the rerun finds every chunk and only combines
  /usr/bin/time -f "rerun: wall %e s" \
    "$BIN" sweep "bench/sweep/$s.toml" --out "$OUT/$s" --threads "$THREADS" --quiet
done
