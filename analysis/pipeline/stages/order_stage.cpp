// order: the order metrics of common/order (docs/order-metrics.md) over the centroids, the
// contact network kept by contacts, the SANN bonds and the particles' axes, and the verdict
// whether the packing has ordered.
#include "order/order_fields.hpp"
#include "pipeline/stage.hpp"
#include "pipeline/stages/stages.hpp"

#include <fmt/format.h>

namespace sbpack::stages {

namespace {

/// "Q6 = 0.0213, T = 0.0721, P4 = 0.0037, solid-like 0.0088": the metrics the packing has.
std::string orderDetail(const OrderMetrics& m) {
    std::string detail = m.cutoffBonds ? "Q6 = " + describe(m.cutoffBonds->q6.globalOrder, 3)
                                       : std::string("Q6 undetermined (no g2 minimum)");
    if (m.translational) detail += ", T = " + describe(m.translational->order, 3);
    if (m.cubatic) detail += ", P4 = " + describe(m.cubatic->order, 3);
    if (m.solidLike) detail += ", solid-like " + describe(m.solidLike->solidFraction, 3);
    return detail;
}

} // namespace

bool runOrder(FileContext& context, schema::Record& record) {
    const Stopwatch clock;
    const Packing& packing = context.packing();
    OrderFigures figures;
    figures.metrics = measureOrder(packing, &context.kept<KeptContacts>(Analysis::Contacts).pairs);
    figures.verdict = orderVerdict(figures.metrics);
    figures.majorAxis = 2.0 * packing.semiAxis;
    figures.seconds = clock.seconds();
    if (figures.verdict.ordered)
        context.progress().warn("order: this packing has ordered: " + figures.verdict.reason);
    context.progress().stageDone("order", figures.seconds, orderDetail(figures.metrics));
    order_fields::kTable.fill(record, figures, context.scales());
    return true;
}

} // namespace sbpack::stages
