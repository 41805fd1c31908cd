// describeCheckpoint: what `shapevo inspect CHECKPOINT` prints, the content of a checkpoint
// folder in words (the same facts `h5ls -r` and `h5dump -H` show as names and shapes).
#include <cinttypes>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "checkpoint/checkpoint_file.hpp"
#include "genome/families/graph_family.hpp"
#include "genome/families/tree_family.hpp"
#include "graph/read_graph_grammar.hpp"
#include "grammar/front_ends.hpp"
#include "base/input_error.hpp"

namespace shapevo {

namespace {

namespace fs = std::filesystem;

std::string format(const char* fmt, auto... args) {
    char buf[512];
    std::snprintf(buf, sizeof buf, fmt, args...);
    return buf;
}

std::string bytes(std::uint64_t n) {
    if (n < 1024) return std::to_string(n) + " B";
    if (n < 1024 * 1024) return format("%.1f KiB", double(n) / 1024);
    return format("%.1f MiB", double(n) / (1024.0 * 1024.0));
}

}  // namespace

std::string describeCheckpoint(const std::string& folder, bool verbose, const AttrOverrides& attrs) {
    const std::string problem = verifyCheckpoint(folder);
    if (!problem.empty()) throw InputError(folder, "", "not a complete checkpoint: " + problem);
    const std::vector<ManifestEntry> files = readManifest(folder);
    std::uint64_t total = 0;
    int islandsListed = 0;
    for (const ManifestEntry& e : files) {
        total += e.size;
        islandsListed += e.name.starts_with("island-") && e.name.ends_with(".h5");  // validated names
    }

    const std::string runPath = (fs::path(folder) / "run.h5").string();
    const RunMetadata m = readRunMetadata(runPath);
    if (m.ranks != islandsListed)
        throw InputError(runPath, "/@ranks", std::to_string(m.ranks) + " islands, but MANIFEST lists " +
                                                 std::to_string(islandsListed) + " island files");
    // The checkpoint carries its own grammar; chromosomes are checked against it. The genome
    // length limit is a run setting, not stored here, so any length is accepted for display.
    // A 2D graph grammar's genome is a graph derivation's (genome/families/graph_family.hpp).
    const bool graphGrammar = graph::isGraphGrammarPath(m.grammarPath);
    const Grammar grammar = graphGrammar ? Grammar{} : parseGrammar(m.grammarText, m.grammarPath, attrs);
    const graph::GraphGrammar graphs = graphGrammar ? graph::parseGraphGrammar(m.grammarText, m.grammarPath) : graph::GraphGrammar{};
    const TreeFamily tree(grammar);
    const GraphFamily drawings(graphs, {});
    const GenomeFamily& family = graphGrammar ? static_cast<const GenomeFamily&>(drawings) : tree;
    const GenomeLimits anyLength{UINT32_MAX};

    std::ostringstream out;
    out << fs::path(folder).filename().string() << ": complete (MANIFEST matches " << files.size() << " files, "
        << bytes(total) << ")\n";
    out << format("  run          %s\n", m.name.empty() ? "(unnamed)" : m.name.c_str());
    out << format("  schema       %" PRIu32 "\n", m.schemaVersion);
    out << format("  generation   %" PRIu32 "\n", m.generation);
    out << format("  islands      %" PRId32 "\n", m.ranks);
    out << format("  seed         %" PRIu64 "\n", m.seed);
    out << format("  target hash  %016" PRIx64 "\n", m.targetHash);
    out << format("  wall time    %.1f s\n", m.wallSeconds);
    out << format("  config       %s (%zu bytes)\n", m.configPath.c_str(), m.configText.size());
    if (graphGrammar)
        out << format("  grammar      %s (%zu bytes, %zu productions; genome: %s)\n", m.grammarPath.c_str(), m.grammarText.size(),
                      graphs.productions.size(), std::string(family.name()).c_str());
    else
        out << format("  grammar      %s (%zu bytes, %zu rules)\n", m.grammarPath.c_str(), m.grammarText.size(),
                      grammar.rules.size());
    if (m.curve.empty()) {
        out << "  curve        empty\n";
    } else {
        const GenerationStats& last = m.curve.back();
        out << format("  curve        %zu rows; generation %" PRIu32 ": best %.6g, mean %.6g, std %.6g, %" PRIu64
                      " evaluations\n",
                      m.curve.size(), last.generation, last.best, last.mean, last.std, last.evaluations);
    }
    out << "  island  individuals         best         mean      genes  curve rows  arriving   file size\n";
    for (int r = 0; r < m.ranks; ++r) {
        const std::string path = (fs::path(folder) / islandFileName(r)).string();
        const IslandState s = readIslandFile(path, family, anyLength);
        if (s.rank != r) throw InputError(path, "/@rank", "says rank " + std::to_string(s.rank) + ", expected " + std::to_string(r));
        std::uint64_t genes = 0;
        double sum = 0;
        for (const Chromosome& c : s.population.individuals) genes += c.genes;
        for (double f : s.population.fitness) sum += f;
        const std::size_t n = s.population.size();
        const std::string best = n ? format("%12.6g", s.population.fitness[s.population.best()]) : format("%12s", "-");
        const std::string mean = n ? format("%12.6g", sum / double(n)) : format("%12s", "-");
        // arriving: migrants received from rank - 1 that join at the next migration (sync mode)
        out << format("  %6d  %11zu %s %s %10" PRIu64 "  %10zu  %8zu  %10s\n", r, n, best.c_str(), mean.c_str(), genes,
                      s.curve.size(), s.arrivals.size(), bytes(fs::file_size(path)).c_str());
    }
    if (verbose) {
        out << "\n--- config: " << m.configPath << " ---\n" << m.configText;
        if (!m.configText.empty() && m.configText.back() != '\n') out << '\n';
    }
    return out.str();
}

}  // namespace shapevo
