"""Checks what try.sh wrote for the Mule: every mobility event answered
(a value, or a stall or failure with its reason), the 3-D ones among
them; every steady turn's sprockets paying for its friction and rolling
losses; the 3-D run's 90° turn made; its 3-D modes written; the FMU valid by fmpy's
checks, and its first 3 s simulated (settling, then the speed ramp),
with and without the engine: every output finite, the hull driven
forward.

    python check.py out
"""

import json
import math
import sys
from pathlib import Path

from fmpy import simulate_fmu
from fmpy.validation import validate_fmu

out = Path(sys.argv[1] if len(sys.argv) > 1 else "out")

EVENTS = ["ride", "half-round", "step", "gap", "ditch", "barrier", "grade", "soil",
          "side-slope", "turning"]
rows = [json.loads(line) for line in (out / "mobility.jsonl").read_text().splitlines()
        if line.startswith("{")]
for event in EVENTS:
    mine = [r for r in rows if r["event"] == event]
    assert mine, f"mobility: no answer for {event}"
    for r in mine:
        answered = r["value"] is not None and r["relation"] not in ("failed", "stalled")
        explained = r["relation"] in ("failed", "stalled") and r["failure"]
        assert answered or explained or r["relation"] == "not held", r
for name in ["report.html", "trials.csv", "summary.svg"] + [f"{e}.csv" for e in EVENTS]:
    assert (out / "mobility" / name).stat().st_size > 0, name
print(f"mobility: {len(rows)} answers over {len(EVENTS)} events")

lines = (out / "steer" / "steer.csv").read_text().splitlines()
header = lines[0].split(",")
turns = [dict(zip(header, line.split(","))) for line in lines[1:]]
assert len(turns) == 5, f"steer: {len(turns)} turns"
for t in turns:
    paid = float(t["outer_power"]) + float(t["inner_power"])
    lost = float(t["friction_dissipation"]) + float(t["rolling_loss"])
    assert abs(paid - lost) <= 1e-9 * lost, (paid, lost)
print(f"steer: {len(turns)} turns, the tightest on {float(turns[1]['radius']):.2f} m")

lines = (out / "spatial" / "spatial.csv").read_text().splitlines()
header = lines[0].split(",")
last = dict(zip(header, map(float, lines[-1].split(","))))
# The driver's 90° turn to the left, held: the heading within 3°.
assert abs(math.degrees(last["heading"]) - 90.0) < 3.0, last["heading"]
print(f"spatial: heading {math.degrees(last['heading']):.1f}° after the 90° turn, "
      f"{last['vx']:.2f}, {last['vy']:.2f} m/s")
assert (out / "modes-spatial" / "modes-spatial.csv").stat().st_size > 0

for fmu in [out / "fmu" / "Mule.fmu", out / "fmu" / "Mule-fmi2.fmu"]:
    problems = validate_fmu(str(fmu))
    assert not problems, f"{fmu}: {problems}"
    for engine in (0, 1):
        result = simulate_fmu(str(fmu), stop_time=3.0, output_interval=0.01,
                              start_values={"engine": engine},
                              output=["x", "speed", "pitch", "books_residual"])
        for column in ("x", "speed", "pitch"):
            assert all(math.isfinite(v) for v in result[column]), (fmu, engine, column)
        assert result["x"][-1] - result["x"][0] > 0.5, (fmu, engine, result["x"][-1])
        print(f"{fmu.name}, engine {engine}: x {result['x'][0]:.3f} -> {result['x'][-1]:.3f} m "
              f"in 3 s, books {result['books_residual'][-1]:.1e}")
