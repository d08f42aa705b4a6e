// Ctrl-C during a compute (docs/python.md, "Interrupts"): the work runs on a worker thread with
// the GIL released while the calling thread, which Python delivers signals to, polls for them.
#include "bindings.hpp"

#include <chrono>
#include <exception>
#include <functional>
#include <future>

namespace sbpack::python {

void runInterruptibly(const std::function<void(const StopRequest&)>& work) {
    StopRequest stop;
    bool interrupted = false;
    {
        py::gil_scoped_release release;
        std::future<void> done = std::async(std::launch::async, work, std::cref(stop));
        while (done.wait_for(std::chrono::milliseconds(50)) != std::future_status::ready) {
            py::gil_scoped_acquire acquire;
            if (!interrupted && PyErr_CheckSignals() != 0) {
                interrupted =
                    true; // KeyboardInterrupt is now set; the work stops at its next check
                stop.request();
            }
        }
        if (!interrupted) {
            done.get(); // rethrows the work's exception
            return;
        }
        try {
            done.get();
        } catch (...) { // the interrupt's own exception: the Python error stands
        }
    }
    throw py::error_already_set();
}

} // namespace sbpack::python
