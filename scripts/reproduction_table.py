"""The reproduction tables (scripts/reproduce-paper.sh), markdown on stdout.

Table 1, for each ensemble of a sbanalyze results file: ours (mean +- sd, count) beside the
paper's phi, Z and phi_R (data/mst-reference-values.csv), with issue 18's acceptance tests
(|phi - phi_paper| <= 2 sqrt(sd_paper^2 + sd^2 / n), |Z - Z_paper| <= 0.05, phi_R inside the
paper's +- 2 sd band) and the cost of the packings (sbgen's CPU seconds, from each input's
provenance when the input is still there).

Table 2, when the results have them: the order metrics and the verdict (docs/order-metrics.md).
Table 3, when the results have them: where the contacts sit on the particles (the regions of
their ends and the pair types, docs/contact-types.md).
Table 4, when the results have them: the local packing fractions of the set-Voronoi cells
(docs/local-structure.md).
Table 5, when the results have them: the mean width w / D (D = 2R, paper Eq. w), the pore-size
moments and transport bounds in units of w (paper Eqs. 17-20), and the hyperuniformity fit
(alpha from the spreadability, a0, a1 and H from chi_V = a0 + a1 Q^alpha; the paper's a0 in
1e-4 w^3, a1 in 1e-3, H in 1e-3, as printed in its Table tab:fit).
Table 6, when the results have them: the jamming categories (docs/jamming.md): the packings per
category reached, those left undecided, whether every contact opens (no self-stress: Gordan's
alternative), the backbone, its contacts and the Maxwell deficit (the floppy modes where every
contact opens).

Table 1 holds the ensembles whose p the paper tabulates; the others (issue 68, "Beyond the
paper's range") go to Table 1b: phi, Z and phi_R with the acceptance's checks (overlapping pairs
by sbanalyze's own exact signed distance, jammed by sbgen's check, ordered by sbanalyze's
verdict), the CPU time per packing, and, where SECOND.csv (data/jst2010-reference-values.csv)
states a value for that p, Jiao, Stillinger & Torquato 2010's Z and P4 beside ours.

usage: reproduction_table.py RESULTS.h5 REFERENCE.csv [SECOND.csv]"""
import csv
import math
import os
import statistics
import sys

import h5py


def paper_rows(path):
    with open(path) as f:
        lines = [line for line in f if not line.startswith("#")]
    return {round(float(r["p"]), 4): r for r in csv.DictReader(lines)}


def number(row, key):
    value = row.get(key, "") if row else ""
    return float(value) if value not in ("", None) else math.nan


def paper_value(row, key):
    """The paper's value to two decimals, "-" where it has none (p beyond its table)."""
    value = number(row, key)
    return "-" if math.isnan(value) else f"{value:.2f}"


def mark(ok):
    return "n/a" if ok is None else ("yes" if ok else "**no**")


def attr(group, name, key):
    """(mean, sd) of attribute key of subgroup name, nan where absent."""
    if name not in group:
        return math.nan, math.nan
    a = group[name].attrs
    return float(a.get(key, math.nan)), float(a.get(key + "_std", math.nan))


def provenance_values(results, group, *keys):
    """key -> sbgen's provenance attribute key of the ensemble's packings that can still be
    read, each packing opened once."""
    values = {key: [] for key in keys}
    for member in group["members"][:]:
        path = results["files"][str(member)].attrs["input"]
        path = path.decode() if isinstance(path, bytes) else path
        if os.path.exists(path):
            with h5py.File(path) as f:
                attrs = f["provenance"].attrs if "provenance" in f else {}
                for key in keys:
                    if key in attrs:
                        values[key].append(float(attrs[key]))
    return values


def cpu_seconds(results, group):
    """sbgen's CPU seconds of the ensemble's packings that can still be read: (mean, max)."""
    times = provenance_values(results, group, "cpu_time_s")["cpu_time_s"]
    return (sum(times) / len(times), max(times)) if times else (math.nan, math.nan)


