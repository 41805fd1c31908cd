// The table of target kinds and the reading of [target] that chooses one of them.
#include "score/target_kinds.hpp"

#include <array>

#include "base/format_double.hpp"
#include "base/input_error.hpp"
#include "base/word_list.hpp"

#include "score/image/image_kind.hpp"
#include "score/volume/volume_kind.hpp"

namespace shapevo {

namespace {

constexpr std::array<const TargetKind*, 2> kTargetKinds{&volumeTargetKind, &imageTargetKind};

bool uses(const TargetKind& kind, std::string_view section) {
    for (std::string_view s : kind.sections)
        if (s == section) return true;
    return false;
}

}  // namespace

std::span<const TargetKind* const> targetKinds() { return kTargetKinds; }

const TargetKind* findTargetKind(std::string_view name) {
    for (const TargetKind* k : kTargetKinds)
        if (k->name == name) return k;
    return nullptr;
}

std::vector<std::string_view> targetExportFormats() {
    std::vector<std::string_view> out;
    for (const TargetKind* k : kTargetKinds) out.insert(out.end(), k->exportFormats.begin(), k->exportFormats.end());
    return out;
}

const Grammar& requireTreeGrammar(const TargetLoadContext& context, const TargetKind& kind) {
    if (const Grammar* g = context.family.treeGrammar()) return *g;
    throw InputError(context.configPath, "[target]",
                     std::string(kind.noun) + " is matched by a derivation tree's model; a " + std::string(context.family.name()) +
                         " (a 2D graph grammar) draws pictures: give it an image target (image = \"FILE.png\")");
}

std::string countsText(std::initializer_list<NamedCount> counts) {
    std::string out;
    for (const NamedCount& c : counts) out += std::string("  ") + c.name + " " + std::to_string(c.value);
    return out;
}

std::string evaluationText(const TargetKind& kind, double fitness, double iou, std::uint32_t genes, std::size_t primitives,
                           const std::string& counts) {
    return "fitness " + formatDouble(fitness) + "  " + std::string(kind.iouKey) + " " + formatDouble(iou) + "  genes " +
           std::to_string(genes) + "  primitives " + std::to_string(primitives) + counts;
}

std::shared_ptr<const TargetSettings> readTargetSettings(ConfigReader& config) {
    SectionReader& target = config.section("target");
    std::vector<std::unique_ptr<TargetSettings>> read;
    for (const TargetKind* k : kTargetKinds) read.push_back(k->readTarget(target));
    for (const TargetKind* k : kTargetKinds)
        for (std::string_view section : k->sections) config.section(section);

    // The kinds [target] names: one is chosen; none chooses the default, which says what is missing.
    std::vector<std::size_t> named;
    for (std::size_t i = 0; i < read.size(); ++i)
        if (read[i]->named()) named.push_back(i);
    if (named.size() > 1) {
        std::vector<std::string> keys;
        for (std::size_t i : named)
            for (std::string& key : read[i]->namingKeys()) keys.push_back(std::move(key));
        target.failKeys(keys, "[target]",
                        std::string(kTargetKinds[named.back()]->noun) + " cannot be combined with " +
                            std::string(kTargetKinds[named.front()]->keysPhrase));
    }
    const std::size_t chosen = named.empty() ? 0 : named.front();
    const TargetKind& kind = *kTargetKinds[chosen];
    for (const TargetKind* other : kTargetKinds)
        for (std::string_view section : other->sections)
            if (!uses(kind, section) && config.section(section).present())
                config.section(section).failSection("a " + std::string(section) + " is only used with " +
                                                    std::string(other->noun) + " ([target] " + std::string(other->namedBy) + ")");
    const std::string missing =
        "missing [target] " + wordList(kTargetKinds.size(), [](std::size_t i) { return kTargetKinds[i]->namedBy; });
    read[chosen]->finish(config, missing);
    return std::shared_ptr<const TargetSettings>(std::move(read[chosen]));
}

}  // namespace shapevo
