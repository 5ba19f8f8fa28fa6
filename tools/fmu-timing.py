#!/usr/bin/env python3
"""An M113 FMU driven by fmpy against the native job it runs, wall time of
10 interleaved runs each: tools/fmu-timing.py out/fmu/M113.fmu (the main
job) or out/fmu/M113Spatial.fmu (the 3-D main job, `trackgen spatial`),
run from the repository root after cargo build --release -p trackgen-cli.
The FMU runs its default experiment, every output read at every
communication point."""
import time, statistics, subprocess
from fmpy import read_model_description, extract
from fmpy.fmi3 import FMU3Slave
import sys
path = sys.argv[1]
md = read_model_description(path); d = extract(path)
refs = [v.valueReference for v in md.modelVariables if v.causality == "output"]
stop = float(md.defaultExperiment.stopTime)
step = float(md.defaultExperiment.stepSize)
n = round(stop / step)
spatial = md.modelName.endswith("Spatial")
native = ["./target/release/trackgen"] + (["spatial"] if spatial else []) + ["--out", "target/fmu-timing"]
def run():
    fmu = FMU3Slave(guid=md.guid, unzipDirectory=d,
                    modelIdentifier=md.coSimulation.modelIdentifier, instanceName="p")
    fmu.instantiate(); fmu.enterInitializationMode(startTime=0.0, stopTime=stop); fmu.exitInitializationMode()
    for i in range(n):
        fmu.doStep(i * step, (i + 1) * step - i * step)
        fmu.getFloat64(refs)
    fmu.terminate(); fmu.freeInstance()
fmu_t, nat_t = [], []
for _ in range(10):
    t = time.perf_counter(); run(); fmu_t.append(time.perf_counter() - t)
    t = time.perf_counter(); subprocess.run(native, stdout=subprocess.DEVNULL, check=True); nat_t.append(time.perf_counter() - t)
print(f"FMU (fmpy, {n} doStep + {len(refs)} outputs read each): best {min(fmu_t)*1e3:.1f} ms, median {statistics.median(fmu_t)*1e3:.1f} ms")
print(f"native ({' '.join(native[1:])}: the whole command, files written): best {min(nat_t)*1e3:.1f} ms, median {statistics.median(nat_t)*1e3:.1f} ms")
