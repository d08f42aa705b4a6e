#include "schema/results_schema.hpp"

#include "geometry/particle_shape.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <deque>
#include <map>
#include <mutex>
#include <stdexcept>

namespace sbpack::schema {

namespace {

using namespace columns;

constexpr Field kRun[] = {
    {"format", A, S, "", "\"sbpack.results\""},
    {"format_version", A, I, "1",
     "4 (this layout; 2 and 3 differ in the fields renamed, \"Names\")"},
    {"sbanalyze_version", A, S, "", "version of the sbanalyze that wrote the file"},
    {"compute", A, S, "", "the analyses run, comma-separated (--compute with what they need)"},
    {"options", A, S, "",
     "the options of the analyses run, with their values (--qmax 30 --voxels 300 ...): given to "
     "sbanalyze with --compute, they repeat these results"},
    {"threads", A, I, "1", "threads of the run (--threads), per rank"},
    {"device", A, S, "",
     "where the grids were computed (--device): \"cpu\", or \"cuda: \" and the GPU (docs/gpu.md)"},
    {"ranks", A, I, "1", "MPI processes of the run (1 without mpirun; docs/scale-out.md)"},
    {"distribute", A, S, "", "what the ranks shared out (--distribute): files or grids"},
    {"n_files", A, I, "1", "inputs: groups files/0 ... files/<n_files - 1>"},
    {"n_ensembles", A, I, "1", "ensembles (inputs of equal shape and N): ensembles/0 ..."},
    {"runtime_s", A, F, "s", "wall-clock time of the whole run"},
};

constexpr RenamedField kRenamed[] = {
    {"transport", "mean_survival_time_scaled", "mean_survival_time_w2", 3},
    {"transport", "principal_relaxation_time_scaled", "principal_relaxation_time_w2", 3},
    // alpha became the extrapolated local alpha; the window's mean it was keeps its own name.
    {"spreadability", "alpha", "alpha_window_mean", 4},
    {"spreadability", "alpha_stderr", "alpha_window_mean_stderr", 4},
};

constexpr Field kFileLeading[] = {
    {"input", A, S, "", "the packing file, as named on the command line"},
};

// After the shape's fields (shapeFields).
constexpr Field kFile[] = {
    {"n_particles", A, I, "1", "N"},
    {"box_length", A, F, "length", "cubic box edge L", Mean},
    {"semi_axis", A, F, "length", "semi-axis R (major-axis length D = 2 R)"},
    {"phi", A, F, "1", "packing fraction N v1 / L^3", Mean},
    {"mean_width", A, F, "length", "mean width w of one particle (the largest of a mixture)", Mean},
};

// After the shape's fields, which the members share (shapeFields).
constexpr Field kEnsembleOwn[] = {
    {"n_particles", A, I, "1", "N, common to the members"},
    {"n_files", A, I, "1", "members"},
    {"members", D, I, "1", "indices i of the members' groups files/<i>"},
};

constexpr Group kRunGroup{"", "/", "the run", kRun};

/// `leading`, then the shape (geometry/particle_shape): the family's name, written only where
/// it is not the superball, and each family's parameters under their names; then `rest`.
std::vector<Field> withShapeFields(std::span<const Field> leading, std::span<const Field> rest) {
    std::vector<Field> fields(leading.begin(), leading.end());
    for (const ShapeField& shape : shapeFields())
        fields.push_back({.name = shape.name,
                          .kind = A,
                          .type = shape.text ? S : F,
                          .units = shape.units,
                          .description = shape.description,
                          .optional = shape.optional});
    fields.insert(fields.end(), rest.begin(), rest.end());
    return fields;
}

const Group& fileGroupOnce() {
    static const std::vector<Field> fields = withShapeFields(kFileLeading, kFile);
    static const Group group{"", "files/<i>", "one input", fields};
    return group;
}

/// The ensemble groups, derived from the fields and their Reduce, built once per group.
class EnsembleSchemas {
  public:
    EnsembleSchemas() {
        build("", "ensembles/<k>", "statistics over inputs of equal shape and N",
              withShapeFields({}, kEnsembleOwn), fileGroupOnce());
    }
    const Group& root() const { return groups_.at("").group; }
    const Group& operator[](const Group& source) {
        const std::scoped_lock lock(mutex_);
        const auto it = groups_.find(std::string(source.name));
        if (it != groups_.end()) return it->second.group;
        return build(source.name, "ensembles/<k>/" + std::string(source.name),
                     "statistics of " + std::string(source.path), {}, source);
    }

  private:
    struct Owned {
        std::vector<Field> fields;
        Group group;
    };
    std::string_view keep(std::string text) { return texts_.emplace_back(std::move(text)); }

