// Run reports: plain text written to a temporary file, then renamed into place.
#include "report/run_report.hpp"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "base/atomic_write.hpp"
#include "base/hash.hpp"

namespace shapevo {

namespace {
void writeText(const std::string& path, const std::string& text) {
    writeStreamAtomically(path, [&](std::ostream& out) { out << text; });
}
std::string jsonString(const std::string& s) {
    std::string r = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') r += '\\', r += c;
        else if (static_cast<unsigned char>(c) < 0x20) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\u%04x", c);
            r += buf;
        } else r += c;
    }
    return r + "\"";
}
}  // namespace

void writeCurveCsv(const std::vector<GenerationStats>& curve, const std::string& path) {
    std::string text = "generation,seconds,evaluations,best,mean,std,iou\n";
    for (const auto& s : curve) {
        char secs[32];
        std::snprintf(secs, sizeof secs, "%.6f", s.seconds);
        text += std::to_string(s.generation) + "," + secs + "," + std::to_string(s.evaluations) + "," +
                formatDouble(s.best) + "," + formatDouble(s.mean) + "," + formatDouble(s.std) + "," +
                (std::isfinite(s.iou) ? formatDouble(s.iou) : std::string()) + "\n";
    }
    writeText(path, text);
}

void writeSummaryJson(const RunSummary& s, const std::string& path) {
    std::string t = "{\n";
    t += "  \"name\": " + jsonString(s.name) + ",\n";
    t += "  \"config\": " + jsonString(s.config) + ",\n";
    t += "  \"grammar\": " + jsonString(s.grammar) + ",\n";
    t += "  \"seed\": " + std::to_string(s.seed) + ",\n";
    t += "  \"generations\": " + std::to_string(s.generations) + ",\n";
    t += "  \"evaluations\": " + std::to_string(s.evaluations) + ",\n";
    t += "  \"wall_seconds\": " + formatDouble(s.wallSeconds) + ",\n";
    t += "  \"best_fitness\": " + formatDouble(s.bestFitness) + ",\n";
    if (!s.iouKey.empty()) t += "  " + jsonString(s.iouKey) + ": " + formatDouble(s.iou) + ",\n";
    t += "  \"best_genes\": " + std::to_string(s.bestGenes) + ",\n";
    t += "  \"best_primitives\": " + std::to_string(s.bestPrimitives) + ",\n";
    t += "  \"target_hash\": \"" + hashHex(s.targetHash) + "\",\n";
    t += "  \"islands\": " + std::to_string(s.islands) + ",\n";
    t += "  \"migration_seconds\": " + formatDouble(s.migrationSeconds) + ",\n";
    t += "  \"checkpoint_seconds\": " + formatDouble(s.checkpointSeconds) + ",\n";
    t += "  \"iou_seconds\": " + formatDouble(s.iouSeconds) + ",\n";
    t += "  \"wait_share_max\": " + formatDouble(s.waitShareMax) + ",\n";
    t += "  \"wait_share_mean\": " + formatDouble(s.waitShareMean) + ",\n";
    t += "  \"wait_share_outside_checkpoints_max\": " + formatDouble(s.waitShareOutsideCheckpointsMax) + ",\n";
    t += "  \"wait_share_outside_checkpoints_mean\": " + formatDouble(s.waitShareOutsideCheckpointsMean) + ",\n";
    t += "  \"non_finite_models\": " + std::to_string(s.nonFiniteModels) + ",\n";
    t += "  \"truncated_models\": " + std::to_string(s.truncatedModels) + ",\n";
    t += "  \"population\": " + std::to_string(s.population) + ",\n";
    t += "  \"cache_bytes\": " + std::to_string(s.cacheBytes) + ",\n";
    t += "  \"model_bytes\": " + std::to_string(s.modelBytes) + ",\n";
    t += "  \"max_rss_bytes\": " + std::to_string(s.maxRssBytes) + ",\n";
    if (!s.changedInputs.empty()) {
        t += "  \"changed_inputs\": [";
        for (std::size_t i = 0; i < s.changedInputs.size(); ++i) t += (i ? ", " : "") + jsonString(s.changedInputs[i]);
        t += "],\n";
    }
    t += "  \"threads\": " + std::to_string(s.threads) + "\n}\n";
    writeText(path, t);
}

}  // namespace shapevo
