#include "protocol/checkpoint_entries.hpp"

#include "protocol/protocol_advice.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <stdexcept>
#include <type_traits>

namespace sbpack {
namespace {

enum class Group { provenance, resumeState };

const char* groupName(Group group) {
    return group == Group::provenance ? "provenance" : "resume_state";
}

/// One entry: where it lives, the type it is stored as (a ProvenanceValue alternative), how a
/// run writes it (none: not written for this run) and how it is read back (none: write-only).
struct Entry {
    Group group;
    std::string key;
    std::size_t type;
    bool optional = false;
    std::function<std::optional<ProvenanceValue>(const CheckpointFields&)> write;
    std::function<void(CheckpointFields&, const ProvenanceValue&, const std::string&)> read;
};

template <class Stored> constexpr std::size_t typeOf() {
    return ProvenanceValue(Stored{}).index();
}

/// The field `field(fields)` stored as `Stored`; unsigned fields refuse negative values.
template <class Stored, class Field>
Entry field(Group group, std::string key, Field field, bool optional = false) {
    auto write = [field](const CheckpointFields& f) -> std::optional<ProvenanceValue> {
        return ProvenanceValue(static_cast<Stored>(field(f)));
    };
    auto read = [field, key](CheckpointFields& f, const ProvenanceValue& value,
                             const std::string& where) {
        auto& target = field(f);
        using Target = std::remove_reference_t<decltype(target)>;
        const Stored stored = std::get<Stored>(value);
        if constexpr (std::is_unsigned_v<Target>)
            if (stored < 0)
                throw std::invalid_argument(where + "checkpoint entry '" + key + "' is negative");
        target = static_cast<Target>(stored);
    };
    return {group, std::move(key), typeOf<Stored>(), optional, write, read};
}

/// A value written for readers of the file only (derived from the others).
Entry derived(Group group, std::string key,
              std::function<std::optional<ProvenanceValue>(const CheckpointFields&)> write) {
    return {group, std::move(key), 0, true, std::move(write), nullptr};
}

/// A growth rate: the rate in use is written, and read back as set.
Entry rate(std::string key, std::optional<double> ProtocolParameters::*member,
           double (ProtocolParameters::*used)() const) {
    return {Group::provenance,
            std::move(key),
            typeOf<double>(),
            false,
            [used](const CheckpointFields& f) { return ProvenanceValue((f.parameters.*used)()); },
            [member](CheckpointFields& f, const ProvenanceValue& value, const std::string&) {
                f.parameters.*member = std::get<double>(value);
            }};
}

/// An optional entry written only where `applies` (a finish, issue 64; a plateau's raise,
/// docs/design.md §3 "Plateaus"; a mixture, docs/mixtures.md): the files of the other runs stay
/// as they were.
Entry writtenOnlyWhere(bool (*applies)(const CheckpointFields&), Entry e) {
    e.write = [applies,
               write = e.write](const CheckpointFields& f) -> std::optional<ProvenanceValue> {
        if (!applies(f)) return std::nullopt;
        return write(f);
    };
    return e;
}

Entry finish(Entry e) {
    return writtenOnlyWhere(
        [](const CheckpointFields& f) { return f.parameters.pressureFinish != 0.0; }, std::move(e));
}

Entry plateau(Entry e) {
    return writtenOnlyWhere([](const CheckpointFields& f) { return f.status.stallSpeed != 1.0; },
                            std::move(e));
}

Entry mixture(Entry e) {
    return writtenOnlyWhere([](const CheckpointFields& f) { return f.parameters.isMixture(); },
                            std::move(e));
}

/// The phase, range-checked (a phase beyond Done would never end).
Entry phase() {
    return {Group::resumeState,
            "phase",
            typeOf<std::int64_t>(),
            false,
            [](const CheckpointFields& f) {
                return ProvenanceValue(static_cast<std::int64_t>(f.status.phase));
            },
            [](CheckpointFields& f, const ProvenanceValue& value, const std::string& where) {
                const std::int64_t stored = std::get<std::int64_t>(value);
                if (stored < 0 || stored > static_cast<std::int64_t>(Phase::Done))
                    throw std::invalid_argument(where + "checkpoint state phase is " +
                                                std::to_string(stored) +
                                                ", not 0 (fast), 1 (slow) or 2 (done)");
                f.status.phase = static_cast<Phase>(stored);
            }};
}

/// The format name, checked first among the resume state.
Entry format() {
    return {Group::resumeState,
            "format",
            typeOf<std::string>(),
            false,
            [](const CheckpointFields&) { return ProvenanceValue(std::string(kCheckpointFormat)); },
            [](CheckpointFields&, const ProvenanceValue& value, const std::string& where) {
                if (std::get<std::string>(value) != kCheckpointFormat)
                    throw std::invalid_argument(where + "checkpoint state format is not " +
                                                std::string(kCheckpointFormat));
            }};
}

std::vector<Entry> parameterEntries() {
    constexpr Group P = Group::provenance;
    return {
        derived(P, "generator",
                [](const CheckpointFields&) {
                    return ProvenanceValue(std::string("sbgen (DTS event-driven MD)"));
                }),
        field<std::int64_t>(
            P, "seed", [](auto& f) -> auto& { return f.parameters.seed; }),
        field<double>(
            P, "phi_init", [](auto& f) -> auto& { return f.parameters.phiInit; }),
        rate("gamma_fast", &ProtocolParameters::gammaFast, &ProtocolParameters::fastGrowthRate),
        rate("gamma_slow", &ProtocolParameters::gammaSlow, &ProtocolParameters::slowGrowthRate),
        field<double>(
            P, "pressure_switch", [](auto& f) -> auto& { return f.parameters.pressureSwitch; }),
        field<double>(
            P, "pressure_final", [](auto& f) -> auto& { return f.parameters.pressureFinal; }),
        finish(field<double>(
            P, "pressure_finish", [](auto& f) -> auto& { return f.parameters.pressureFinish; },
            true)),
        finish(field<double>(
            P, "finish_speed", [](auto& f) -> auto& { return f.parameters.finishSpeed; }, true)),
        mixture(field<double>(
            P, "size_ratio", [](auto& f) -> auto& { return f.parameters.sizeRatio; }, true)),
        mixture(field<double>(
            P, "large_fraction", [](auto& f) -> auto& { return f.parameters.largeFraction; },
            true)),
        mixture(field<double>(
            P, "polydispersity", [](auto& f) -> auto& { return f.parameters.polydispersity; },
            true)),
        field<double>(
            P, "collisions_per_window",
            [](auto& f) -> auto& { return f.parameters.collisionsPerWindow; }),
        field<double>(
            P, "cost_limit", [](auto& f) -> auto& { return f.parameters.costLimit; }, true),
        field<std::int64_t>(
            P, "force_windows", [](auto& f) -> auto& { return f.parameters.forceWindows; }, true),
        derived(P, "expected_collisions",
                [](const CheckpointFields& f) {
                    return ProvenanceValue(expectedCost(f.parameters).collisions);
                }),
    };
}

std::vector<Entry> statusEntries() {
    constexpr Group P = Group::provenance;
    std::vector<Entry> entries = {
        field<double>(
            P, "final_reduced_pressure", [](auto& f) -> auto& { return f.status.reducedPressure; }),
        field<std::int64_t>(
            P, "collisions", [](auto& f) -> auto& { return f.status.collisions; }),
        field<std::int64_t>(
            P, "relists", [](auto& f) -> auto& { return f.status.relists; }),
        field<std::int64_t>(
            P, "stale_events", [](auto& f) -> auto& { return f.status.staleEvents; }),
        field<std::int64_t>(
            P, "rechecks", [](auto& f) -> auto& { return f.status.rechecks; }, true),
        plateau(field<double>(
            P, "stall_speed", [](auto& f) -> auto& { return f.status.stallSpeed; }, true)),
        derived(P, "events",
                [](const CheckpointFields& f) {
                    const ProtocolStatus& s = f.status;
                    return ProvenanceValue(static_cast<std::int64_t>(s.collisions + s.relists +
                                                                     s.staleEvents + s.rechecks));
                }),
    };
    for (const auto& named : PredictorStats::kCounters) {
        const auto counter = named.second; // captured below (a structured binding cannot be)
        Entry e = field<std::int64_t>(
            P, named.first, [counter](auto& f) -> auto& { return f.status.predictor.*counter; },
            true);
        e.write = [counter](const CheckpointFields& f) -> std::optional<ProvenanceValue> {
            if (!rotating(f.parameters.shape)) return std::nullopt; // spheres predict exactly
            return ProvenanceValue(static_cast<std::int64_t>(f.status.predictor.*counter));
        };
        entries.push_back(std::move(e));
    }
    entries.push_back(field<std::int64_t>(
        P, "windows", [](auto& f) -> auto& { return f.status.windows; }));
    entries.push_back(field<double>(
        P, "wall_time_s", [](auto& f) -> auto& { return f.status.wallSeconds; }));
    entries.push_back(field<double>(
        P, "cpu_time_s", [](auto& f) -> auto& { return f.status.cpuSeconds; }, true));
    return entries;
}

std::vector<Entry> resumeEntries() {
    constexpr Group R = Group::resumeState;
    return {
        format(),
        phase(),
        field<std::int64_t>(
            R, "subset_windows", [](auto& f) -> auto& { return f.status.subsetWindows; }, true),
        field<std::int64_t>(
            R, "stalled_windows", [](auto& f) -> auto& { return f.status.stall.stalledWindows; },
            true),
        field<double>(
            R, "stall_pressure", [](auto& f) -> auto& { return f.status.stall.stallPressure; },
            true),
        field<std::int64_t>(
            R, "longest_doubling", [](auto& f) -> auto& { return f.status.stall.longestDoubling; },
            true),
        field<double>(
            R, "base_diameter", [](auto& f) -> auto& { return f.clock.baseDiameter; }),
        field<double>(
            R, "growth_elapsed", [](auto& f) -> auto& { return f.clock.elapsed; }),
        field<double>(
            R, "growth_rate", [](auto& f) -> auto& { return f.clock.rate; }),
        // Their rows are the dataset resume_state/pair_records (shapes/registry); common/io reads
        // this count to read it.
        derived(R, "pair_records",
                [](const CheckpointFields& f) -> std::optional<ProvenanceValue> {
                    if (f.pairRecords.empty()) return std::nullopt;
                    return ProvenanceValue(
                        static_cast<std::int64_t>(f.pairRecords.size() / kPairRecordColumns));
                }),
    };
}

/// The table, in the order written (and read: the resume state's format before the rest).
const std::vector<Entry>& table() {
    static const std::vector<Entry> entries = [] {
        std::vector<Entry> all = resumeEntries();
        for (std::vector<Entry> part : {parameterEntries(), statusEntries()})
            all.insert(all.end(), part.begin(), part.end());
        return all;
    }();
    return entries;
}

template <class AnyPacking> auto& groupOf(AnyPacking& packing, Group group) {
    return group == Group::provenance ? packing.provenance : packing.resumeState;
}

/// The engine's growth clock from a checkpoint, refused if tampered with: a non-positive size
/// or rate, or a diameter that disagrees with the packing's semi_axis (a resume must continue
/// the packing in the file, not silently another size).
GrowthClock checkedClock(const GrowthClock& clock, const Packing& packing,
                         const std::string& source) {
    const auto refuse = [&](const std::string& problem) {
        throw std::invalid_argument("'" + source + "': checkpoint state " + problem);
    };
    if (!(std::isfinite(clock.baseDiameter) && clock.baseDiameter > 0.0))
        refuse("base_diameter must be positive");
    if (!(std::isfinite(clock.rate) && clock.rate > 0.0)) refuse("growth_rate must be positive");
    if (!(std::isfinite(clock.elapsed) && clock.elapsed >= 0.0))
        refuse("growth_elapsed must be finite and non-negative");
    const double diameter = 2.0 * packing.semiAxis;
    if (std::abs(clock.diameter() - diameter) > 1e-12 * diameter)
        refuse("gives the diameter " + std::to_string(clock.diameter()) +
               ", not 2 semi_axis = " + std::to_string(diameter));
    return clock;
}

/// The parameters of a checkpoint's run (its size and p from the packing), validated.
ProtocolParameters checkedParameters(ProtocolParameters parameters, const Packing& packing,
                                     const std::string& source) {
    parameters.particles = static_cast<int>(packing.size());
    parameters.shape = packing.shapeSpec;
    try {
        parameters.validate();
    } catch (const ProtocolParameterError& e) {
        throw std::invalid_argument("'" + source + "': checkpoint parameter " + e.what());
    }
    return parameters;
}

} // namespace

std::vector<CheckpointKey> checkpointKeys() {
    std::vector<CheckpointKey> keys;
    for (const Entry& e : table())
        keys.push_back({groupName(e.group), e.key, e.read != nullptr, e.optional});
    return keys;
}

void writeCheckpoint(const CheckpointFields& fields, Packing& packing) {
    for (const Entry& e : table())
        if (const std::optional<ProvenanceValue> value = e.write(fields))
            groupOf(packing, e.group)[e.key] = *value;
    packing.pairRecords = fields.pairRecords;
}

CheckpointFields readCheckpoint(const Packing& packing, const std::string& source) {
    const std::string where = "'" + source + "': ";
    CheckpointFields fields;
    for (const Entry& e : table()) {
        if (!e.read) continue;
        const auto& entries = groupOf(packing, e.group);
        const auto found = entries.find(e.key);
        if (found == entries.end() && e.optional) continue;
        if (found == entries.end() || found->second.index() != e.type)
            throw std::invalid_argument(where + "not an sbgen checkpoint (" + groupName(e.group) +
                                        " '" + e.key + "' missing or of the wrong type)");
        e.read(fields, found->second, where);
    }
    fields.parameters = checkedParameters(fields.parameters, packing, source);
    fields.clock = checkedClock(fields.clock, packing, source);
    if (!(std::isfinite(fields.status.stallSpeed) && fields.status.stallSpeed >= 1.0))
        throw std::invalid_argument(where + "checkpoint provenance 'stall_speed' must be at "
                                            "least 1 (the slow rate's raise at plateaus)");
    fields.pairRecords = packing.pairRecords;
    return fields;
}

} // namespace sbpack
