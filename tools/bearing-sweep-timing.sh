#!/usr/bin/env bash
# Time a sweep of 100 000 bearing load cases through `kontakt sweep` on 2 threads
# (issue 28, "Speed": at most 60 s). The 32008 X class TRB of examples/bearing_32008x.toml
# (23 rollers x 31 slices, ISO/TS 16281 slice law, tilts held), radial force 0 to 5 kN
# (400 values) x axial force 2 to 6 kN (250 values). Prints the CLI's JSON summary and
# the seconds spent computing; exits 1 above the target.
#
# Usage: tools/bearing-sweep-timing.sh [KONTAKT_BINARY]   (default: target/release/kontakt;
#        build it first with `cargo build --release -p kontakt-cli`)
#        AXIAL=5 RADIAL=10 tools/bearing-sweep-timing.sh target/debug/kontakt   (a smoke run)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
bin="${1:-$root/target/release/kontakt}"
[ -x "$bin" ] || { echo "no binary $bin: cargo build --release -p kontakt-cli" >&2; exit 2; }
axial="${AXIAL:-250}"
radial="${RADIAL:-400}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cat > "$work/sweep.toml" <<TOML
name = "32008 X TRB, $((axial * radial)) load cases"
base = "$root/examples/bearing_32008x.toml"
max_cases = $((axial * radial))
chunk_size = 10000

[[parameter]]
key = "load.force_n[2]"     # axial force [N]
start = 2000.0
stop = 6000.0
count = $axial

[[parameter]]
key = "load.force_n[0]"     # radial force [N]
start = 0.0
stop = 5000.0
count = $radial
TOML
summary="$("$bin" sweep "$work/sweep.toml" --out "$work/out" --threads 2 --quiet --json)"
echo "$summary"
python3 - "$summary" <<'PY'
import json, sys
s = json.loads(sys.argv[1])
t = s["seconds_computing"]
print(f"{s['cases']} cases, {s['cases_not_ok']} not ok, {s['threads']} threads: "
      f"{t:.2f} s computing ({1e6 * t * s['threads'] / s['cases']:.1f} us per case and thread), "
      f"{s['seconds_combining']:.2f} s combining; target 60 s")
sys.exit(0 if t + s["seconds_combining"] <= 60.0 else 1)
PY
