"""The table of bench/jamming_relax.sh: per packing, its jamming category as given and relaxed
(docs/jamming.md §6.7), the jamming shell's bracket, the motion, the second order's numbers, then
the same packing relaxed with the box free (§6.8): its category, shell and the cell's strain."""
import glob
import os
import re
import sys

import h5py


def attributes(path, group):
    with h5py.File(path, "r") as f:
        key = f"files/0/{group}"
        return dict(f[key].attrs) if key in f else {}


def text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


def box_columns(work, name):
    """The category, jamming shell, motion, box strain and seconds with the box free; blank
    without."""
    box = attributes(os.path.join(work, f"box-{name}.h5"), "jamming")
    if not box:
        return " | | | | |"
    if not box["relaxed"]:
        return " | no jammed minimum up to {:.3g} D | | | | {:.0f} |".format(
            box["relaxation_shell_unjammed"], box["relaxation_runtime_s"])
    return " | {} | {:.3g}-{:.3g} | {:.3g} | {:.3g} | {:.0f} |".format(
        text(box["category"]), box["relaxation_shell_unjammed"], box["relaxation_shell_jammed"],
        box["relaxation_displacement_max"], box["relaxation_box_strain"],
        box["relaxation_runtime_s"])


def row(work, name):
    line = relaxed_columns(work, name)
    return line and line + box_columns(work, name)


def relaxed_columns(work, name):
    given = attributes(os.path.join(work, f"given-{name}.h5"), "jamming")
    relaxed = attributes(os.path.join(work, f"relaxed-{name}.h5"), "jamming")
    second = attributes(os.path.join(work, f"relaxed-{name}.h5"), "jamming_collective")
    if not relaxed:
        return None
    stiffness = second.get("smallest_stiffness")
    if not relaxed["relaxed"]:  # no jammed minimum: the categories are of the packing as given
        return "| {} | {} | no jammed minimum up to {:.3g} D ({} of {} unconverged) | | | | | | | | | {:.0f}".format(
            name, text(given.get("category", "skipped")), relaxed["relaxation_shell_unjammed"],
            relaxed["relaxation_unconverged"], relaxed["relaxation_minimisations"],
            relaxed["relaxation_runtime_s"])
    return "| {} | {} | {} | {:.3g}-{:.3g} | {:.3g} | {:.3g} | {} | {} | {} | {} | {:.1e} | {:.0f}".format(
        name, text(given.get("category", "skipped")), text(relaxed["category"]),
        relaxed["relaxation_shell_unjammed"], relaxed["relaxation_shell_jammed"],
        relaxed["relaxation_displacement_max"], relaxed.get("relaxation_rotation_max", 0.0),
        relaxed["contacts"], text(second.get("second_order", "-")),
        second.get("floppy_modes", "-"), "-" if stiffness is None else f"{stiffness:.3g}",
        relaxed["relaxation_balance"], relaxed["relaxation_runtime_s"])


def main(work):
    print("| packing | as given | relaxed | jamming shell (D) | moved (D) | turned (rad) | "
          "contacts | second order | floppy modes | stiffness | balance | s | box free | "
          "its shell (D) | moved (D) | box strain | s |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    names = sorted(re.sub(r"^relaxed-|\.h5$", "", os.path.basename(p))
                   for p in glob.glob(os.path.join(work, "relaxed-*.h5")))
    names.sort(key=lambda n: (float(n.split("-")[0][1:]), n))
    for name in names:
        line = row(work, name)
        if line:
            print(line)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "/tmp/sbpack-jamming-relax")
