#!/usr/bin/env python3
"""The M113's spatial FMUs (both tracks and the hull in 3-D) through fmpy.

    tools/fmu-check-spatial.py FMU_DIR SPATIAL_JOB_DIR [FMUSIM]

FMU_DIR holds M113Spatial.fmu and M113Spatial-fmi2.fmu (tools/build-fmu.sh
m113 FMU_DIR); SPATIAL_JOB_DIR the default 3-D main job's output
(`trackgen spatial --out DIR`: the bump across both tracks, a 90° turn,
14 s, rows every 10 ms). Checks, each failing loudly:

1. fmpy's validation of each FMU finds no problem;
2. simulated by fmpy with its defaults (the 3-D main job's), every output
   equals the job's `spatial.csv` column at every communication point
   within 1e-9 of that column's largest magnitude (the FMU takes the
   native run's steps, so the difference is expected to be 0; the
   engine's columns are NaN in both);
3. a bad steering mode gives an error status and a logged message naming
   it, and the instance goes on;
4. steered by its input: with `steering = yaw_rate`, 0.3 rad/s asked from
   3 to 6 s at 1 m/s turns the hull left through the 0.9 rad wanted (the
   input's integral), within 0.05 rad 4 s later;
5. with FMUSIM (the Reference FMUs' importer), each FMU simulated by it
   equals the job as in 2 (its CSV prints 16 significant digits).
"""

import sys
from pathlib import Path

import numpy as np
from fmpy import extract, read_model_description, simulate_fmu
from fmpy.fmi1 import FMICallException
from fmpy.fmi3 import FMU3Slave
from fmpy.validation import validate_fmu

from fmu_compare import compare, fmusim_compare, read_csv

STOP, STEP = 14.0, 0.01
NAMES = ["M113Spatial.fmu", "M113Spatial-fmi2.fmu"]


def instance(path, messages):
    md = read_model_description(path)
    refs = {v.name: v.valueReference for v in md.modelVariables}
    fmu = FMU3Slave(guid=md.guid, unzipDirectory=extract(path),
                    modelIdentifier=md.coSimulation.modelIdentifier, instanceName="check")
    fmu.instantiate(logMessage=lambda env, status, category, message:
                    messages.append((status, message.decode())))
    return fmu, refs


def main():
    fmu_dir, job = Path(sys.argv[1]), Path(sys.argv[2])
    native = read_csv(job / "spatial.csv")
    outputs = [name for name in native if name != "t"]

    for name in NAMES:
        path = str(fmu_dir / name)
        problems = validate_fmu(path)
        print(f"{name}: fmpy's validation: {len(problems)} problems {problems}")
        assert not problems
        result = simulate_fmu(path, stop_time=STOP, output_interval=STEP, output=outputs)
        compare(name, result, native)

    path = str(fmu_dir / NAMES[0])

    # A bad steering mode: an error status, a message, the instance goes on.
    messages = []
    fmu, refs = instance(path, messages)
    try:
        fmu.setString([refs["steering"]], ["wheel"])
        raise AssertionError("steering = wheel was accepted")
    except FMICallException as e:
        assert e.status == 3, e
    assert any(s == 3 and "steering" in m for s, m in messages), messages
    print(f"bad parameter: error status, logged: {messages[-1][1]!r}")

    # Steered by the input: the heading wanted turns at the rate asked.
    fmu.setString([refs["steering"]], ["yaw_rate"])
    fmu.setString([refs["course"]], ["flat"])
    fmu.setFloat64([refs["profile_speed"]], [1.0])
    fmu.enterInitializationMode(startTime=0.0, stopTime=10.0)
    fmu.exitInitializationMode()
    h = 0.05
    for k in range(200):
        t = k * h
        fmu.setFloat64([refs["target_yaw_rate"]], [0.3 if 3.0 <= t + 1e-9 < 6.0 else 0.0])
        fmu.doStep(t, (k + 1) * h - t)
    heading, yaw_rate = fmu.getFloat64([refs["heading"], refs["yaw_rate"]])
    fmu.terminate()
    fmu.freeInstance()
    print(f"steered by target_yaw_rate: heading {heading:.4f} rad against 0.9 wanted, "
          f"yaw rate {yaw_rate:.4f} rad/s at 10 s")
    assert abs(heading - 0.9) < 0.05 and abs(yaw_rate) < 0.02

    if len(sys.argv) > 3:
        fmusim_compare(sys.argv[3], fmu_dir, NAMES, STOP, STEP, native)

    print("fmu-check-spatial: all checks passed")


if __name__ == "__main__":
    main()
