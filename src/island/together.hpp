// together(): one step (reading input, claiming a folder) run on every rank and agreed on, so that
// when one rank's input is bad every rank leaves, none waits forever for another. SilentFailure:
// what the ranks whose own step succeeded throw then.
// Promise: a mistake every rank shares is reported once (by rank 0); a rank's own mistake is
// reported by that rank; the others leave quietly.
#pragma once
#include <exception>

#include "base/input_error.hpp"
#include "island/mpi_session.hpp"

namespace shapevo {

/// Thrown on ranks whose input was fine when another rank's was not: exit 2 without a message.
struct SilentFailure {};

/// Run `f` on every rank; if it threw InputError anywhere, every rank leaves: the failing ranks
/// rethrow (only rank 0 when it failed too, so a shared mistake is reported once), the others
/// throw SilentFailure. Collective.
template <class F>
void together(const MpiSession& mpi, F&& f) {
    std::exception_ptr error;
    try {
        f();
    } catch (const InputError&) {
        error = std::current_exception();
    }
    if (mpi.allTrue(!error)) return;
    const bool rootFailed = !mpi.fromRoot(!error);
    if (error && (mpi.rank() == 0 || !rootFailed)) std::rethrow_exception(error);
    throw SilentFailure{};
}

}  // namespace shapevo