def structure_row(results, group, paper):
    n = int(group.attrs["n_files"])
    p = float(group.attrs["p"])
    phi, phi_sd = float(group.attrs["phi"]), float(group.attrs["phi_std"])
    z, z_sd = attr(group, "contacts", "z_mean")
    r, r_sd = (100 * v for v in attr(group, "contacts", "rattler_fraction"))
    ref = paper.get(round(p, 4))
    pphi, pphi_sd = number(ref, "phi"), number(ref, "phi_sd")
    pz, pr, pr_sd = number(ref, "Z"), number(ref, "phi_R_percent"), number(ref, "phi_R_sd_percent")
    ok_phi = None if math.isnan(pphi) else abs(phi - pphi) <= 2 * math.sqrt(pphi_sd**2 + phi_sd**2 / n)
    ok_z = None if math.isnan(pz) or math.isnan(z) else abs(z - pz) <= 0.05
    ok_r = None if math.isnan(pr) or math.isnan(r) else abs(r - pr) <= 2 * pr_sd
    # The same with our mean's own sampling error, as for phi: rattlers are few (a fraction f of
    # N scatters by about sqrt(f / N) per packing), so at N = 1000 and n = 5 our mean's error is
    # as large as the paper's band.
    ok_r_both = None if ok_r is None else abs(r - pr) <= 2 * math.sqrt(pr_sd**2 + r_sd**2 / n)
    cpu_mean, cpu_max = cpu_seconds(results, group)
    return (f"| {p:g} | {int(group.attrs['n_particles'])} | {n} | {pm((phi, phi_sd), 1, 5, n)} | "
            f"{pphi:.5f} +- {pphi_sd:.5f} | {mark(ok_phi)} | {pm((z, z_sd), 1, 3, n)} | {pz:.3f} | "
            f"{mark(ok_z)} | {pm((r, r_sd), 1, 2, n)} | {pr:.2f} +- {pr_sd:.2f} | {mark(ok_r)} | "
            f"{mark(ok_r_both)} | "
            f"{cpu_mean:.0f} / {cpu_max:.0f} |")


def second_rows(path):
    """Jiao, Stillinger & Torquato 2010's stated values: quantity -> (p_min, p_max, low, high)."""
    if not path:
        return {}
    with open(path) as f:
        rows = csv.DictReader(line for line in f if not line.startswith("#"))
        return {r["quantity"]: tuple(float(r[k]) for k in ("p_min", "p_max", "low", "high"))
                for r in rows}


def second_value(second, quantity, p):
    """'8.15' or '0.03-0.21' where the second reference states quantity at p, else '-'."""
    if quantity not in second:
        return "-"
    p_min, p_max, low, high = second[quantity]
    if not p_min <= p <= p_max:
        return "-"
    return f"{low:g}" if low == high else f"{low:g}-{high:g}"


def member_sum(results, group, subgroup, key):
    """The sum of files/<member>/subgroup's attribute key over the ensemble, or None."""
    values = [results["files"][str(m)][subgroup].attrs[key] for m in group["members"][:]
              if subgroup in results["files"][str(m)]]
    return int(sum(values)) if values else None


def beyond_row(results, group, second):
    n = int(group.attrs["n_files"])
    p = float(group.attrs["p"])
    overlaps = member_sum(results, group, "contacts", "overlapping_pairs")
    provenance = provenance_values(results, group, "jammed", "cpu_time_s", "stall_speed")
    jammed, times = provenance["jammed"], provenance["cpu_time_s"]
    raised = len(provenance["stall_speed"])  # written only by a run raised at a plateau
    ordered = (f"{ordered_count(results, group)} of {n}"
               if any("order" in results["files"][str(m)] for m in group["members"][:]) else "-")
    return (f"| {p:g} | {int(group.attrs['n_particles'])} | {n} | "
            f"{pm((float(group.attrs['phi']), float(group.attrs['phi_std'])), 1, 4, n)} | "
            f"{pm(attr(group, 'contacts', 'z_mean'), 1, 3, n)} | "
            f"{second_value(second, 'Z', p)} | "
            f"{pm(attr(group, 'contacts', 'rattler_fraction'), 100, 2, n)} | "
            f"{pm(attr(group, 'order', 'P4'), 1, 3, n)} | {second_value(second, 'P4', p)} | "
            f"{'-' if overlaps is None else overlaps} | "
            f"{int(sum(jammed))} of {len(jammed)} | {ordered} | {raised} | "
            f"{statistics.median(times) if times else math.nan:.0f} / "
            f"{max(times, default=math.nan):.0f} |")


