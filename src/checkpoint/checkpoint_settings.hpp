// CheckpointSettings: the [checkpoint] part of a config, owned by the checkpoint stage: when a
// checkpoint is written and how many are kept.
#pragma once
#include <cstdint>

namespace shapevo {

/// When checkpoints are written and how many stay.
struct CheckpointSettings {
    std::uint32_t interval = 500;  ///< generations between checkpoints (0 = none by count)
    double seconds = 300;          ///< also checkpoint when this long has passed since the last (0 = never by time)
    int keep = 3;                  ///< newest published checkpoints to keep
};

}  // namespace shapevo
