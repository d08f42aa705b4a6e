#pragma once
// Counters of a shape's collision predictor (the superball one's tiers, superball_shape.hpp),
// written into sbgen's provenance under the names below.

#include <utility>

namespace sbpack {

/// What a shape's predictor did, summed over calls and handed to the protocol every window
/// (Shape::takeStats). The exact sphere predictor counts nothing.
struct PredictorStats {
    long calls = 0;
    long sphereRejections = 0;  ///< circumscribed spheres do not meet before the horizon
    long boundRejections = 0;   ///< the remembered bound on its gap shows it, unevaluated
    long witnessRejections = 0; ///< the witness record's material points separate them
    long planeRejections = 0;   ///< the cached normal's plane separates up to the horizon
    long evaluations = 0;       ///< exact signed distances (advancement, Newton, refinement)
    long localSearches = 0;     ///< of those, near contact: Newton's normal polished locally
    long robustEvaluations = 0; ///< of those, by the robust pair solver (no warm Newton)
    long newtonSteps = 0;       ///< warm Newton iterations on the normal, over all evaluations
    long lowerBounds = 0;       ///< of those, far from contact: unconverged Newton's bound
    long planeSteps = 0;        ///< advancement steps on a plane gap (two support functions)
    long chordSteps = 0;        ///< of those, steps certified by the plane's chord bound
    long newtonBrackets = 0;    ///< Newton steps in time that bracketed the contact
    long uncertifiedRoots = 0;  ///< of those, roots not certified first: advancement went on
    long refinementSteps = 0;   ///< evaluations in the bracketed refinement
    long distanceFallbacks = 0; ///< pair-solver cutting-plane finishes
    long rechecks = 0;          ///< step limit reached: a safe recheck time instead of a contact
    long limitHits = 0;         ///< refinement limit reached: the bracket's safe end returned
    long startOverlaps = 0;     ///< s(0) < -contactGap D (the pair just resolved, by rounding)
    long predictedContacts = 0; ///< collisions whose contact normal was the prediction's

    /// Each counter with its provenance name (the names of earlier files kept).
    static constexpr std::pair<const char*, long PredictorStats::*> kCounters[] = {
        {"predictor_calls", &PredictorStats::calls},
        {"predictor_sphere_rejections", &PredictorStats::sphereRejections},
        {"predictor_bound_rejections", &PredictorStats::boundRejections},
        {"predictor_witness_rejections", &PredictorStats::witnessRejections},
        {"predictor_plane_rejections", &PredictorStats::planeRejections},
        {"predictor_evaluations", &PredictorStats::evaluations},
        {"predictor_local_searches", &PredictorStats::localSearches},
        {"predictor_robust_evaluations", &PredictorStats::robustEvaluations},
        {"predictor_newton_steps", &PredictorStats::newtonSteps},
        {"predictor_lower_bounds", &PredictorStats::lowerBounds},
        {"predictor_plane_steps", &PredictorStats::planeSteps},
        {"predictor_chord_steps", &PredictorStats::chordSteps},
        {"predictor_newton_brackets", &PredictorStats::newtonBrackets},
        {"predictor_uncertified_roots", &PredictorStats::uncertifiedRoots},
        {"predictor_refinement_steps", &PredictorStats::refinementSteps},
        {"predictor_fallbacks", &PredictorStats::distanceFallbacks},
        {"predictor_rechecks", &PredictorStats::rechecks},
        {"predictor_limit_hits", &PredictorStats::limitHits},
        {"predictor_start_overlaps", &PredictorStats::startOverlaps},
        {"predictor_predicted_contacts", &PredictorStats::predictedContacts},
    };
    PredictorStats& operator+=(const PredictorStats& other) {
        for (const auto& [name, counter] : kCounters)
            this->*counter += other.*counter;
        return *this;
    }
};

} // namespace sbpack
