// The [checkpoint] section's reader.
#include "checkpoint/checkpoint_section.hpp"

namespace shapevo {

void readCheckpointSection(SectionReader& r, CheckpointSettings& c) {
    r.count("interval", c.interval, 0, 1e9,
            "generations between checkpoints (0: none by count); a run always checkpoints at its end");
    r.number("seconds", c.seconds, 0, 1e9,
             "also checkpoint when this many seconds have passed since the last one (0: never by time)");
    std::uint32_t keep = std::uint32_t(c.keep);
    r.count("keep", keep, 1, 1e6, "the newest checkpoints kept; older ones are deleted");
    c.keep = int(keep);
}

}  // namespace shapevo
