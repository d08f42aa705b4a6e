"""The reproduction table (scripts/reproduce-paper.sh): for each ensemble of a sbanalyze results
file, ours (mean +- sd, count) beside the paper's phi, Z and phi_R (data/mst-reference-values.csv),
with the issue's acceptance tests: |phi - phi_paper| <= 2 sqrt(sd_paper^2 + sd^2 / n),
|Z - Z_paper| <= 0.05, phi_R inside the paper's +- 2 sd band. Also alpha when the results have
it. Markdown on stdout.

usage: reproduction_table.py RESULTS.h5 REFERENCE.csv"""
import csv
import math
import sys

import h5py


def paper_rows(path):
    with open(path) as f:
        lines = [line for line in f if not line.startswith("#")]
    return {round(float(r["p"]), 4): r for r in csv.DictReader(lines)}


def number(row, key):
    value = row.get(key, "") if row else ""
    return float(value) if value not in ("", None) else math.nan


def mark(ok):
    return "n/a" if ok is None else ("yes" if ok else "**no**")


def ensemble_row(group, paper):
    n = int(group.attrs["n_files"])
    p = float(group.attrs["p"])
    phi, phi_sd = float(group.attrs["phi"]), float(group.attrs["phi_std"])
    contacts = group["contacts"].attrs if "contacts" in group else {}
    z = float(contacts.get("z_mean", math.nan))
    z_sd = float(contacts.get("z_mean_std", math.nan))
    r = 100 * float(contacts.get("rattler_fraction", math.nan))
    r_sd = 100 * float(contacts.get("rattler_fraction_std", math.nan))
    ref = paper.get(round(p, 4))
    pphi, pphi_sd = number(ref, "phi"), number(ref, "phi_sd")
    pz, pr, pr_sd = number(ref, "Z"), number(ref, "phi_R_percent"), number(ref, "phi_R_sd_percent")
    ok_phi = None if math.isnan(pphi) else abs(phi - pphi) <= 2 * math.sqrt(pphi_sd**2 + phi_sd**2 / n)
    ok_z = None if math.isnan(pz) or math.isnan(z) else abs(z - pz) <= 0.05
    ok_r = None if math.isnan(pr) or math.isnan(r) else abs(r - pr) <= 2 * pr_sd
    hyper = group["hyperuniformity"].attrs if "hyperuniformity" in group else {}
    alpha = float(hyper.get("alpha", math.nan))
    return (f"| {p:g} | {int(group.attrs['n_particles'])} | {n} | {phi:.5f} +- {phi_sd:.5f} | "
            f"{pphi:.5f} +- {pphi_sd:.5f} | {mark(ok_phi)} | {z:.3f} +- {z_sd:.3f} | {pz:.3f} | "
            f"{mark(ok_z)} | {r:.2f} +- {r_sd:.2f} | {pr:.2f} +- {pr_sd:.2f} | {mark(ok_r)} | "
            f"{alpha:.2f} | {number(ref, 'alpha'):.2f} |")


def main(results, reference):
    paper = paper_rows(reference)
    print("| p | N | n | phi (ours) | phi (paper) | phi ok | Z (ours) | Z (paper) | Z ok | "
          "phi_R % (ours) | phi_R % (paper) | phi_R ok | alpha (ours) | alpha (paper) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    with h5py.File(results) as f:
        groups = sorted(f["ensembles"].values(), key=lambda g: float(g.attrs["p"]))
        for group in groups:
            print(ensemble_row(group, paper))
    print("\nphi ok: |phi - phi_paper| <= 2 sqrt(sd_paper^2 + sd^2 / n); Z ok: |Z - Z_paper| <= "
          "0.05; phi_R ok: inside the paper's +- 2 sd. Paper: data/mst-reference-values.csv "
          "(N = 5000 for p != 1, N = 1000 for spheres, final pressure 1e14).")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(*sys.argv[1:])
