#include "shapes/registry.hpp"

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

namespace sbpack {
namespace {

template <class Shape> std::vector<double> rowsOf(const EventDrivenMd<Shape>& engine) {
    using Memory = typename Shape::Memory;
    std::vector<double> rows;
    if constexpr (Memory::kCheckpointColumns > 0) {
        static_assert(2 + Memory::kCheckpointColumns == kPairRecordColumns);
        const auto records = engine.pairRecords();
        rows.reserve(kPairRecordColumns * records.size());
        for (const auto& record : records) {
            rows.insert(rows.end(), {static_cast<double>(record.i), static_cast<double>(record.j)});
            record.memory.appendColumns(rows);
        }
    }
    return rows;
}

template <class Shape>
void restoreRows(EventDrivenMd<Shape>& engine, const std::vector<double>& rows,
                 const std::string& source) {
    using Memory = typename Shape::Memory;
    if constexpr (Memory::kCheckpointColumns == 0) {
        if (!rows.empty())
            throw std::invalid_argument("'" + source +
                                        "': checkpoint has pair_records for spheres");
    } else {
        std::vector<typename EventDrivenMd<Shape>::PairRecord> records(rows.size() /
                                                                       kPairRecordColumns);
        const auto n = static_cast<double>(engine.particles().size());
        for (std::size_t k = 0; k < records.size(); ++k) {
            const double* row = rows.data() + kPairRecordColumns * k;
            const auto refuse = [&](const std::string& problem) {
                throw std::invalid_argument("'" + source + "': checkpoint resume_state " +
                                            "pair_records row " + std::to_string(k) + ": " +
                                            problem);
            };
            if (!(row[0] >= 0.0 && row[0] < row[1] && row[1] < n && std::floor(row[0]) == row[0] &&
                  std::floor(row[1]) == row[1]))
                refuse("the particles must be indices i < j < n_particles");
            std::string problem;
            const std::optional<Memory> memory = Memory::fromColumns(row + 2, problem);
            if (!memory) refuse(problem);
            records[k] = {static_cast<int>(row[0]), static_cast<int>(row[1]), *memory};
        }
        engine.restorePairRecords(records);
    }
}

} // namespace

MeasuredProtocol measuredProtocol(const ShapeSpec& shape) {
    MeasuredProtocol measured;
    const bool runs =
        EngineFamilies::find(shape.familyIndex(), [&]<class E>(std::type_identity<E>) {
            measured = E::measured(shape.values());
        });
    if (!runs)
        measured.problem = {std::string(kShapeFamilyKey), "sbgen does not run " +
                                                              std::string(shape.info().name) +
                                                              "s (sbanalyze analyses them)"};
    return measured;
}

std::string shapeOptionHelp(std::string_view family, const ShapeParameter& parameter) {
    std::string help(parameter.description);
    if (const ShapeFamily* known = findShapeFamily(family))
        EngineFamilies::find(known - shapeFamilies().data(), [&]<class E>(std::type_identity<E>) {
            help = E::optionHelp(parameter);
        });
    return help;
}

bool rotating(const ShapeSpec& shape) {
    return std::visit([](const auto& s) { return std::decay_t<decltype(s)>::kRotates; },
                      shapeFor(shape));
}

AnyShape shapeFor(const ShapeSpec& shape) {
    std::optional<AnyShape> engineShape;
    EngineFamilies::find(shape.familyIndex(), [&]<class E>(std::type_identity<E>) {
        std::visit([&](const auto& one) { engineShape = one; }, E::shapeFor(shape.values()));
    });
    if (!engineShape) throw std::invalid_argument(measuredProtocol(shape).problem->message);
    return *engineShape;
}

AnyEngine makeEngine(const ShapeSpec& shape, double boxLength, std::vector<ParticleState> state,
                     GrowthClock clock, std::vector<double> sizes) {
    return std::visit(
        [&](const auto& shape) -> AnyEngine {
            return EventDrivenMd(shape, boxLength, std::move(state), clock, std::move(sizes));
        },
        shapeFor(shape));
}

std::vector<double> pairRecordRows(const AnyEngine& engine) {
    return std::visit([](const auto& e) { return rowsOf(e); }, engine);
}

void restorePairRecords(AnyEngine& engine, const std::vector<double>& rows,
                        const std::string& source) {
    std::visit([&](auto& e) { restoreRows(e, rows, source); }, engine);
}

} // namespace sbpack
