// The [migration] section's reader.
#include "island/migration_section.hpp"

#include <string>

#include "base/input_error.hpp"

namespace shapevo {

void readMigrationSection(SectionReader& r, MigrationSettings& m) {
    r.count("interval", m.interval, 0, 1e9,
            "generations between migrations: each island's best `count` go to the next rank and replace its worst (0: "
            "no migration)");
    r.count("count", m.count, 0, 1e7, "individuals sent per migration; at most population - elitism");
    r.count("meeting_interval", m.meetingInterval, 0, 1e9,
            "sync mode: generations between the islands' meetings (curve rows, stopping rules, checkpoints agreed "
            "together); 0 = the migration interval (20 when migration is off)");
    std::string mode = "sync";
    r.string("mode", mode,
             "\"sync\": islands meet at fixed generations, repeatable; \"async\": migrants are sent without waiting, "
             "not repeatable");
    if (mode != "sync" && mode != "async")
        r.fail("mode", "migration.mode must be \"sync\" or \"async\", got \"" + shortened(mode) + "\"");
    m.async = mode == "async";
}

}  // namespace shapevo
