// The [migration] section's reader.
#include "island/migration_section.hpp"

#include <string>

#include "base/input_error.hpp"

namespace shapevo {

void readMigrationSection(SectionReader& r, MigrationSettings& m) {
    r.count("interval", m.interval, 0, 1e9);
    r.count("count", m.count, 0, 1e7);
    r.count("meeting_interval", m.meetingInterval, 0, 1e9);
    std::string mode = "sync";
    r.string("mode", mode);
    if (mode != "sync" && mode != "async")
        r.fail("mode", "migration.mode must be \"sync\" or \"async\", got \"" + shortened(mode) + "\"");
    m.async = mode == "async";
}

}  // namespace shapevo