def width_over_axis(results, group):
    """w / D, the mean width over the major axis D = 2 semi_axis, of each member on its own (each
    packing has its own grown D; sbanalyze info prints the same ratio): their mean."""
    ratios = [float(a["mean_width"]) / (2 * float(a["semi_axis"]))
              for a in (results["files"][str(m)].attrs for m in group["members"][:])]
    return sum(ratios) / len(ratios)


def pm(pair, scale=1.0, digits=3, n=2):
    """mean +- sd, or the value alone where one packing has no spread (n = 1)."""
    mean, sd = pair
    if math.isnan(mean):
        return "-"
    if n < 2:
        return f"{mean * scale:.{digits}f} (one packing)"
    return f"{mean * scale:.{digits}f} +- {sd * scale:.{digits}f}"


def members_with(results, group, name):
    """How many of the ensemble's packings have the analysis `name` (one skipped on a packing,
    e.g. hyperuniformity where the box is too small for alpha's window, writes none)."""
    return sum(name in results["files"][str(m)] for m in group["members"][:])


def over_members(text, k, n):
    """`text` (a cell of the ensemble's value), saying over how many of the n packings where
    only k have it: "0.10 (1 of 5)"."""
    if k == n or text == "-":
        return text
    return f"{text.replace(' (one packing)', '')} ({k} of {n})"


def pooled(group, key, scale, digits):
    """The ensemble's one fit through every member's wave vectors: value +- its standard error."""
    h = group["hyperuniformity"].attrs if "hyperuniformity" in group else {}
    value = float(h.get(key + "_pooled", math.nan))
    if math.isnan(value):
        return "-"
    return f"{value * scale:.{digits}f} +- {float(h[key + '_pooled_stderr']) * scale:.{digits}f}"


def transport_row(results, group, paper):
    p = float(group.attrs["p"])
    ref = paper.get(round(p, 4))
    n = int(group.attrs["n_files"])
    width = width_over_axis(results, group)
    k = members_with(results, group, "spreadability")
    kh = members_with(results, group, "hyperuniformity")
    return (f"| {p:g} | {width:.4f} | {pm(attr(group, 'pore_size', 'mean_w'), 1e2, 3, n)} | "
            f"{pm(attr(group, 'transport', 'permeability_w2'), 1e4, 3, n)} | "
            f"{pm(attr(group, 'transport', 'mean_survival_time_w2'), 1e3, 3, n)} | "
            f"{pm(attr(group, 'transport', 'principal_relaxation_time_w2'), 1e3, 3, n)} | "
            f"{over_members(pm(attr(group, 'spreadability', 'alpha'), 1, 2, k), k, n)} | "
            f"{paper_value(ref, 'alpha')} | "
            f"{over_members(pooled(group, 'a0', 1e4, 1), kh, n)} | {paper_value(ref, 'a0_e-4')} | "
            f"{over_members(pooled(group, 'a1', 1e3, 2), kh, n)} | {paper_value(ref, 'a1_e-3')} | "
            f"{over_members(pooled(group, 'H', 1e3, 1), kh, n)} | {paper_value(ref, 'H_e-3')} |")


