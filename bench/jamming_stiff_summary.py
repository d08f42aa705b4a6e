"""Summarises bench/jamming_stiff.sh: one row per run, the jam verdict of sbgen beside the contact
network that `sbanalyze info --tolerance 1e-8` finds in the same file."""
import glob
import os
import re
import subprocess
import sys

import h5py

work, sbanalyze = sys.argv[1], sys.argv[2]


def info_at_1e8(path):
    """Contacts per particle, rattler fraction and smallest gap / D from sbanalyze info."""
    text = subprocess.run([sbanalyze, "info", "--tolerance", "1e-8", path], capture_output=True,
                          text=True).stdout
    number = r"([-+0-9.eE]+)"
    n = int(re.search(r"N = (\d+)", text).group(1))
    contacts = int(re.search(r"contacts \(gap < 1e-08 D\): (\d+)", text).group(1))
    # No phi_R where the contact resolution says 1e-8 D cuts through the load-bearing gaps (a
    # refusal below P ~ 1e10): NaN, and the row's check rests on the refusal itself.
    found = re.search(r"phi_R = " + number, text)
    rattlers = float(found.group(1)) if found else float("nan")
    gap = float(re.search(r"smallest gap +\= " + number, text).group(1))
    return 2.0 * contacts / n, rattlers, gap


def row(path):
    rc = int(open(path + ".rc").read())
    cpu = sum(float(user) + float(system) for user, system in
              re.findall(r"^([0-9.]+) ([0-9.]+)$", open(path + ".time").read(), re.M))
    name = os.path.basename(path)
    # The newest of the run's checkpoint and the one it resumed from (jamming_stiff.sh).
    saved = [f for f in (path[:-len(".h5")] + suffix for suffix in (".checkpoint.h5", ".resumed.h5"))
             if os.path.exists(f)]
    checkpoint = max(saved, key=os.path.getmtime) if saved else None
    if not os.path.exists(path) and checkpoint:
        with h5py.File(checkpoint, "r") as f:
            state = (f"P {float(f.attrs['reduced_pressure']):.2e}, phi "
                     f"{float(f.attrs['phi']):.4f}, "
                     f"{int(f['provenance'].attrs['collisions']) / 1e6:.2f} M collisions")
        return (f"| {name} | - | - | rc {rc}: capped, checkpoint at {state} (run the script "
                f"again to resume) | - | - | - | - | - | {cpu:.0f} |")
    if not os.path.exists(path):
        return f"| {name} | - | - | rc {rc}: no output (cap or error) | - | - | - | - | - | {cpu:.0f} |"
    with h5py.File(path, "r") as f:
        log = f["provenance"].attrs
        collisions = int(log["collisions"])
        jammed = int(log["jammed"])
        verdict = log["jam_check"]
        verdict = verdict.decode() if isinstance(verdict, bytes) else str(verdict)
        per = {k: log[k] / collisions for k in ("predictor_fallbacks",
                                               "predictor_robust_evaluations", "rechecks")}
        pressure, phi = float(f.attrs["reduced_pressure"]), float(f.attrs["phi"])
    z, rattlers, gap = info_at_1e8(path)
    ok = "ok" if (jammed == 0 and rc == 3) or (jammed == 1 and rc == 0 and z >= 5 and
                                                rattlers < 0.1 and gap > -1e-12) else "FAIL"
    return (f"| {name} | {phi:.4f} | {pressure:.2e} | rc {rc}, jammed {jammed}: {verdict[:90]} | "
            f"{z:.2f} | {100 * rattlers:.1f} % | {gap:.1e} | {ok} | "
            f"{collisions / 1e6:.2f} M; fallbacks {per['predictor_fallbacks']:.2f}, robust "
            f"{per['predictor_robust_evaluations']:.2f}, rechecks {per['rechecks']:.3f} | {cpu:.0f} |")


print("| run | phi | P | sbgen's verdict | contacts per particle at 1e-8 D | phi_R at 1e-8 D | "
      "smallest gap / D | check | collisions; per collision | CPU s |")
print("|" + "---|" * 10)
for path in sorted(glob.glob(f"{work}/stiff-*.h5.rc")):
    print(row(path[:-3]))
