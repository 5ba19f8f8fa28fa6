#!/usr/bin/env python3
"""The M113 FMU driven by fmpy against the native main job, wall time of
10 interleaved runs each: tools/fmu-timing.py out/fmu/M113.fmu (run from
the repository root after cargo build --release -p trackgen-cli)."""
import time, statistics, subprocess
from fmpy import simulate_fmu, read_model_description, extract
from fmpy.fmi3 import FMU3Slave
import sys
path = sys.argv[1]
md = read_model_description(path); d = extract(path)
refs = [v.valueReference for v in md.modelVariables if v.causality == "output"]
def run():
    fmu = FMU3Slave(guid=md.guid, unzipDirectory=d, modelIdentifier="M113", instanceName="p")
    fmu.instantiate(); fmu.enterInitializationMode(startTime=0.0, stopTime=8.0); fmu.exitInitializationMode()
    for i in range(800):
        fmu.doStep(i * 0.01, (i + 1) * 0.01 - i * 0.01)
        fmu.getFloat64(refs)
    fmu.terminate(); fmu.freeInstance()
fmu_t, nat_t = [], []
for _ in range(10):
    t = time.perf_counter(); run(); fmu_t.append(time.perf_counter() - t)
    t = time.perf_counter(); subprocess.run(["./target/release/trackgen", "--out", "target/fmu-timing"], stdout=subprocess.DEVNULL, check=True); nat_t.append(time.perf_counter() - t)
print(f"FMU (fmpy, 800 doStep + 202 outputs read each): best {min(fmu_t)*1e3:.1f} ms, median {statistics.median(fmu_t)*1e3:.1f} ms")
print(f"native main job (whole command, files written): best {min(nat_t)*1e3:.1f} ms, median {statistics.median(nat_t)*1e3:.1f} ms")