def ordered_count(results, group):
    """How many of the ensemble's packings sbanalyze's order verdict calls ordered."""
    return sum(int(results["files"][str(m)]["order"].attrs["ordered"])
               for m in group["members"][:] if "order" in results["files"][str(m)])


def order_row(results, group):
    n = int(group.attrs["n_files"])
    return (f"| {float(group.attrs['p']):g} | {int(group.attrs['n_particles'])} | {n} | "
            f"{pm(attr(group, 'order', 'q6_local_mean'), 1, 3, n)} | "
            f"{pm(attr(group, 'order', 'Q6'), 1, 3, n)} | {pm(attr(group, 'order', 'T'), 1, 3, n)} | "
            f"{pm(attr(group, 'order', 'P4'), 1, 4, n)} | "
            f"{pm(attr(group, 'order', 'solid_like_fraction'), 1, 4, n)} | "
            f"{pm(attr(group, 'order', 'crystal_cluster_fraction'), 1, 4, n)} | "
            f"{ordered_count(results, group)} of {n} |")


def local_structure_row(results, group):
    n = int(group.attrs["n_files"])
    first = results["files"][str(group["members"][0])]
    voxels = int(first["voronoi"].attrs["voxels"]) if "voronoi" in first else "?"
    return (f"| {float(group.attrs['p']):g} | {int(group.attrs['n_particles'])} | {n} | "
            f"{pm(attr(group, 'voronoi', 'local_phi_mean'), 1, 4, n)} | "
            f"{pm(attr(group, 'voronoi', 'local_phi_sd'), 1, 4, n)} | "
            f"{pm(attr(group, 'voronoi', 'local_phi_mean_non_rattlers'), 1, 4, n)} | "
            f"{pm(attr(group, 'voronoi', 'local_phi_mean_rattlers'), 1, 4, n)} | "
            f"{pm(attr(group, 'voronoi', 'local_phi_min'), 1, 3, n)} | "
            f"{pm(attr(group, 'voronoi', 'local_phi_max'), 1, 3, n)} | {voxels} | "
            f"{variance_alpha(group, n)} | {pooled_variance_alpha(group)} |")


def variance_alpha(group, n):
    """The variance route's alpha, mean +- sd over the packings with a tail fit."""
    if "variance" not in group or "alpha" not in group["variance"].attrs:
        return "-"
    return pm(attr(group, "variance", "alpha"), 1, 2, n)


def pooled_variance_alpha(group):
    """The tail fit to the ensemble's mean sigma_V^2, +- its error, saying where it saturates."""
    v = group["variance"].attrs if "variance" in group else {}
    if "alpha_pooled" not in v:
        return "-"
    text = f"{float(v['alpha_pooled']):.2f} +- {float(v['alpha_pooled_error']):.2f}"
    return text + (" (>= 1)" if int(v["alpha_pooled_saturated"]) else "")


REGIONS = ("axis", "edge", "diagonal")
PAIRS = [(a, b) for i, a in enumerate(REGIONS) for b in REGIONS[i:]]  # the schema's order


def contact_types_row(group):
    n = int(group.attrs["n_files"])
    ends = " | ".join(pm(attr(group, "contacts", f"{r}_fraction"), 1, 3, n) for r in REGIONS)
    pairs = " | ".join(pm(attr(group, "contacts", f"{a}_{b}_fraction"), 1, 3, n)
                       for a, b in PAIRS)
    return (f"| {float(group.attrs['p']):g} | {int(group.attrs['n_particles'])} | {n} | "
            f"{pm(attr(group, 'contacts', 'axis_angle_mean'), 1, 2, n)} | {ends} | {pairs} |")


STRUCTURE_HEADER = ("p", "N", "n", "phi (ours)", "phi (paper)", "phi ok", "Z (ours)", "Z (paper)",
                    "Z ok", "phi_R % (ours)", "phi_R % (paper)", "phi_R ok",
                    "phi_R ok (both errors)", "sbgen CPU s (mean / max)")
