#pragma once
// The results group of transport, declared once (schema/field_table.hpp, docs/results-schema.md).

#include "schema/field_table.hpp"
#include "transport/transport.hpp"

namespace sbpack {

namespace transport_fields {
using namespace schema::columns;
using R = TransportResult;
inline constexpr schema::FieldTable kTable{std::array<schema::Column<R>, 10>{{
    {{"zeta2", A, F, "1",
      "three-point parameter zeta_2 (Sec. V A interpolation); absent, with F and k, where it "
      "leaves (0, 1] (fitted for 0.85 <= p <= 1.5) or the particles are not superballs",
      No, true},
     member<&R::zeta2>},
    {{"formation_factor", A, F, "1", "formation factor F (Eq. 18)", No, true},
     member<&R::formationFactor>},
    {{"permeability", A, F, "length^2", "k ~ <delta^2> / F (Eq. 17)", No, true},
     member<&R::permeability>},
    {{"permeability_w2", A, F, "1", "k / w^2", Mean, true}, member<&R::permeabilityOverWidth2>},
    {{"mean_survival_time", A, F, "time", "bound tau <= <delta>^2 / D_diff (Eq. 19)"},
     member<&R::meanSurvivalTime>},
    {{"mean_survival_time_w2", A, F, "w^2/D_diff", "tau D_diff / w^2", Mean},
     member<&R::meanSurvivalTimeOverWidth2>},
    {{"principal_relaxation_time", A, F, "time", "bound T1 <= <delta^2> / D_diff (Eq. 20)"},
     member<&R::principalRelaxationTime>},
    {{"principal_relaxation_time_w2", A, F, "w^2/D_diff", "T1 D_diff / w^2", Mean},
     member<&R::principalRelaxationTimeOverWidth2>},
    {{"diffusion_coefficient", A, F, "length^2/time", "D_diff"},
     member<&R::parameters, &TransportParameters::diffusionCoefficient>},
    {{"runtime_s", A, F, "s", kRuntime}, member<&R::runtimeSeconds>},
}}};
} // namespace transport_fields

inline constexpr schema::Group kTransportGroup{
    "transport", "files/<i>/transport",
    "transport estimates, diffusion-controlled limit (transport)",
    transport_fields::kTable.fields()};

} // namespace sbpack
