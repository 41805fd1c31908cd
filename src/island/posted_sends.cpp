// PostedSends: a deque of (request, owned buffer); completed sends are retired from the front.
#include "island/posted_sends.hpp"

#include <mpi.h>

#include <cstdint>
#include <cstring>

namespace shapevo {

struct PostedSends::Send {
    MPI_Request request = MPI_REQUEST_NULL;
    std::vector<std::uint64_t> buffer;  ///< 8-byte aligned storage for either element type
};

PostedSends::PostedSends() = default;
PostedSends::~PostedSends() = default;

void PostedSends::retireCompleted() {
    while (!sends_.empty()) {
        int done = 0;
        MPI_Test(&sends_.front()->request, &done, MPI_STATUS_IGNORE);
        if (!done) return;
        sends_.pop_front();
    }
}

void PostedSends::post(const void* data, std::size_t count, Type type, int rank, int tag) {
    retireCompleted();
    const std::size_t bytes = count * (type == Type::Double ? sizeof(double) : sizeof(std::uint32_t));
    auto send = std::make_unique<Send>();
    send->buffer.resize((bytes + 7) / 8);
    if (bytes > 0) std::memcpy(send->buffer.data(), data, bytes);
    MPI_Isend(send->buffer.data(), int(count), type == Type::Double ? MPI_DOUBLE : MPI_UINT32_T, rank, tag,
              MPI_COMM_WORLD, &send->request);
    sends_.push_back(std::move(send));
}

bool PostedSends::allComplete() {
    bool all = true;
    for (const auto& s : sends_) {
        int done = 0;
        MPI_Test(&s->request, &done, MPI_STATUS_IGNORE);
        all = all && done;
    }
    return all;
}

}  // namespace shapevo