STRUCTURE_NOTE = (
    "phi ok: |phi - phi_paper| <= 2 sqrt(sd_paper^2 + sd^2 / n); Z ok: |Z - Z_paper| <= 0.05; "
    "phi_R ok: inside the paper's +- 2 sd; phi_R ok (both errors): |phi_R - phi_R_paper| <= "
    "2 sqrt(sd_paper^2 + sd^2 / n), as for phi. Paper: data/mst-reference-values.csv (N = 5000 "
    "for p != 1, N = 1000 for spheres, final pressure 1e14). CPU s: sbgen's, from each "
    "packing's provenance.")
TRANSPORT_HEADER = ("p", "w / D", "<delta> / w (1e-2)", "k / w^2 (1e-4)", "tau D_diff / w^2 (1e-3)",
                    "T1 D_diff / w^2 (1e-3)", "alpha (ours)", "alpha (paper)", "a0 (1e-4 w^3, ours)",
                    "a0 (paper)", "a1 (1e-3, ours)", "a1 (paper)", "H (1e-3, ours)", "H (paper)")
TRANSPORT_NOTE = (
    "Mean +- sd over the ensemble's packings (the value alone for one packing); w / D of each "
    "packing on its own (as sbanalyze info prints it), averaged. Pore sizes and transport: "
    "{pores}; k, tau and T1 are the paper's bounds (Eqs. "
    "17-20, diffusion-controlled: T1 D_diff / w^2 = <delta^2> / w^2). alpha from the spreadability "
    "(mean +- sd of the packings' alphas); a0, a1, H from one fit of chi_V = a0 + a1 Q^alpha "
    "through every packing's wave vectors at the ensemble's pooled alpha, +- its least-squares "
    "standard error (docs/hyperuniformity.md, \"Ensembles\"); (k of n): over the k packings "
    "the analysis ran on (hyperuniformity skips a packing whose box is too small for alpha's "
    "window). The paper prints no table of "
    "w, pore sizes or transport (its figures only).")


ORDER_HEADER = ("p", "N", "n", "mean local q6", "Q6", "T", "P4", "solid-like fraction",
                "largest crystal / N", "ordered")
ORDER_NOTE = (
    "Order metrics (sbanalyze --compute order, docs/order-metrics.md): mean local q6 and global "
    "Q6 over the bonds shorter than the first minimum of g2, T over the fcc shells, the cubatic "
    "P4 of the axes (none for spheres), the fraction of solid-like particles (ten Wolde-Frenkel, "
    "SANN neighbours) and the largest crystalline cluster over N; ordered: packings the verdict "
    "calls ordered (mean local q6 >= 0.5, T >= 0.3 over its 12 shells, P4 >= 0.5, solid-like "
    "fraction >= 0.15 or largest crystal >= 0.1 N; fcc: q6 0.575, T 1, solid-like 1). The paper "
    "reports none of them.")


CONTACT_TYPES_HEADER = (("p", "N", "n", "mean theta (deg)")
                        + tuple(f"{r} ends" for r in REGIONS)
                        + tuple(f"{a}-{b}" for a, b in PAIRS))
CONTACT_TYPES_NOTE = (
    "Where the contacts between non-rattlers sit on the particles (sbanalyze --compute contacts, "
    "docs/contact-types.md): theta is the angle between an end's body-frame normal and the "
    "nearest body axis; an end's region is the nearest symmetry direction, <100> axis (the "
    "cube's face for p > 1, the octahedron's vertex for p < 1), <110> edge, <111> diagonal (the "
    "cube's vertex, the octahedron's face); the pair columns are the fractions of the contacts "
    "by the regions of their two ends. Normals uniform on the sphere (the sphere limit, Eq. 2.4 "
    "there): ends 0.275 / 0.444 / 0.282, mean theta 31.90 deg; two independent uniform ends: "
    "pairs 0.075 / 0.244 / 0.155 / 0.197 / 0.250 / 0.079. Spheres' orientations carry no "
    "physics: with equal orientations a contact's ends share a region (like pairs only). The "
    "paper asks for these (its closing section) and reports none.")


