// The [checkpoint] section, read by the checkpoint stage itself:
//   interval (generations, 0 = none by count), seconds (0 = never by time), keep (1..1e6).
#pragma once
#include "base/section_reader.hpp"
#include "checkpoint/checkpoint_settings.hpp"

namespace shapevo {

void readCheckpointSection(SectionReader& checkpoint, CheckpointSettings& settings);

}  // namespace shapevo
