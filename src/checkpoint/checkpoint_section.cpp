// The [checkpoint] section's reader.
#include "checkpoint/checkpoint_section.hpp"

namespace shapevo {

void readCheckpointSection(SectionReader& r, CheckpointSettings& c) {
    r.count("interval", c.interval, 0, 1e9);
    r.number("seconds", c.seconds, 0, 1e9);
    std::uint32_t keep = std::uint32_t(c.keep);
    r.count("keep", keep, 1, 1e6);
    c.keep = int(keep);
}

}  // namespace shapevo
