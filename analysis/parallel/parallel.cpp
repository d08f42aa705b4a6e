#include "parallel/parallel.hpp"

#include <fftw3.h>
#include <omp.h>
#include <tbb/global_control.h>

#include <stdexcept>
#include <string>
#include <thread>

namespace sbpack {

struct ThreadBudgetState {
    tbb::global_control control;
};

int ThreadBudget::maxThreads() {
    const unsigned hardware = std::thread::hardware_concurrency();
    return 4 * static_cast<int>(hardware == 0 ? 1 : hardware);
}

ThreadBudget::ThreadBudget(int threads) : threads_(threads) {
    if (threads < 1 || threads > maxThreads())
        throw std::invalid_argument("option --threads: " + std::to_string(threads) +
                                    " is not in [1, " + std::to_string(maxThreads()) +
                                    "] (4 times the hardware threads)");
    state_.reset(new ThreadBudgetState{
        tbb::global_control(tbb::global_control::max_allowed_parallelism, threads)});
    static const bool fftwThreadsReady = fftw_init_threads() != 0;
    if (!fftwThreadsReady) throw std::runtime_error("FFTW: fftw_init_threads failed");
    fftw_plan_with_nthreads(threads);
    omp_set_num_threads(threads);
}

ThreadBudget::~ThreadBudget() = default;

} // namespace sbpack
