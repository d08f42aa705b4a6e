#pragma once
// The results schema of sbanalyze, declared once (docs/architecture.md, docs/results-schema.md):
// every group, attribute and dataset of the results file, with its type, units and description.
// The HDF5 writer, the JSON summary, the ensemble reducer and the generated docs/results-schema.md
// all read this table; values are filled by name into a Record (schema/record.hpp), which refuses
// a name the table does not declare.

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace sbpack::schema {

inline constexpr std::string_view kFormat = "sbpack.results";
inline constexpr std::string_view kSummaryFormat = "sbpack.summary";
/// 3: the transport times reduced by w^2 / D_diff named as the other reduced fields
/// (renamedFields).
inline constexpr std::int64_t kFormatVersion = 4;

enum class Kind { Attribute, Dataset };
enum class Type { Float, Int, String };

/// How the ensemble of a group reduces a field (docs/results-schema.md, "Ensembles").
enum class Reduce {
    None,    ///< not in the ensemble
    MeanStd, ///< scalar: NAME (mean over files) and NAME_std (sample standard deviation)
    Curve,   ///< shell-averaged curve (with the group's Q and count): mean and std on a Q w grid
    /// dataset on a grid common to every file (e.g. times): NAME and NAME_std element-wise
    Pointwise,
    /// the grid of the Pointwise datasets, the same in every file: copied
    Same,
    /// an ensemble's own value, computed from its statistics by the analysis's EnsembleFinish
    /// (pipeline/analysis_registry.hpp); never set per file
    Pooled,
    /// dataset, a right-continuous step function of the dataset `over` (F against delta_w):
    /// mean and std over the files on a common grid `over` of kStepsGrid + 1 points from 0 to
    /// the largest `over` of the files
    Steps,
};

/// Intervals of the common grid of Reduce::Steps.
inline constexpr int kStepsGrid = 200;

struct Field {
    std::string_view name;
    Kind kind;
    Type type;
    /// "1" dimensionless, "length" (the packing's), "1/length", "length^2", "length^3", "time"
    /// (length^2 / diffusion_coefficient), "length^2/time", "D" (the major axis 2 semi_axis),
    /// "s" (wall clock), "bytes", "w^3" and "w^2/D_diff" (in units of the mean width w and the
    /// diffusion coefficient D_diff); "" for strings.
    std::string_view units;
    std::string_view description;
    Reduce reduce = Reduce::None;
    bool optional = false;      ///< written only in some cases (said in the description)
    std::string_view over = {}; ///< Reduce::Steps: the dataset it is a function of
    /// A dataset of rows of `width` values (3: n x 3, one row per particle, as OVITO and h5py
    /// read vectors), held flat in a Record; 0: one-dimensional.
    int width = 0;
    /// Reduce::Pooled: absent from an ensemble whose finisher could not compute it (variance's
    /// tail fit in a small box); false: every ensemble with the group has it.
    bool pooledOptional = false;
};

/// "n" for a one-dimensional dataset, "n x 3" for rows of width 3; "" for an attribute.
std::string shapeName(const Field& field);

/// Short names for the rows of a field table (here, and schema/field_table.hpp's).
namespace columns {
inline constexpr Kind A = Kind::Attribute;
inline constexpr Kind D = Kind::Dataset;
inline constexpr Type F = Type::Float;
inline constexpr Type I = Type::Int;
inline constexpr Type S = Type::String;
inline constexpr Reduce Mean = Reduce::MeanStd;
inline constexpr Reduce Curve = Reduce::Curve;
inline constexpr Reduce No = Reduce::None;
inline constexpr Reduce Pointwise = Reduce::Pointwise;
inline constexpr Reduce Same = Reduce::Same;
inline constexpr Reduce Pooled = Reduce::Pooled;
inline constexpr Reduce Steps = Reduce::Steps;
} // namespace columns

/// A field that files of an earlier format_version name otherwise (docs/results-schema.md,
/// "Names"); sbpack.read_results reads such files under today's names.
struct RenamedField {
    std::string_view group;  ///< the analysis group, under files/<i>/ and ensembles/<k>/
    std::string_view before; ///< the name before `since` (its ensemble NAME_std likewise)
    std::string_view now;    ///< the name from `since` on
    std::int64_t since;      ///< the format_version that renamed it
};

/// Every renamed field, oldest first.
std::span<const RenamedField> renamedFields();

struct Group {
    std::string_view name; ///< the group's name under files/<i>/ and ensembles/<k>/; "" for those
    std::string_view path; ///< where it is in the file, e.g. "files/<i>/contacts"
    std::string_view title;
    std::span<const Field> fields;
};

/// The root of the results file: the run.
const Group& runGroup();
/// files/<i>: one input's attributes (its analyses are subgroups).
const Group& fileGroup();
/// ensembles/<k>: the ensemble's own attributes and the statistics of fileGroup()'s fields.
const Group& ensembleRootGroup();
/// ensembles/<k>/<name>: the statistics of the analysis group `source` (files/<i>/<name>; the
/// analyses' groups are declared beside their results, schema/field_table.hpp), derived from its
/// fields' Reduce.
const Group& ensembleGroup(const Group& source);

/// The field called `name` in `group`; nullptr if there is none.
const Field* findField(const Group& group, std::string_view name);

/// The factor that turns a value in `units` computed on the packing in units of `lengthUnit`
/// (the analyses compute in units of D, pipeline/file_analysis.hpp) into the packing's own
/// units: lengthUnit^k for "length^k", 1 / lengthUnit for "1/length", lengthUnit^2 for "time"
/// (length^2 / diffusion_coefficient, which is given in the packing's units), 1 for every
/// dimensionless or reduced unit ("1", "D", "w^3", "w^2/D_diff", "s", ...). std::logic_error for a
/// unit that names "length" or "time" in another way (a new unit must be declared here).
double unitFactor(std::string_view units, double lengthUnit);

/// Units attributes: a dataset has attribute "units"; a numeric attribute NAME has NAME_units.
inline constexpr std::string_view kDatasetUnits = "units";
std::string unitsAttributeName(std::string_view attribute);

/// docs/results-schema.md (`sbanalyze schema --markdown`): the run, the file, the analyses'
/// groups `analyses` (pipeline's resultGroups()) and their ensembles.
std::string schemaMarkdown(std::span<const Group* const> analyses);
/// The same table as JSON (`sbanalyze schema --json`), for readers in other languages.
std::string schemaJson(std::span<const Group* const> analyses);

} // namespace sbpack::schema
