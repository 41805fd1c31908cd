// The [migration] section, read by the island stage itself:
//   interval (0 = never), count, meeting_interval, mode = "sync" | "async".
// Its check against [ga] (count <= population - elitism) is run/config_file.cpp's.
#pragma once
#include "base/section_reader.hpp"
#include "island/migration_settings.hpp"

namespace shapevo {

void readMigrationSection(SectionReader& migration, MigrationSettings& settings);

}  // namespace shapevo
