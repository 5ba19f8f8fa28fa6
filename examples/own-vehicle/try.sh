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
# the whole set), as JSON lines too; the 3-D ones (its tracks block) among
# them but cornering, whose trials each drive a 15 m circle (half a
# minute here; `--events cornering` runs it).
$mule mobility --quick --json --out out/mobility \
  --events ride,half-round,step,gap,ditch,barrier,grade,soil,side-slope,turning \
  > out/mobility.jsonl

# Where it rests and how it rings.
$mule modes --out out/modes

# How it turns: two of its tracks 1.6 m apart, loaded as it rests.
$mule steer --out out/steer

# In 3-D (its tracks block): both tracks and the hull over the bump and
# through a 90° turn, and its modes at rest with the hull's six motions.
$mule spatial --out out/spatial
$mule modes --spatial --out out/modes-spatial

# The FMU: FMI 3.0 and 2.0 archives of the library cargo built.
$mule fmu --library "$target/libmule.so" --out out/fmu

# What a user checks: every event answered or failed with its reason, and
# the FMU validated and simulated by fmpy.
if [ -n "${PYTHON:-}" ]; then
  "$PYTHON" check.py out
fi