    void addStatistics(std::vector<Field>& out, const Field& f) {
        out.push_back({f.name, f.kind, Type::Float, f.units,
                       keep("mean over the files: " + std::string(f.description)), No, f.optional});
        out.push_back({keep(std::string(f.name) + "_std"), f.kind, Type::Float, f.units,
                       keep("sample standard deviation of " + std::string(f.name) +
                            " over the files (n - 1; 0 for one file)"),
                       No, f.optional});
    }
    /// A file never has it (optional there); every ensemble with the group does, unless the
    /// field is pooledOptional.
    static void addPooled(std::vector<Field>& out, const Field& f) {
        out.push_back(f);
        out.back().optional = f.pooledOptional;
    }
    /// A group's first curve brings the common grid; a later one (S's partials, on S's shells)
    /// its mean and deviation only, optional where it is.
    void addCurve(std::vector<Field>& out, const Field& f) {
        const std::string v(f.name);
        const bool first =
            std::none_of(out.begin(), out.end(), [](const Field& g) { return g.name == "Q_w"; });
        if (first) {
            out.push_back({"bin_width_Q_w", A, F, "1",
                           "bin width of the common Q w grid: the mean of the files' 2 pi w / L"});
            out.push_back({"Q_w", D, F, "1", "mean Q w of the files' shells in the bin"});
            out.push_back({"Q", D, F, "1/length", "mean Q of the files' shells in the bin"});
        }
        out.push_back({.name = f.name,
                       .kind = D,
                       .type = F,
                       .units = f.units,
                       .description = keep("mean over the files of " + v),
                       .optional = f.optional});
        out.push_back({.name = keep(v + "_std"),
                       .kind = D,
                       .type = F,
                       .units = f.units,
                       .description =
                           keep("sample standard deviation of " + v + " over the files in the bin"),
                       .optional = f.optional});
        if (!first) return;
        out.push_back({"count", D, I, "1", "wave vectors in the bin, all files together"});
        out.push_back({"files", D, I, "1", "files with a shell in the bin"});
    }
    void addSteps(std::vector<Field>& out, const Field& f) {
        const std::string v(f.name), x(f.over);
        out.push_back({f.over, D, F, "1",
                       keep(fmt::format("common grid: {} points from 0 to the files' largest {}",
                                        kStepsGrid + 1, x))});
        out.push_back({f.name, D, F, f.units, keep("mean over the files of " + v + " there")});
        out.push_back({keep(v + "_std"), D, F, f.units,
                       keep("sample standard deviation of " + v + " over the files there")});
    }
    const Group& build(std::string_view name, std::string path, std::string title,
                       std::span<const Field> own, const Group& source) {
        Owned& o = groups_[std::string(name)];
        o.fields.assign(own.begin(), own.end());
        if (!name.empty()) o.fields.push_back({"n_files", A, I, "1", "members with this group"});
        for (const Field& f : source.fields) {
            if (f.reduce == Reduce::MeanStd) addStatistics(o.fields, f);
            if (f.reduce == Reduce::Curve) addCurve(o.fields, f);
            if (f.reduce == Reduce::Pointwise) addStatistics(o.fields, f);
            if (f.reduce == Reduce::Same) o.fields.push_back(f);
            if (f.reduce == Reduce::Pooled) addPooled(o.fields, f);
            if (f.reduce == Reduce::Steps) addSteps(o.fields, f);
        }
        o.group = {name, keep(std::move(path)), keep(std::move(title)), o.fields};
        return o.group;
    }

    std::mutex mutex_;
    std::deque<std::string> texts_;
    std::map<std::string, Owned> groups_; ///< std::map: the groups stay where they are
};

EnsembleSchemas& ensembleSchemas() {
    static EnsembleSchemas schemas;
    return schemas;
}

} // namespace

std::span<const RenamedField> renamedFields() {
    return kRenamed;
}

const Group& runGroup() {
    return kRunGroup;
}
const Group& fileGroup() {
    return fileGroupOnce();
}
const Group& ensembleRootGroup() {
    return ensembleSchemas().root();
}

const Group& ensembleGroup(const Group& source) {
    if (source.name.empty())
        throw std::logic_error("results schema: the ensemble root has no name");
    return ensembleSchemas()[source];
}

const Field* findField(const Group& group, std::string_view name) {
    for (const Field& f : group.fields)
        if (f.name == name) return &f;
    return nullptr;
}

std::string shapeName(const Field& field) {
    if (field.kind == Kind::Attribute) return "";
    return field.width > 0 ? fmt::format("n x {}", field.width) : "n";
}

double unitFactor(std::string_view units, double lengthUnit) {
    if (units == "length") return lengthUnit;
    if (units == "length^2" || units == "time") return lengthUnit * lengthUnit;
    if (units == "length^3") return lengthUnit * lengthUnit * lengthUnit;
    if (units == "1/length") return 1.0 / lengthUnit;
    if (units == "length^2/time") return 1.0; // (length^2) / (length^2 / diffusion coefficient)
    if (units.find("length") != std::string_view::npos ||
        units.find("time") != std::string_view::npos)
        throw std::logic_error(fmt::format("results schema: units '{}' have no factor", units));
    return 1.0;
}

std::string unitsAttributeName(std::string_view attribute) {
    return std::string(attribute) + "_units";
}

} // namespace sbpack::schema
