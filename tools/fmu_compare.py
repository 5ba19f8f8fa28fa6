"""What tools/fmu-check.py and tools/fmu-check-spatial.py share: a native
job's CSV read, an FMU's outputs held to it, and fmusim's run of an FMU
held to it."""

import csv
import subprocess
import tempfile
from pathlib import Path

import numpy as np

# The outputs' largest difference from the native job's, relative to each
# column's largest magnitude: the FMU takes the native run's steps, so 0
# is expected; fmusim's CSV prints 16 significant digits.
TOLERANCE = 1e-9


def read_csv(path, time="t"):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header = [name.strip('"') for name in rows[0]]
    values = np.array(rows[1:], dtype=float)
    return {(time if name == "time" else name): values[:, i] for i, name in enumerate(header)}


def compare(label, result, native):
    """The largest difference over every output column, relative to the
    column's largest magnitude (NaN against NaN counts as equal; a NaN
    against a number fails); fails above TOLERANCE."""
    # (fmusim prints times with 16 significant digits.)
    assert np.allclose(result["time"], native["t"], rtol=0, atol=1e-12), \
        f"{label}: the communication points"
    worst, where = 0.0, None
    for name, column in native.items():
        if name == "t":
            continue
        got = result[name]
        both_nan = np.isnan(got) & np.isnan(column)
        assert np.array_equal(np.isnan(got), np.isnan(column)), f"{label}: {name}'s NaNs"
        if both_nan.all():
            continue
        scale = max(np.nanmax(np.abs(column)), 1e-300)
        diff = np.nanmax(np.abs(np.where(both_nan, 0.0, got - column))) / scale
        if diff > worst:
            worst, where = diff, name
    print(f"{label}: {len(native) - 1} outputs at {len(native['t'])} points; "
          f"largest difference {worst:.1e} of the column's range"
          + (f" ({where})" if where else ""))
    assert worst <= TOLERANCE, f"{label}: {where} differs by {worst:.2e}"


def fmusim_compare(fmusim, fmu_dir, names, stop, step, native):
    """Each FMU of `names` in `fmu_dir` simulated by fmusim (the Reference
    FMUs' importer) with its outputs every `step` s to `stop` s, held to
    `native` by compare."""
    for name in names:
        with tempfile.TemporaryDirectory() as tmp:
            out = Path(tmp) / "out.csv"
            subprocess.run([fmusim, "--interface-type", "cs", "--set-stop-time",
                            "--stop-time", str(stop), "--output-interval", str(step),
                            "--output-file", str(out), str(Path(fmu_dir) / name)], check=True)
            compare(f"fmusim {name}", read_csv(out, time="time"), native)
