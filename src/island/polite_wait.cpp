// politeWait: MPI_Test (or MPI_Iprobe), then sleep with a doubling back-off.
#include "island/polite_wait.hpp"

#include <algorithm>
#include <chrono>
#include <thread>

namespace shapevo {

void politeWaitUntil(const MpiSession& mpi, const std::function<bool()>& done) {
    WaitTimer wait(mpi);
    // First test in a loop for up to 100 microseconds, yielding the core between tests: a
    // non-blocking collective only progresses inside MPI calls, so sleeping at once would add a
    // sleep to every step of it (a 2-rank meeting took 290 us instead of 1 us). Only a real wait
    // goes on to sleep.
    const auto spinUntil = std::chrono::steady_clock::now() + std::chrono::microseconds(100);
    while (std::chrono::steady_clock::now() < spinUntil) {
        if (done()) return;
        std::this_thread::yield();
    }
    auto pause = std::chrono::microseconds(20);
    while (!done()) {
        std::this_thread::sleep_for(pause);
        pause = std::min(pause * 2, std::chrono::microseconds(250));
    }
}

void politeWait(const MpiSession& mpi, MPI_Request& request) {
    politeWaitUntil(mpi, [&] {
        int flag = 0;
        MPI_Test(&request, &flag, MPI_STATUS_IGNORE);
        return flag != 0;
    });
}

void politeProbe(const MpiSession& mpi, int source, int tag, MPI_Status& status) {
    politeWaitUntil(mpi, [&] {
        int arrived = 0;
        MPI_Iprobe(source, tag, MPI_COMM_WORLD, &arrived, &status);
        return arrived != 0;
    });
}

}  // namespace shapevo
