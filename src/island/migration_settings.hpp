// MigrationSettings: the [migration] part of a config, owned by the island stage: how often and
// how many elites move around the ring of islands.
#pragma once
#include <cstdint>

namespace shapevo {

/// Ring migration between islands (one island per MPI rank).
struct MigrationSettings {
    std::uint32_t interval = 20;  ///< generations between migrations (0 = never)
    std::uint32_t count = 5;      ///< best individuals sent to rank + 1, replacing its worst
    bool async = false;           ///< non-blocking messages (not repeatable) instead of lock-step
    /// Sync mode: generations between the islands' meetings, where the curve rows since the last
    /// meeting, stop decisions and checkpoint requests are agreed in one all-reduce. 0 = the
    /// migration interval (20 when migration is off). Async mode has no meetings.
    std::uint32_t meetingInterval = 0;
    std::uint32_t meetingEvery() const { return meetingInterval > 0 ? meetingInterval : interval > 0 ? interval : 20; }
};

}  // namespace shapevo
