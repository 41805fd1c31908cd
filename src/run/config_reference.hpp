// The config reference: every key of every section a run's config may hold, with its type,
// default, range and meaning, as markdown (docs/reference/config.md, `shapevo reference config`).
// Promise: it is made by parsing a minimal config of each target kind with parseConfig recording
// what the stages ask for (run/config_key_record.hpp), so a key a stage reads is in it with the
// default and range the code uses; nothing in it is written by hand.
#pragma once
#include <string>
#include <vector>

#include "run/config_key_record.hpp"
#include "score/target_kind.hpp"

namespace shapevo {

/// A key as the reference lists it: what its reader states, and the target kinds whose configs
/// read it (every kind for most keys; [camera]'s only with an image target).
struct ReferenceKey {
    ConfigKeyRecord record;
    std::vector<const TargetKind*> kinds;
};

/// Every key, in the order the stages ask for them (so grouped by section).
std::vector<ReferenceKey> configReferenceKeys();

/// The reference as markdown: a table per section.
std::string configReferenceMarkdown();

}  // namespace shapevo
