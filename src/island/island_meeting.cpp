// IslandMeeting: one record of doubles per rank, combined by a user-defined MPI operation.
//   [rows n] then per row [best, iou or -1, fitness sum, squares, individuals, evaluations]
//   then [signal, wall time spent, checkpoint due, wait share sum, wait share max]
#include "island/island_meeting.hpp"

#include <algorithm>
#include <cmath>

#include <mpi.h>

#include "island/polite_wait.hpp"

namespace shapevo {

namespace {
constexpr std::size_t kPerRow = 6, kTail = 5;

std::size_t recordLength(std::size_t rows) { return 1 + kPerRow * rows + kTail; }

/// MPI's hook: `len` records of the contiguous type meet() builds; each carries its row count.
void combineRecords(void* in, void* inout, int* len, MPI_Datatype*) {
    const auto* a = static_cast<const double*>(in);
    auto* b = static_cast<double*>(inout);
    for (int k = 0; k < *len; ++k) {
        const std::size_t n = recordLength(std::size_t(a[0]));
        combineMeetings(a, b);
        a += n;
        b += n;
    }
}
}  // namespace

IslandRow islandRow(const GenerationStats& stats, const std::vector<double>& fitness) {
    IslandRow row;
    row.stats = stats;
    for (double f : fitness) row.fitnessSum += f, row.fitnessSquares += f * f;
    row.individuals = double(fitness.size());
    return row;
}

std::vector<double> encodeMeeting(const MeetingInput& in) {
    std::vector<double> r;
    r.reserve(recordLength(in.rows.size()));
    r.push_back(double(in.rows.size()));
    for (const IslandRow& row : in.rows) {
        r.push_back(row.stats.best);
        r.push_back(std::isnan(row.stats.iou) ? -1.0 : row.stats.iou);
        r.push_back(row.fitnessSum);
        r.push_back(row.fitnessSquares);
        r.push_back(row.individuals);
        r.push_back(double(row.stats.evaluations));
    }
    r.push_back(double(in.signal));
    r.push_back(in.wallTimeSpent ? 1.0 : 0.0);
    r.push_back(in.checkpointDue ? 1.0 : 0.0);
    r.push_back(in.waitShare);
    r.push_back(in.waitShare);
    return r;
}

void combineMeetings(const double* in, double* inout) {
    const std::size_t n = std::size_t(in[0]);
    for (std::size_t i = 0; i < n; ++i) {
        const double* a = in + 1 + kPerRow * i;
        double* b = inout + 1 + kPerRow * i;
        // the larger best wins with its IoU; among equal bests the larger IoU
        if (a[0] > b[0]) b[0] = a[0], b[1] = a[1];
        else if (a[0] == b[0]) b[1] = std::max(a[1], b[1]);
        for (std::size_t j = 2; j < kPerRow; ++j) b[j] += a[j];
    }
    const double* a = in + 1 + kPerRow * n;
    double* b = inout + 1 + kPerRow * n;
    b[0] = std::max(a[0], b[0]);
    b[1] = std::max(a[1], b[1]);
    b[2] = std::max(a[2], b[2]);
    b[3] += a[3];
    b[4] = std::max(a[4], b[4]);
}

MeetingResult decodeMeeting(const std::vector<double>& record, const MeetingInput& own, int ranks) {
    MeetingResult m;
    const std::size_t n = own.rows.size();
    m.rows.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double* r = record.data() + 1 + kPerRow * i;
        GenerationStats g;
        g.generation = own.rows[i].stats.generation;
        g.seconds = own.rows[i].stats.seconds;
        g.best = r[0];
        g.iou = r[1] >= 0 ? r[1] : std::numeric_limits<double>::quiet_NaN();
        g.mean = r[2] / r[4];
        g.std = std::sqrt(std::max(0.0, r[3] / r[4] - g.mean * g.mean));
        g.evaluations = std::uint64_t(r[5]);
        m.rows.push_back(g);
    }
    const double* t = record.data() + 1 + kPerRow * n;
    m.signal = int(t[0]);
    m.wallTimeSpent = t[1] > 0;
    m.checkpointDue = t[2] > 0;
    m.waitShareMean = t[3] / std::max(1, ranks);
    m.waitShareMax = t[4];
    return m;
}

MeetingResult meet(const MpiSession& mpi, const MeetingInput& in) {
    std::vector<double> record = encodeMeeting(in);
    if (mpi.active() && mpi.size() > 1) {
        MPI_Datatype type;
        MPI_Type_contiguous(int(record.size()), MPI_DOUBLE, &type);
        MPI_Type_commit(&type);
        MPI_Op op;
        MPI_Op_create(&combineRecords, 1, &op);
        MPI_Request request;
        MPI_Iallreduce(MPI_IN_PLACE, record.data(), 1, type, op, MPI_COMM_WORLD, &request);
        politeWait(mpi, request);
        MPI_Op_free(&op);
        MPI_Type_free(&type);
    }
    return decodeMeeting(record, in, mpi.size());
}

}  // namespace shapevo
