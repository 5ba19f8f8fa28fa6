#!/usr/bin/env python3
"""The M113's FMUs through fmpy, an importer written outside this project.

    tools/fmu-check.py FMU_DIR MAIN_JOB_DIR [FMUSIM]

FMU_DIR holds M113.fmu and M113-fmi2.fmu (tools/build-fmu.sh m113 FMU_DIR);
MAIN_JOB_DIR the default main job's output (`trackgen --out DIR`: the bump
course, 8 s, rows every 10 ms). Checks, each failing loudly:

1. fmpy's validation of each FMU finds no problem;
2. simulated by fmpy with its defaults (the main job's), every output
   equals the main job's column at every communication point within
   1e-9 of that column's largest magnitude (the FMU takes the native run's
   steps, so the difference is expected to be 0);
3. a bad parameter gives an error status and a logged message naming it,
   and the process and the instance go on;
4. two instances in one process, stepped in turn with different spring
   rates, each give what the same instance gives alone;
5. with FMUSIM (the Reference FMUs' importer, tools/fmusim), each FMU
   simulated by it equals the main job as in 2 (its CSV prints 16
   significant digits, so the difference is its rounding).
"""

import sys
from pathlib import Path

import numpy as np
from fmpy import extract, read_model_description, simulate_fmu
from fmpy.fmi1 import FMICallException
from fmpy.fmi3 import FMU3Slave
from fmpy.validation import validate_fmu

from fmu_compare import compare, fmusim_compare, read_csv

STOP, STEP = 8.0, 0.01


def native_rows(main_job_dir):
    return read_csv(Path(main_job_dir) / "all.csv")


def stepped(path, start_values, n_steps, messages=None):
    """An FMI 3.0 instance made by hand, with its value references."""
    md = read_model_description(path)
    refs = {v.name: v.valueReference for v in md.modelVariables}
    fmu = FMU3Slave(guid=md.guid, unzipDirectory=extract(path),
                    modelIdentifier=md.coSimulation.modelIdentifier,
                    instanceName="check")
    def log(env, status, category, message):
        if messages is not None:
            messages.append(message.decode())
    fmu.instantiate(logMessage=log)
    for name, value in start_values.items():
        fmu.setFloat64([refs[name]], [value])
    fmu.enterInitializationMode(startTime=0.0, stopTime=n_steps * STEP)
    fmu.exitInitializationMode()
    return fmu, refs


def main():
    fmu_dir, main_job = Path(sys.argv[1]), sys.argv[2]
    native = native_rows(main_job)
    outputs = [name for name in native if name != "t"]

    for name in ["M113.fmu", "M113-fmi2.fmu"]:
        path = str(fmu_dir / name)
        problems = validate_fmu(path)
        print(f"{name}: fmpy's validation: {len(problems)} problems {problems}")
        assert not problems
        result = simulate_fmu(path, stop_time=STOP, output_interval=STEP, output=outputs)
        compare(name, result, native)

    path = str(fmu_dir / "M113.fmu")

    # A bad parameter: an error status, a message, and the instance goes on.
    messages = []
    md = read_model_description(path)
    refs = {v.name: v.valueReference for v in md.modelVariables}
    fmu = FMU3Slave(guid=md.guid, unzipDirectory=extract(path),
                    modelIdentifier=md.coSimulation.modelIdentifier, instanceName="bad")
    fmu.instantiate(logMessage=lambda env, status, category, message:
                    messages.append((status, message.decode())))
    try:
        fmu.setFloat64([refs["bump_height"]], [5.0])
        raise AssertionError("a bump 5 m high was accepted")
    except FMICallException as e:
        assert e.status == 3, e
    assert any(s == 3 and "bump_height" in m for s, m in messages), messages
    print(f"bad parameter: error status, logged: {messages[-1][1]!r}")
    fmu.setFloat64([refs["bump_height"]], [0.05])
    fmu.enterInitializationMode(startTime=0.0, stopTime=0.1)
    fmu.exitInitializationMode()
    fmu.doStep(0.0, 0.1)
    fmu.terminate()
    fmu.freeInstance()

    # Two instances, stepped in turn, with different spring rates.
    n = 150
    rate = "rw1.arm_stiffness"
    declared = next(float(v.start) for v in md.modelVariables if v.name == rate)
    rates = [declared, 0.5 * declared]
    outputs_refs = [refs["y"], refs["pitch"], refs["seat_az"]]
    alone = []
    for k in rates:
        fmu, _ = stepped(path, {rate: k}, n)
        rows = []
        for i in range(n):
            fmu.doStep(i * STEP, (i + 1) * STEP - i * STEP)
            rows.append(fmu.getFloat64(outputs_refs))
        fmu.terminate(); fmu.freeInstance()
        alone.append(np.array(rows))
    pair = [stepped(path, {rate: k}, n)[0] for k in rates]
    together = [[], []]
    for i in range(n):
        for j, fmu in enumerate(pair):
            fmu.doStep(i * STEP, (i + 1) * STEP - i * STEP)
            together[j].append(fmu.getFloat64(outputs_refs))
    for fmu in pair:
        fmu.terminate(); fmu.freeInstance()
    for j in range(2):
        assert np.array_equal(np.array(together[j]), alone[j]), f"instance {j}"
    assert not np.array_equal(alone[0], alone[1]), "the spring rate changed nothing"
    print(f"two instances ({rate} {rates[0]:.0f} and {rates[1]:.0f} N m/rad), "
          f"stepped in turn for {n} steps: each equals its run alone")
    if len(sys.argv) > 3:
        fmusim_compare(sys.argv[3], fmu_dir, ["M113.fmu", "M113-fmi2.fmu"], STOP, STEP, native)

    print("fmu-check: all checks passed")


if __name__ == "__main__":
    main()
