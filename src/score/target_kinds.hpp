// The target kinds: one table, one entry per kind (score/target_kind.hpp says what an entry
// holds; each kind defines its entry in its own folder, e.g. score/image/image_kind.cpp's
// imageTargetKind). Config reading, run set-up, reports and the CLI all read this table, so a new
// kind is its folder under score/ plus one line in target_kinds.cpp.
#pragma once
#include <memory>
#include <span>
#include <string>
#include <string_view>

#include "base/section_reader.hpp"
#include "score/target_kind.hpp"

namespace shapevo {

/// Every kind, the default ("volume", chosen when [target] names none, to say what is missing) first.
std::span<const TargetKind* const> targetKinds();

/// The kind named `name`, or nullptr.
const TargetKind* findTargetKind(std::string_view name);

/// Read [target] (and the sections the kinds use) through the kinds' readers: every kind reads
/// its own keys; the one [target] names is chosen and finished. @throw InputError for a bad key,
/// a [target] that names two kinds or none, or a section only another kind uses.
std::shared_ptr<const TargetSettings> readTargetSettings(ConfigReader& config);

/// Every kind's export formats, in table order ("vdb", "png").
std::vector<std::string_view> targetExportFormats();

}  // namespace shapevo
