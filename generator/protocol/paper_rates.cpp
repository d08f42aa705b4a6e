#include "protocol/paper_rates.hpp"

#include <algorithm>
#include <iterator>

namespace sbpack {

const std::vector<MeasuredRate>& paperFastRates() {
    // The rate whose packings at N = 1000 have the paper's phi: the log-linear fit
    // phi = a + b ln gamma of two seeds (four for spheres) at gamma = 0.01, 0.02, 0.03 per p,
    // solved for the paper's phi (bench/fidelity/rate_fit.py; bench/RESULTS.md, E8).
    static const std::vector<MeasuredRate> rates = {
        {0.85, 0.0329}, {0.9, 0.0260}, {0.95, 0.0163}, {1.0, 0.0112}, {1.1, 0.0203},
        {1.2, 0.0276},  {1.3, 0.0262}, {1.4, 0.0236},  {1.5, 0.0218},
    };
    return rates;
}

double paperFastRate(double p) {
    const std::vector<MeasuredRate>& table = paperFastRates();
    if (p <= table.front().p) return table.front().gamma;
    if (p >= table.back().p) return table.back().gamma;
    const auto right = std::upper_bound(table.begin(), table.end(), p,
                                        [](double x, const MeasuredRate& r) { return x < r.p; });
    const MeasuredRate& left = *std::prev(right);
    const double t = (p - left.p) / (right->p - left.p);
    return left.gamma + t * (right->gamma - left.gamma);
}

} // namespace sbpack
