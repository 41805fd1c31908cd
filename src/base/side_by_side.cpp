// runSideBySide: one std::thread per job, each job's exception kept for the caller.
#include "base/side_by_side.hpp"

#include <exception>
#include <system_error>
#include <thread>

namespace shapevo {

void runSideBySide(const std::vector<std::function<void()>>& jobs) {
    std::vector<std::exception_ptr> failures(jobs.size());
    const auto runOne = [&](std::size_t i) {
        try {
            jobs[i]();
        } catch (...) {
            failures[i] = std::current_exception();
        }
    };
    std::vector<std::thread> threads;
    threads.reserve(jobs.size());
    for (std::size_t i = 0; i < jobs.size(); ++i) {
        try {
            threads.emplace_back(runOne, i);
        } catch (const std::system_error&) {
            runOne(i);  // no thread to be had: run it here
        }
    }
    for (std::thread& t : threads) t.join();
    for (const std::exception_ptr& f : failures)
        if (f) std::rethrow_exception(f);
}

}  // namespace shapevo
