#!/usr/bin/env bash
# Prints docs/cli.md, the command-line manual, to standard output: the hand-written head below,
# then the --help of sbgen, of sbanalyze and of sbanalyze's subcommands info, convert and schema,
# each under a "## `command`" heading in a text block.
#   scripts/make_cli_doc.sh build/generator/sbgen build/analysis/sbanalyze > docs/cli.md
# tests/cli_doc_current.sh checks that docs/cli.md is what this prints. One change is made to the
# programs' words: sbanalyze's --threads default names the thread count of the machine it runs on,
# which is left out here, so that every machine generates the same file.
set -euo pipefail

if [[ $# -ne 2 ]]; then
    echo "usage: make_cli_doc.sh SBGEN SBANALYZE" >&2
    exit 2
fi
sbgen=$1
sbanalyze=$2
for program in "$sbgen" "$sbanalyze"; do
    if [[ ! -x "$program" || -d "$program" ]]; then
        echo "make_cli_doc.sh: '$program' is not an executable program" >&2
        exit 2
    fi
done
export LC_ALL=C

cat <<'HEAD'
# sbgen and sbanalyze on the command line

`sbgen` generates one maximally random jammed packing of superballs (serial, event-driven).
`sbanalyze` analyses stored packings, thread-parallel, into one HDF5 results file, and has the
subcommands `info` (validate each packing and report it), `convert` (formats) and `schema` (the
results file's names and units). Their `--help` texts close this file, as the programs print
them (but for the machine's thread count in the default of `--threads`).

- `sbgen` exits with 0 when the packing is jammed; 1 on bad input or an error; 3 when the packing
  was written but is not jammed (the jam check failed or the cost limit stopped the run; the
  reason is in the file's provenance and on stderr); 128 + signal when SIGINT or SIGTERM wrote a
  checkpoint.
- `sbanalyze` exits with 1 on any error and with 128 + signal (130, 143) when SIGINT or SIGTERM
  stopped it, within a second, or within the FFT planning budget (`--fft-planning-budget`,
  default 2 s) when the signal lands while FFTW measures a plan, which it cannot interrupt
  (`bash bench/sigterm_sweep.sh`); either way it writes no output
  and earlier files at its output paths stay. `info` reports every file it can read and exits
  with 1 when one of them is bad.
- The results file's groups, names and units: `docs/results-schema.md` (`sbanalyze schema`).
  What the programs promise about inputs, outputs and exit codes, with the test behind each
  promise: `docs/reliability.md`. The protocol and its conventions: `docs/design.md` §3.
  `sbanalyze --version` also lists the versions of HDF5, FFTW, oneTBB, OpenMP and OpenVDB.

This file is generated; edit its head in `scripts/make_cli_doc.sh` and run
`scripts/make_cli_doc.sh build/generator/sbgen build/analysis/sbanalyze > docs/cli.md`
(`tests/cli_doc_current.sh` checks it).

## What `--help` does not say

### sbgen

- **Progress**: a line on stderr every 2 s gives the phase, `phi`, `P`, collisions and
  collisions per second, wall time, and after a plateau the growth rate's raise (`growth x2 at
  a plateau`, docs/design.md §3, "Plateaus"); `--quiet` silences it.
- **Warnings before a run, once each**: a protocol whose expected cost exceeds a CPU hour (the
  estimate is printed: collisions per particle from the rates, collisions per CPU second
  measured at `p`, and when the cost limit would stop it; docs/design.md §3), a fast rate
  outside the paper's range (0.005, 0.05), `p > 10`, near-cubes (`p >= 3`) in a box under 8
  diameters across, where a column of them can span the box (`sbgen --p 3 --n 64 ...` says so;
  `N >= 1000` avoids it), and, at other `p`, `N < 250`, where a third to two thirds of the seeds
  jam partly ordered (bench/RESULTS.md, "Small boxes order"). Near-octahedra (`p` just above
  0.5) run at a few hundred collisions a second, and their expected cost says so. The defaults
  at the paper's `p` and `N = 1000` print none.
- **Output**: the packing (format below, with `velocities`, and `angular_velocities` for
  superballs) and, in `provenance`, every parameter, the seed, the version, the final reduced
  pressure, collisions (and `expected_collisions`, docs/design.md §3), the growth rate's raise
  at plateaus (`stall_speed`, only where there was one), events, list rebuilds,
  stale events and rechecks, the superball predictor's work (`predictor_*`: calls, sphere, bound
  and plane rejections, exact and robust evaluations, warm Newton steps on the normal, plane and
  chord steps, Newton brackets, uncertified roots, refinement steps, pair-solver fallbacks,
  rechecks, limit hits, start overlaps), the wall and CPU time, and the final contact analysis of
  `common/` (`z_mean`, `rattler_fraction`, `contact_tolerance`, `worst_gap_over_d`,
  `overlapping_pairs`; contacts at `100 / P` D clamped to `[1e-10, 1e-2]` D, so a run stopped
  below `P = 1e12` reports the `Z` of its load-bearing gaps, not `Z = 0`), plus the exact engine
  state (`resume_state`, docs/design.md §4).
- **Determinism**: the same seed and options give a bit-identical packing (every dataset and
  provenance entry but the timings, `wall_time_s` and `cpu_time_s`). Random numbers use only `std::mt19937_64` and explicit
  transforms, so they do not depend on the C++ library.
- **Checkpoints**: `--checkpoint FILE` writes the synchronised state every
  `--checkpoint-interval` seconds (atomically), and `--resume FILE` continues from it bit for bit.
  A finished output can be resumed too, e.g. with `--pressure-final 1e14` to continue from 1e12,
  or one stopped at its cost limit with a larger `--cost-limit`. A file without sbgen state is
  refused, and so is an `--out` that is the `--resume` file; `--checkpoint` may name it (each
  checkpoint replaces it atomically with a later state of the same run).
- **Bad input** (`p` outside `(0.5, 1000]` or NaN, `N < 2`, `phi-init` outside [0.001, 0.5),
  non-positive or NaN rates or pressures, `pressure-final <= pressure-switch`, a negative
  `cost-limit`, an unwritable output, a resume file that is not a checkpoint, protocol options
  other than `--pressure-final` and `--cost-limit` given with `--resume`) is one line naming the
  option or file, before any work.

### sbanalyze

- **`info`** reads and validates every file named; a bad file (missing, not HDF5, truncated,
  wrong format or version, missing dataset, shape not matching `n_particles`, NaN/inf
  coordinates, quaternion far from unit norm, `p < 0.5` or NaN, `box_length <= 0`,
  `semi_axis <= 0`) gets one line naming the file and the problem. Overlapping particles are a
  warning naming the worst pair and its depth. A file that keeps sbgen's provenance also gets
  its run (`made by`: collisions, CPU seconds, and the growth rate's raise where its slow phase
  was raised at a plateau, docs/design.md §3, "Plateaus").
- **The analyses** (`--compute`; each brings what it needs and nothing else runs):

  | name | what | paper |
  |---|---|---|
  | `contacts` | contact network: `Z` over non-rattlers, rattler fraction, contacts per particle | Secs. III A, IV C |
  | `sq` | `S(Q) = \|sum_j exp(-i Q.r_j)\|^2 / N` of the centroids, `Q = 2 pi n / L != 0`, by direct summation in double precision (separable phase tables, half space `S(Q) = S(-Q)`) | Eq. 4 |
  | `chi` | `chi_V(Q) = \|F(Q)\|^2 [prod_i a sinc(Q_i a / 2)]^2 / V`, `F` the FFT of the voxel indicator (FFTW r2c, threaded, wisdom kept), `a = L / M`; for spheres also exactly, `\|sum_j exp(-i Q.r_j)\|^2 m(Q)^2 / V` with `m(Q) = 4 pi (sin QR - QR cos QR) / Q^3`, and the voxel path's error against it | Eq. 12 |
  | `voxels` | `M^3` voxels of the box, voxel `(i, j, k)` centred at `((i + 1/2) a, ...)`, solid when its centre is inside a particle or a periodic image; `phi_voxel` beside `phi` | Sec. III B |
  | `pores` | by `--pores`: `refined` (default; at `--pore-voxels` 200), each void voxel centre's certified distance to the nearest particle surface (feature transform, then the exact point-to-superball distance); `voxel` (the paper's; at 500 unless `--pore-voxels` says), on the `--pore-voxels` grid the exact periodic Euclidean distance transform of the void (distance from each void voxel centre to the nearest solid voxel centre, minimum image; Felzenszwalb–Huttenlocher, parallel over lines); `exact`, K random points of the void without voxels; then `F(delta)`, `P(delta)`, `<delta>`, `<delta^2>`, the largest pore (refined, exact: a local maximum by Nelder-Mead) and the saturation check `max delta < w / 2`, also divided by `w` | Eqs. 13–15 |
  | `transport` | from the pore-size moments, diffusion-controlled limit: formation factor from the `zeta_2` interpolation of Sec. V A, `k ~ <delta^2> / F`, `tau <= <delta>^2 / D`, `T1 <= <delta^2> / D_diff`, each also over `w^2` | Eqs. 16–20 |
  | `hyper` | the excess spreadability `E(t)` as the exact lattice sum over the box's wave vectors, its local exponent, `alpha` from the long-time decay with a bootstrap error, the fit `chi_V = a0 + a1 Q^alpha` at that `alpha` (and the free fit), `H = a0 / chi_V(Q_peak)`, the Debye medium on the same time axis; `chi_V` exact (no voxels) at `Q w <= --chi-exact-qmax` (docs/hyperuniformity.md) | Eqs. FT_spread, PLF, fit, HX, deb |

- **Shells**: curves are averaged over shells of width `2 pi / L`: shell `s` holds the `n` with
  `round(|n|) = s`, so shells `1..s_max` use exactly the `n` with `|n| < s_max + 1/2`; `s_max` is
  the last shell with `Q w <= qmax` (`--qmax`, `w` the mean width) and, for `chi`, also
  `|n| < M / 2` (no aliasing). Each shell has its mean `Q`, mean value and number of wave vectors.
- **Grids**: the pore grid takes 5 bytes a voxel, 625 MB at 500^3. A grid must put at least 4
  voxels across a particle's narrowest width (`2 r_in`), else the run is refused with the
  smallest acceptable `M`.
- **`--threads`** caps TBB and FFTW (whose threads are OpenMP's) alike; `0` or more than 4
  times the hardware threads is refused.
- **`--vdb DIR`**: the density volume is in the packing's length units, with metadata `p`,
  `phi_voxel`, `phi_exact`; Blender (Volume object), Houdini and ParaView open it. The pore-size
  grid is active on the void voxels only. Every `.vdb` also carries `box_length`, `voxels`
  (int64), `units` and `length_unit` (one writer, `analysis/voxels/vdb_image`): the grids are in
  the unit the analyses compute in, the power of two `u` with `1 <= D / u < 2` (`length_unit`,
  1 for `1 <= D < 2`), so that a packing in metres stays within OpenVDB's scales; a length of the
  grid times `length_unit` is the packing's.
- **FFT planning**: planning predicted to take longer than `--fft-planning-budget` (a `n log n`
  model calibrated on the reference machine, `bench/RESULTS.md`, "FFT planning") falls back on
  FFTW's `estimate` plan, and measuring is cut off near the budget (FFTW's time limit); run once
  with `none` to store measured plans. The "FFT plan" progress line gives the planning time and
  where the plan came from (wisdom, measured, or estimate over the budget), as do `fft_plan_s`
  and `fft_plan_source` in the results. A wisdom file that cannot be read or written is only a
  warning.
- **Progress**: one line per stage on standard error (stage, detail, wall time); Ctrl-C or
  SIGTERM stops the running stage at its next chunk (0.1-0.5 s measured, up to 1.2 s in a
  1000^3 voxelisation).
- **Several inputs** are processed one after the other (`sbanalyze run*/packing.h5 --out
  all.h5`), so stored packings can be reprocessed in one call or from a script; the same file
  twice is refused, and an error names the file it came from. The results
  file, the JSON summary and the `.vdb` files are written to temporaries and renamed together at
  the end.
- **`hyper` skipped**: a box too small for a long-time window, a given `--alpha-window` that ends
  past the box's cutoff time, or a fit window whose wave vectors lie at one `|Q|`, skips `hyper`
  for that file; the warning names the option to change (`--alpha-window`, `--fit-qmax`,
  `--voxels`).
- **Under `mpirun`** (builds with `-DSBPACK_WITH_MPI=ON`; docs/scale-out.md): `--distribute
  grids` takes `--pores voxel` (its default there) and refuses `--pores refined|exact`. Under Slurm (scripts/slurm/, docs/scale-out.md),
  preemption, `scontrol requeue` and the time-limit warning resume bit for bit (tests
  `slurm_preemption` and, against a real Slurm, `slurm_real`).

### Files

- **Packing file** (HDF5, `format = "sbpack.packing"`, `format_version = 1`): its attributes and
  datasets are in docs/design.md §4; its `phi` must equal `N v1 / L^3`, which readers check.
  Readable with h5py: `h5py.File(name)["positions"][:]`, `dict(f.attrs)`.
- **Plain text** (`.txt`, read by `info`, the analysis, `convert` and `sbpack.Packing.read`): a
  header `# sbpack text packing v1`, the shape as the packing file names it (`# p P`; another
  family would add `# shape NAME` and its own parameters), `# semi_axis R`,
  `# box_length L`, `# n_particles N`, optionally `# reduced_pressure P` and `# seed S` (the
  pressure sets the jam check's tolerance, so Z and phi_R), then one particle per line
  `x y z qw qx qy qz`, and for a mixture each particle's semi-axis as an eighth number on every
  line (`semi_axis` their largest; docs/mixtures.md). `convert` to it (or to XYZ) names what the target leaves out
  (velocities, provenance, a checkpoint's resume state).
- **The shape in the exchange formats** (XYZ, GSD, LAMMPS; `ShapeSpec::superquadric` in
  `common/geometry/particle_shape.hpp`): each writes the shape as a superquadric, OVITO's
  `(|x/a|^(2/phi) + |y/b|^(2/phi))^(phi/theta) + |z/c|^(2/theta) <= 1` with the semi-axes
  `(a, b, c)` at each particle's size and the roundness `(phi, theta)` (LAMMPS's blockiness
  `n = 2 / roundness`); the superball (paper Eq. 1) is `a = b = c`, `phi = theta = 1/p`,
  `n = 2p`, test `ShapeSpec.ItsSuperquadricIsPaperEq1AndReadsBack`. Reading inverts it
  (`ShapeSpec::fromSuperquadric`): every particle must have the same proportions `a:b:c` and
  roundness (its size may differ: a mixture), and a superquadric that is no family sbpack
  knows (an ellipsoid's unequal axes, two roundnesses) is refused naming the file.
- **Extended XYZ** (`.xyz`, written by `convert`; read by `info`, the analysis and `convert`:
  one frame, sbpack's export or OVITO's, a cubic `Lattice`, the shape from the keys `p=` (the
  shape's parameters by name, with `shape=` for a family other than the superball) and
  `semi_axis=` or the columns below, which must then agree with the keys; it carries no
  reduced pressure, so the contacts take
  `--tolerance`): OVITO reads positions, `orientation` (its
  quaternion order `x y z w`) and `aspherical_shape` directly (a mixture's: each particle's
  own semi-axis, `semi_axis=` their largest; docs/mixtures.md); map the two
  `superquadric_roundness` columns (`phi theta`, both `1/p`) to OVITO's "Superquadric Roundness" in the
  import dialog to see superball shapes.
- **GSD** (`.gsd`, HOOMD-blue's format, read and written by `convert`, `info`, the analysis and
  `sbpack.Packing.read`/`write`; `common/io/gsd_io.hpp`, by the reference library vendored in
  `common/third_party/gsd`, BSD-2-Clause, gsd 5.0.1): one frame of HOOMD schema 1.4, which
  HOOMD 4, gsd.hoomd 4 and 5, freud and OVITO read: the cubic `configuration/box`, one type
  named by the shape's family (`superball`) whose `particles/type_shapes` is a `ConvexPolyhedron` of 266 points on the
  superball's surface (OVITO draws the particles as superballs, no dialog),
  `particles/position` in `[-L/2, L/2)` and `particles/orientation` `(w, x, y, z)` in single
  precision as the schema has them, and, so that nothing is lost, double-precision copies
  `log/particles/sbpack/position` (in `[0, L)`) and `log/particles/sbpack/orientation` with
  the scalars `log/sbpack/p` (the shape's parameters by name), `semi_axis`, `box_length`, `reduced_pressure` and `seed`: an sbpack
  file round-trips bit for bit. A mixture has a type per distinct size (`superball_0`, ...,
  largest first) and `log/particles/sbpack/semi_axis` (docs/mixtures.md). A file from elsewhere is read from its last frame: the
  single-precision positions (a jammed packing then overlaps by up to the rounding: `info` and
  the contacts say so and advise `--tolerance`), orientations (identity where absent), a cubic
  box without tilt, and the shape from sbpack's scalars or one `Sphere` type_shape (a HOOMD
  hard-sphere frame: `p = 1`, `a` = diameter / 2); anything else is refused naming the file.
  Checked against gsd.hoomd, freud and OVITO by `bench/formats_vs_peers.sh` (bench/RESULTS.md).
- **LAMMPS** (`common/io/lammps_io.hpp`, read and written like GSD, 17 significant digits): a
  dump (`.dump` or `.lammpstrj`, `dump custom` of one frame: `BOX BOUNDS pp pp pp` `0 L` and the
  columns `id type x y z quatw quati quatj quatk shapex shapey shapez
  SuperquadricRoundness.Phi SuperquadricRoundness.Theta`, shapes as LAMMPS's diameters `2a`, the
  roundness `1/p`: OVITO 3.8.5 and later maps the columns by name to Orientation, Aspherical
  Shape and Superquadric Roundness and draws superballs with no dialog) and a data file (`.data`,
  `atom_style ellipsoid`: `Atoms # ellipsoid` lines `id type 1 1 x y z` and `Ellipsoids` lines
  `id 2a 2b 2c quatw quati quatj quatk`, with the superellipsoid blockiness `2p 2p` appended
  where `p != 1`, which `atom_style ellipsoid superellipsoid` of LAMMPS 30Mar2026 and later
  reads and older versions refuse; spheres keep the 8 columns every version reads). Reading
  takes a dump's first frame from any origin, in `x y z`, `xu yu zu` or scaled `xs ys zs`, the
  particles in the order of their ids (`p = 1` without the roundness columns), and a data file's
  Atoms and Ellipsoids joined by id (`p` = blockiness / 2, or 1); neither carries the reduced
  pressure, so the contacts take `--tolerance`. A mixture's atoms carry their own diameters
  (docs/mixtures.md). A non-cubic or tilted box, missing shape columns, particles whose
  proportions or roundness differ, a shape that is no superball, a repeated id or a short frame
  is refused naming the file and line.
- **Results file** (HDF5, `format = "sbpack.results"`, `format_version = 4`): the root holds the
  run, `files/<i>` one input with one subgroup per analysis, `ensembles/<k>` the inputs of equal
  `p` and `N`; every name and unit is in docs/results-schema.md. Reading it with h5py
  (`tests/read_results.py` does this):

  ```python
  import h5py
  with h5py.File("results.h5") as f:
      one = f["files/0"]
      w = one.attrs["mean_width"]
      Qw, S = one["structure_factor/Q_w"][:], one["structure_factor/S"][:]
      chi_w3 = one["spectral_density/chi"][:] / w**3      # chi_V / w^3 against Q w, as the paper
      print(one["spectral_density/chi"].attrs["units"])   # length^3
      print(dict(f["ensembles/0/contacts"].attrs))        # z_mean, z_mean_std, ...
  ```
HEAD

# One section: "## `TITLE`" and the output of the command in a text block.
section() {
    local title=$1
    shift
    local text
    if ! text=$("$@"); then
        echo "make_cli_doc.sh: '$title' failed" >&2
        exit 1
    fi
    text=$(sed -E "s/\(default: the hardware's, [0-9]+\)/(default: the hardware's)/" <<<"$text")
    # shellcheck disable=SC2016 # the backticks are Markdown, not a command substitution
    printf '\n## `%s`\n\n```text\n%s\n```\n' "$title" "$text"
}

section "sbgen --help" "$sbgen" --help
section "sbanalyze --help" "$sbanalyze" --help
section "sbanalyze info --help" "$sbanalyze" info --help
section "sbanalyze convert --help" "$sbanalyze" convert --help
section "sbanalyze schema --help" "$sbanalyze" schema --help