LOCAL_HEADER = ("p", "N", "n", "mean local phi", "sd of local phi", "mean, non-rattlers",
                "mean, rattlers", "smallest", "largest", "M", "alpha (variance route)",
                "alpha (variance route, pooled)")
LOCAL_NOTE = (
    "Set-Voronoi cells (sbanalyze --compute voronoi, docs/local-structure.md): phi_i = v1 / "
    "v_cell(i) on the --voxels grid of M^3; mean +- sd over the ensemble of each packing's mean, "
    "standard deviation and extremes of phi_i; rattlers by the contact network. The harmonic "
    "mean of phi_i is phi (the cells tile the box). At M = 300 the voxel cells overstate the sd "
    "by about 0.3 % (spheres) to 0.7 % (p = 1.5). alpha (variance route): the tail of sigma_V^2(R) "
    "(sbanalyze --compute variance, docs/local-structure.md §2), mean +- sd over the packings, "
    "and its fit to the ensemble's mean sigma_V^2 (pooled; >= 1: saturated); at N = 5000 the "
    "window [2 w, L / 4] is short and the surface term leads: these alphas agree with the "
    "spreadability's within errors too wide to test it (docs/local-structure.md §2). The paper "
    "reports none of them.")


JAMMING_HEADER = ("p", "N", "n", "strict", "collective", "local", "none",
                  "undecided (local)", "every contact opens", "opening per contact (1e-4 D)",
                  "backbone", "contacts", "floppy modes", "s per packing")
JAMMING_NOTE = (
    "Jamming categories (sbanalyze --compute jamming, docs/jamming.md) at the jam check's "
    "network (gap < max(1e-10, 100 / P) D), rattlers removed: the packings per category reached "
    "(strict, collective, local, none), those whose local test is left undecided (an opening "
    "that slides a closed contact: curvature decides, p != 1), and those whose collective and "
    "strict tests find a first-order motion that opens every contact (Gordan's alternative: "
    "no self-stress exists, the packing as given is not collectively jammed; docs/jamming.md "
    "§3), with that motion's opening per contact at a largest step of 1 D. Floppy modes: the "
    "collective Maxwell deficit, 6 N_b - 3 - contacts (3 N_b for spheres), which equals "
    "dim ker A^T - 3 where every contact opens (A has full column rank). Mean +- sd over the "
    "packings. The paper tests no category.")


BEYOND_HEADER = ("p", "N", "n", "phi", "Z", "Z (JST 2010)", "phi_R %", "P4", "P4 (JST 2010)",
                 "overlapping pairs", "jammed (sbgen)", "ordered", "raised at a plateau",
                 "sbgen CPU s (median / max)")
BEYOND_NOTE = (
    "Ensembles at p the paper does not tabulate (issue 68): mean +- sd over the packings; Z and "
    "phi_R over the contact network at gaps < 1e-10 D, as for the paper's range; P4 the cubatic "
    "order of the axes. Overlapping pairs: summed over the ensemble, by sbanalyze's exact signed "
    "distance (independent of sbgen's predictor); jammed: sbgen's jam check, from each packing's "
    "provenance; ordered: sbanalyze's verdict (docs/order-metrics.md); raised at a plateau: "
    "the packings whose slow phase sbgen sped up where the pressure stalled on a jammed, "
    "creeping network (provenance stall_speed; docs/design.md §3, \"Plateaus\"). JST 2010: Jiao, "
    "Stillinger & Torquato, PRE 81, 041304 (data/jst2010-reference-values.csv), the values its "
    "text states for 0.85 <= p <= 3 (its phi and Z are curves only): Z's plateau 8.15 from "
    "p = 1.4, and P4 between 0.03 and 0.21, growing with |p - 1|; a deforming box and fast "
    "growth, N not stated.")


