// HDF5 error handling for the checkpoint files: silence the library's printing (per thread) and
// turn its error stack into one readable line.
#include "checkpoint/hdf5_handles.hpp"

namespace shapevo::h5 {

void silenceErrorPrinting() {
    // Per thread on purpose: with a thread-safe libhdf5, H5Eset_auto2(H5E_DEFAULT, ...) changes
    // only the calling thread's default stack, so a process-wide std::call_once would leave every
    // other thread printing. A thread_local flag makes it once per thread and race-free.
    thread_local bool silenced = false;
    if (silenced) return;
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    silenced = true;
}

namespace {
herr_t keepInnermost(unsigned n, const H5E_error2_t* err, void* out) {
    // Walking upward, entry 0 is the innermost (where the failure was detected).
    if (n == 0 && err && err->desc) *static_cast<std::string*>(out) = err->desc;
    return 0;
}
}  // namespace

std::string takeErrorMessage() {
    std::string message;
    H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, keepInnermost, &message);
    H5Eclear2(H5E_DEFAULT);
    return message.empty() ? "HDF5 call failed" : message;
}

}  // namespace shapevo::h5
