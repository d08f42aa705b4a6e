#pragma once
// The results groups of jamming, declared once (schema/field_table.hpp, docs/results-schema.md):
// the category reached (jamming) and one group per category tested (jamming_local,
// jamming_collective, jamming_strict) with its first-order verdict and the unjamming motions
// per particle (docs/jamming.md §3).

#include "jamming/jamming_categories.hpp"
#include "schema/field_table.hpp"

#include <array>
#include <string>
#include <vector>

namespace sbpack {

namespace jamming_fields {
using namespace schema::columns;
using P = PackingJamming;
using R = JammingResult;
using M = UnjammingMotion;

/// Per-particle vectors as rows of three (schema::Field::width).
inline std::vector<double> rowsOf(const std::vector<Vector3d>& vectors) {
    std::vector<double> flat;
    flat.reserve(3 * vectors.size());
    for (const Vector3d& v : vectors)
        flat.insert(flat.end(), {v.x(), v.y(), v.z()});
    return flat;
}

/// A number of the relaxation (--jamming-relax), absent without it.
template <class T> Optional relaxationValue(const P& p, T (*value)(const JammingPoint&)) {
    if (!p.relaxation) return std::nullopt;
    return Value(value(*p.relaxation));
}

inline constexpr schema::FieldTable kTable{std::array<schema::Column<P>, 26>{{
    {{"category", A, S, "",
      "the highest category tested that is jammed, at first order or (collective) at second: "
      "strict, collective, "
      "local, or none (a jammed category implies those below it; docs/jamming.md §1)"},
     +[](const P& p, const Scales&) -> Optional { return Value(std::string(p.reachedName())); }},
    {{"verdict", A, S, "",
      "one line: the category reached and the next one's verdict (not jammed, or undecided "
      "pending the second-order test)"},
     +[](const P& p, const Scales&) -> Optional { return Value(p.verdict()); }},
    {{"undecided", A, S, "",
      "the categories whose first-order verdict is undecided, comma-separated (\"\" for none): "
      "they await the second-order test (docs/jamming.md §3)"},
     +[](const P& p, const Scales&) -> Optional { return Value(p.undecided()); }},
    {{"categories", A, S, "", "the categories tested (--jamming-categories)"},
     +[](const P& p, const Scales&) -> Optional {
         std::vector<JammingCategory> tested;
         for (const JammingResult& t : p.tests)
             tested.push_back(t.category);
         return Value(jammingCategoryNames(tested));
     }},
    {{"tolerance", A, F, "D",
      "the contact network's gap tolerance: the jam check's, max(1e-10, 100 / P) D, unless "
      "--jamming-tolerance; --tolerance where the file has no reduced pressure"},
     member<&P::tolerance>},
    {{"tolerance_from", A, S, "", "where the tolerance comes from"}, member<&P::toleranceFrom>},
    {{"backbone", A, I, "1", "particles that are not rattlers (--rattler-threshold)", Mean},
     member<&P::backbone>},
    {{"contacts", A, I, "1", "contacts among the backbone", Mean}, member<&P::contacts>},
    {{"runtime_s", A, F, "s", kRuntime, Mean}, member<&P::seconds>},
    {{"relaxed", A, I, "1",
      "1 where the categories are those of the nearest jammed packing (--jamming-relax and "
      "a jamming shell found: docs/jamming.md §6.7), 0 where of the packing as given"},
     +[](const P& p, const Scales&) -> Optional {
         return Value(std::int64_t{p.relaxation && p.relaxation->found ? 1 : 0});
     }},
    {{"relaxation_shell_unjammed", A, F, "D",
      "--jamming-relax: the largest shell found unjammed (its overlaps relax away; 0 where "
      "jammed at the smallest, 1e-10 D): the particles fit, rearranged, inflated by it",
      Mean, true},
     +[](const P& p, const Scales&) -> Optional {
         return relaxationValue<double>(p, [](const JammingPoint& j) { return j.unjammedShell; });
     }},
    {{"relaxation_shell_jammed", A, F, "D",
      "--jamming-relax: the smallest shell found jammed (a minimum with E > 0); the jamming "
      "shell lies between the two, the relaxed packing is the minimum at this one; 0 where none "
      "up to 1e-2 D is jammed",
      Mean, true},
     +[](const P& p, const Scales&) -> Optional {
         return relaxationValue<double>(p, [](const JammingPoint& j) { return j.jammedShell; });
     }},
    {{"relaxation_displacement_max", A, F, "D",
      "--jamming-relax: the largest displacement from the given packing to the relaxed one", Mean,
      true},
     +[](const P& p, const Scales&) -> Optional {
         return relaxationValue<double>(
             p, [](const JammingPoint& j) { return j.largestDisplacement; });
     }},
    {{"relaxation_rotation_max", A, F, "rad",
      "--jamming-relax: the largest rotation from the given packing to the relaxed one", Mean,
      true},
     +[](const P& p, const Scales&) -> Optional {
         return relaxationValue<double>(p, [](const JammingPoint& j) { return j.largestRotation; });
     }},
    {{"relaxation_box_strain", A, F, "1",
      "--jamming-relax box: the largest entry of F - I, the relaxed cell's edges over L less "
      "the cube's (det F = 1; 0 where the box keeps its shape: docs/jamming.md §6.8)",
      Mean, true},
     +[](const P& p, const Scales&) -> Optional {
         return relaxationValue<double>(p, [](const JammingPoint& j) { return j.boxStrain; });
     }},
    {{"relaxation_path_overlap", A, F, "D",
      "--jamming-relax: the deepest overlap of the particles themselves on the way from the "
      "given packing to the relaxed one (0: a motion of hard particles)",
      Mean, true},
     +[](const P& p, const Scales&) -> Optional {
         return relaxationValue<double>(p, [](const JammingPoint& j) { return j.deepestOverlap; });
     }},
    {{"relaxation_balance", A, F, "1",
      "--jamming-relax: |grad E|_inf over the mean force at the relaxed minimum: how exactly "
      "its forces balance",
      Mean, true},
     +[](const P& p, const Scales&) -> Optional {
         return relaxationValue<double>(
             p, [](const JammingPoint& j) { return j.relaxed.balanceResidual; });
     }},
    {{"relaxation_minimisations", A, I, "1",
      "--jamming-relax: minimisations of the bracketing (unconverged ones in "
      "relaxation_unconverged, counted unjammed)",
      Mean, true},
     +[](const P& p, const Scales&) -> Optional {
         return relaxationValue<std::int64_t>(
             p, [](const JammingPoint& j) { return std::int64_t{j.minimisations}; });
     }},
    {{"relaxation_unconverged", A, I, "1",
      "--jamming-relax: minimisations that ended neither jammed nor unjammed (the iteration "
      "limit, or a stall above rounding), counted unjammed",
      Mean, true},
     +[](const P& p, const Scales&) -> Optional {
         return relaxationValue<std::int64_t>(
             p, [](const JammingPoint& j) { return std::int64_t{j.unconverged}; });
     }},
    {{"relaxation_runtime_s", A, F, "s", "--jamming-relax: wall-clock time of the relaxation", Mean,
      true},
     +[](const P& p, const Scales&) -> Optional {
         return relaxationValue<double>(p, [](const JammingPoint& j) { return j.seconds; });
     }},
    {{"relaxation_displacement",
      D,
      F,
      "D",
      "--jamming-relax: each particle's displacement from the given packing to the relaxed one "
      "(box: less the cell's affine part)",
      No,
      true,
      {},
      3},
     +[](const P& p, const Scales&) -> Optional {
         if (!p.relaxation) return std::nullopt;
         return Value(rowsOf(p.relaxation->displacement));
     }},
    {{"n_strict", A, I, "1", "ensembles only: members strictly jammed at first order", Pooled,
      true},
     schema::ensembleOnly<P>},
    {{"n_collective", A, I, "1",
      "ensembles only: members collectively but not strictly jammed (or strict not tested)", Pooled,
      true},
     schema::ensembleOnly<P>},
    {{"n_local", A, I, "1",
      "ensembles only: members locally but not collectively jammed (or collective not tested)",
      Pooled, true},
     schema::ensembleOnly<P>},
    {{"n_none", A, I, "1", "ensembles only: members jammed in no category tested", Pooled, true},
     schema::ensembleOnly<P>},
    {{"n_undecided", A, I, "1",
      "ensembles only: members with a category left undecided (undecided at first order, not "
      "jammed at second)",
      Pooled, true},
     schema::ensembleOnly<P>},
}}};

/// The motion's `Part` (displacement or rotation) as n x 3 rows; absent without the motion (or,
/// for the rotation, for spheres).
template <auto Motion, auto Part> Optional motionRows(const R& r, const Scales&) {
    const auto& motion = r.*Motion;
    if (!motion || ((*motion).*Part).empty()) return std::nullopt;
    return Value(rowsOf((*motion).*Part));
}

/// The motion's strain as 3 x 3 rows; Strict only.
template <auto Motion> Optional strainRows(const R& r, const Scales&) {
    const auto& motion = r.*Motion;
    if (!motion || r.category != JammingCategory::Strict) return std::nullopt;
    std::vector<double> rows;
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
            rows.push_back(motion->strain(a, b));
    return Value(std::move(rows));
}

/// Particles the motion moves by more than the motion tolerance; 0 without it.
template <auto Motion> Optional movingCount(const R& r, const Scales&) {
    const auto& motion = r.*Motion;
    return Value(static_cast<std::int64_t>(motion ? motion->moving.size() : 0));
}

/// The second-order test's result where it ran (collective, first order undecided).
template <class T> Optional secondOrderValue(const R& r, T (*value)(const SecondOrderResult&)) {
    if (!r.secondOrder) return std::nullopt;
    return Value(value(*r.secondOrder));
}

inline constexpr schema::FieldTable kCategoryTable{std::array<schema::Column<R>, 28>{{
    {{"verdict", A, S, "",
      "first-order verdict: jammed (no motion), unjammed (a particle certainly freed; for "
      "spheres any motion) or undecided (p != 1: only motions that curvature may block, for the "
      "second-order test; docs/jamming.md §3)"},
     +[](const R& r, const Scales&) -> Optional {
         return Value(std::string(firstOrderVerdictName(r.verdict)));
     }},
    {{"order", A, I, "1",
      "the order of the test that decided: 1, or 2 where first order was undecided and the "
      "second-order test gave jammed or not jammed (docs/jamming.md §6)"},
     +[](const R& r, const Scales&) -> Optional {
         const bool second =
             r.secondOrder && (r.secondOrder->verdict == SecondOrderVerdict::Jammed ||
                               r.secondOrder->verdict == SecondOrderVerdict::NotJammed);
         return Value(std::int64_t{second ? 2 : 1});
     }},
    {{"second_order", A, S, "",
      "the second-order stress test's verdict where it ran (collective, first order undecided; "
      "--jamming-second-order): jammed, not jammed (with the self-stress tested), no self-stress "
      "(a first-order motion opens every contact), singular curvature; docs/jamming.md §6",
      No, true},
     +[](const R& r, const Scales&) -> Optional {
         return secondOrderValue<std::string>(r, [](const SecondOrderResult& s) {
             return std::string(secondOrderVerdictName(s.verdict));
         });
     }},
    {{"floppy_modes", A, I, "1",
      "second order: first-order flexes beyond the trivial translations, dim ker A^T - 3 "
      "(rank-revealing QR)",
      Mean, true},
     +[](const R& r, const Scales&) -> Optional {
         return secondOrderValue<std::int64_t>(
             r, [](const SecondOrderResult& s) { return std::int64_t{s.floppyModes}; });
     }},
    {{"self_stresses", A, I, "1", "second order: dim ker A, the independent self-stresses", Mean,
      true},
     +[](const R& r, const Scales&) -> Optional {
         return secondOrderValue<std::int64_t>(
             r, [](const SecondOrderResult& s) { return std::int64_t{s.selfStresses}; });
     }},
    {{"smallest_stiffness", A, F, "1",
      "second order: the smallest eigenvalue of the stress matrix on the flexes, in units of the "
      "mean contact force per D (positive: jammed at second order); only with a self-stress",
      Mean, true},
     +[](const R& r, const Scales&) -> Optional {
         if (!r.secondOrder || r.secondOrder->verdict == SecondOrderVerdict::NoSelfStress)
             return std::nullopt;
         return Value(r.secondOrder->smallestStiffness);
     }},
    {{"forces_given", A, I, "1",
      "second order: 1 where the self-stress tested is sbgen's stored contact forces (the "
      "packing's "
      "contact_forces), 0 where the linear program found it",
      No, true},
     +[](const R& r, const Scales&) -> Optional {
         return secondOrderValue<std::int64_t>(
             r, [](const SecondOrderResult& s) { return std::int64_t{s.forcesGiven ? 1 : 0}; });
     }},
    {{"balance_residual", A, F, "1",
      "second order: the largest net force or torque (per D) on a particle under the self-stress "
      "tested (the max norm of A f), in units of its mean force: rounding for the program's, "
      "the imbalance of stored forces",
      Mean, true},
     +[](const R& r, const Scales&) -> Optional {
         return secondOrderValue<double>(
             r, [](const SecondOrderResult& s) { return s.stress.balanceResidual; });
     }},
    {{"second_order_runtime_s", A, F, "s", "second order: wall-clock time", Mean, true},
     +[](const R& r, const Scales&) -> Optional {
         return secondOrderValue<double>(r, [](const SecondOrderResult& s) { return s.seconds; });
     }},
    {{"isostatic_deficit", A, I, "1",
      "degrees of freedom - 3 - contacts (the Maxwell count; above 0 flexes must exist); not "
      "for local",
      Mean, true},
     +[](const R& r, const Scales&) -> Optional {
         if (r.category == JammingCategory::Local) return std::nullopt;
         return Value(std::int64_t{r.isostaticDeficit});
     }},
    {{"largest_opening", A, F, "D",
      "largest first-order opening of a contact by the opening motion, max_c ds_c, at steps "
      "up to --jamming-max-step",
      Mean},
     member<&R::largestOpening>},
    {{"largest_displacement", A, F, "D",
      "the largest displacement of a particle (or of the box's images, eps L) by any solution "
      "of the programs, kept as a motion or not; with --jamming-unjam-distance, how near the "
      "finite-gap test came to it (docs/jamming.md §4.1)",
      Mean},
     member<&R::largestDisplacement>},
    {{"opens_every_contact", A, I, "1",
      "1 where the opening opens every contact: the rigidity matrix has full column rank, no "
      "self-stress exists and, by Gordan's alternative, the network is not jammed (the motions "
      "by one factorisation of A^T A, not the programs; the flexes number isostatic_deficit; "
      "docs/jamming.md §3); not for local",
      Mean, true},
     +[](const R& r, const Scales&) -> Optional {
         if (r.category == JammingCategory::Local) return std::nullopt;
         return Value(std::int64_t{r.opensEveryContact ? 1 : 0});
     }},
    {{"n_freed", A, I, "1", "particles certainly freed (the dataset freed)", Mean},
     +[](const R& r, const Scales&) -> Optional {
         return Value(static_cast<std::int64_t>(r.freed.size()));
     }},
    {{"n_opening_moving", A, I, "1", "particles the opening motion moves (0: none found)", Mean},
     movingCount<&R::opening>},
    {{"n_flex_moving", A, I, "1", "particles the flex moves (0: none found)", Mean},
     movingCount<&R::flex>},
    {{"fixed_particle", A, I, "1",
      "the particle held fixed against the trivial translations; not for local", No, true},
     +[](const R& r, const Scales&) -> Optional {
         if (r.fixedParticle < 0) return std::nullopt;
         return Value(std::int64_t{r.fixedParticle});
     }},
    {{"runtime_s", A, F, "s", "wall-clock time of this category's matrix and programs", Mean},
     member<&R::seconds>},
    {{"freed", D, I, "1", "indices of the particles certainly freed (may be empty)"},
     member<&R::freed>},
    {{"opening_displacement",
      D,
      F,
      "D",
      "the opening motion: each particle's displacement dr (0 for rattlers; strict: eps r "
      "included); only where a contact opens",
      No,
      true,
      {},
      3},
     motionRows<&R::opening, &M::displacement>},
    {{"opening_rotation",
      D,
      F,
      "rad",
      "the opening motion: each particle's small rotation dtheta; only for p != 1 with an opening",
      No,
      true,
      {},
      3},
     motionRows<&R::opening, &M::rotation>},
    {{"opening_strain",
      D,
      F,
      "1",
      "the opening motion's box strain eps (3 x 3); strict only",
      No,
      true,
      {},
      3},
     strainRows<&R::opening>},
    {{"flex_displacement",
      D,
      F,
      "D",
      "the flex (a motion that keeps every contact at first order): each particle's dr; only "
      "where one exists",
      No,
      true,
      {},
      3},
     motionRows<&R::flex, &M::displacement>},
    {{"flex_rotation",
      D,
      F,
      "rad",
      "the flex: each particle's dtheta; only for p != 1 with a flex",
      No,
      true,
      {},
      3},
     motionRows<&R::flex, &M::rotation>},
    {{"flex_strain", D, F, "1", "the flex's box strain eps (3 x 3); strict only", No, true, {}, 3},
     strainRows<&R::flex>},
    {{"n_jammed", A, I, "1", "ensembles only: members jammed in this category", Pooled, true},
     schema::ensembleOnly<R>},
    {{"n_unjammed", A, I, "1", "ensembles only: members unjammed in this category", Pooled, true},
     schema::ensembleOnly<R>},
    {{"n_undecided", A, I, "1", "ensembles only: members undecided in this category", Pooled, true},
     schema::ensembleOnly<R>},
}}};
} // namespace jamming_fields

inline constexpr schema::Group kJammingGroup{
    "jamming", "files/<i>/jamming",
    "the jamming categories (first order; collective at second order where first order is "
    "undecided): the category reached (jamming; docs/jamming.md)",
    jamming_fields::kTable.fields()};
inline constexpr schema::Group kJammingLocalGroup{
    "jamming_local", "files/<i>/jamming_local",
    "local jamming at first order: each particle alone, its neighbours fixed (jamming)",
    jamming_fields::kCategoryTable.fields()};
inline constexpr schema::Group kJammingCollectiveGroup{
    "jamming_collective", "files/<i>/jamming_collective",
    "collective jamming: all particles together, the box fixed; at first order, and at second "
    "where first order is undecided (jamming)",
    jamming_fields::kCategoryTable.fields()};
inline constexpr schema::Group kJammingStrictGroup{
    "jamming_strict", "files/<i>/jamming_strict",
    "strict jamming at first order: with a volume-nonincreasing strain of the box (jamming)",
    jamming_fields::kCategoryTable.fields()};

/// The group of `category`'s test.
inline const schema::Group& jammingCategoryGroup(JammingCategory category) {
    return category == JammingCategory::Local        ? kJammingLocalGroup
           : category == JammingCategory::Collective ? kJammingCollectiveGroup
                                                     : kJammingStrictGroup;
}

} // namespace sbpack