def jamming_row(group):
    n = int(group.attrs["n_files"])
    p = float(group.attrs["p"])
    j = group["jamming"].attrs
    counts = [str(int(j.get(f"n_{name}", 0))) for name in
              ("strict", "collective", "local", "none")]
    undecided = int(group["jamming_local"].attrs.get("n_undecided", 0)) \
        if "jamming_local" in group else 0
    collective = group["jamming_collective"] if "jamming_collective" in group else None
    opens = "-"
    opening = floppy = "-"
    if collective is not None:
        c = collective.attrs
        opens = str(round(float(c.get("opens_every_contact", 0.0)) * n))
        opening = pm(attr(group, "jamming_collective", "largest_opening"), 1e4, 2, n)
        floppy = pm(attr(group, "jamming_collective", "isostatic_deficit"), 1.0, 0, n)
    return (f"| {p:g} | {int(group.attrs['n_particles'])} | {n} | " + " | ".join(counts)
            + f" | {undecided} | {opens} of {n} | {opening} | "
            + f"{pm(attr(group, 'jamming', 'backbone'), 1.0, 0, n)} | "
            + f"{pm(attr(group, 'jamming', 'contacts'), 1.0, 0, n)} | {floppy} | "
            + f"{float(j.get('runtime_s', math.nan)):.2g} |")


def pore_method(results):
    """The pore-size methods of the files, as their pore_size groups record them."""
    methods = set()
    for f in results["files"].values():
        if "pore_size" in f:
            a = f["pore_size"].attrs
            method = a["method"].decode() if isinstance(a["method"], bytes) else str(a["method"])
            voxels = int(a.get("voxels", 0))
            methods.add(f"{method} at M = {voxels}" if voxels else method)
    return ", ".join(sorted(methods)) + " (sbanalyze --pores, --pore-voxels)" if methods else "none"


def print_table(header, rows, note):
    print("| " + " | ".join(header) + " |")
    print("|" + "---|" * len(header))
    for row in rows:
        print(row)
    print("\n" + note)


def main(results_path, reference, second_path=None):
    paper = paper_rows(reference)
    second = second_rows(second_path)
    with h5py.File(results_path) as results:
        groups = sorted(results["ensembles"].values(), key=lambda g: float(g.attrs["p"]))
        tabulated = [round(float(g.attrs["p"]), 4) in paper for g in groups]
        inside = [g for g, t in zip(groups, tabulated) if t]
        beyond = [g for g, t in zip(groups, tabulated) if not t]
        if inside:
            print_table(STRUCTURE_HEADER, [structure_row(results, g, paper) for g in inside],
                        STRUCTURE_NOTE)
        if beyond:
            print("\n" if inside else "", end="")
            print_table(BEYOND_HEADER, [beyond_row(results, g, second) for g in beyond],
                        BEYOND_NOTE)
        if any("order" in g for g in groups):
            print()
            print_table(ORDER_HEADER, [order_row(results, g) for g in groups], ORDER_NOTE)
        if any("contacts" in g and "axis_angle_mean" in g["contacts"].attrs for g in groups):
            print()
            print_table(CONTACT_TYPES_HEADER, [contact_types_row(g) for g in groups],
                        CONTACT_TYPES_NOTE)
        if any("voronoi" in g for g in groups):
            print()
            print_table(LOCAL_HEADER, [local_structure_row(results, g) for g in groups],
                        LOCAL_NOTE)
        if any(name in g for g in groups for name in ("pore_size", "hyperuniformity")):
            print()
            print_table(TRANSPORT_HEADER, [transport_row(results, g, paper) for g in groups],
                        TRANSPORT_NOTE.format(pores=pore_method(results)))
        if any("jamming" in g for g in groups):
            print()
            print_table(JAMMING_HEADER, [jamming_row(g) for g in groups], JAMMING_NOTE)


if __name__ == "__main__":
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    main(*sys.argv[1:])
