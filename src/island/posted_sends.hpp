// PostedSends: non-blocking sends whose buffers live until MPI is done with them. post() copies
// the data, starts MPI_Isend and forgets completed sends as it goes; allComplete() tells whether
// every send has finished (what drainUntilEveryoneIsDone needs at the end of a run).
// Promise: a buffer is freed only after its send has completed (or at destruction, which is
// after the run's final drain).
#pragma once
#include <cstddef>
#include <deque>
#include <memory>
#include <vector>

namespace shapevo {

class PostedSends {
public:
    enum class Type { Uint32, Double };
    PostedSends();
    ~PostedSends();
    PostedSends(const PostedSends&) = delete;
    PostedSends& operator=(const PostedSends&) = delete;

    /// Send `count` elements of `type` at `data` to `rank` with `tag` (data copied first).
    void post(const void* data, std::size_t count, Type type, int rank, int tag);
    /// Every posted send has completed (tests each; never blocks).
    bool allComplete();

private:
    struct Send;
    void retireCompleted();
    std::deque<std::unique_ptr<Send>> sends_;
};

}  // namespace shapevo
