#!/usr/bin/env bash
# Every answer for the Mule, as the guide's chapter "Your own vehicle"
# gives them: run from this folder (CI runs it, .ci/run). PYTHON, if set,
# is a Python with fmpy (pip install fmpy numpy) for the FMU's check.
set -euo pipefail
cd "$(dirname "$0")"

# The binary and the FMU's library, optimised. MULE_BUILT, if set, is the
# folder where they were already built (CI builds them beside trackgen's
# own, to share the dependencies' compiled code).
if [ -z "${MULE_BUILT:-}" ]; then
  cargo build --release --quiet
fi
target=${MULE_BUILT:-${CARGO_TARGET_DIR:-target}/release}
mule=$target/mule

# The main job over our own course, recording every 2 ms for the ride.
$mule run --course-file course.csv --duration 12 --output-every 0.002 --out out/run

# The mobility events, one parameter each (a smoke test: drop --quick for
# the whole set), as JSON lines too.
$mule mobility --quick --json --out out/mobility > out/mobility.jsonl

# Where it rests and how it rings.
$mule modes --out out/modes

# How it turns: two of its tracks 1.6 m apart, loaded as it rests.
$mule steer --gauge 1.6 --out out/steer

# The FMU: FMI 3.0 and 2.0 archives of the library cargo built.
$mule fmu --library "$target/libmule.so" --out out/fmu

# What a user checks: every event answered or failed with its reason, and
# the FMU validated and simulated by fmpy.
if [ -n "${PYTHON:-}" ]; then
  "$PYTHON" check.py out
fi
