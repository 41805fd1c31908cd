// Run metadata file (run.h5): what a checkpoint needs besides the islands, written by rank 0.
// The names below are a stable public format (docs/run-folder.md, `h5ls -r`, `h5dump -H`).
//
//   /                     root group, attributes:
//       schema_version    u32     format version of the checkpoint layout (3)
//       run_id            string  32 random hex digits made when the run started: with seed,
//                                 config and inputs the run's identity
//       seed              u64     the run's seed
//       generation        u32     generations completed by every island
//       ranks             i32     number of islands (files island-0000.h5 ...)
//       wall_seconds      f64     run time so far, summed over resumes
//       target_hash       u64     hash identifying the scoring target
//       name              string  the run's name
//   /config/text          string  the config as used (with --set overrides applied); attribute
//       path              string  where it was read from
//   /grammar/text         string  the grammar source; attribute
//       path              string  where it was read from
//   /inputs/text          string  one line per input file when the run started:
//                                 "<role> <xxh3-64 hex> <absolute path>" (role: config, grammar,
//                                 mesh, target)
//   /curve                f64 [G x 7]  the global fitness curve (best/mean/std over all
//                                      islands), chunked and extendible; attribute
//       columns           string  "generation,seconds,evaluations,best,mean,std,iou"
//
// Strings are fixed-length, null-padded UTF-8 (h5dump prints them as text; an empty string is
// stored as one NUL). Every dataset has an "xxh3_64" (u64) attribute over its raw bytes.
#include <cmath>
#include <stdexcept>
#include <tuple>

#include "checkpoint/checkpoint_file.hpp"
#include "checkpoint/hdf5_file.hpp"
#include "checkpoint/island_codec.hpp"
#include "checkpoint/run_identity.hpp"
#include "base/input_error.hpp"

namespace shapevo {

void writeRunMetadata(const std::string& path, const RunMetadata& m) {
    using namespace island_layout;
    if (m.ranks < 1) throw std::invalid_argument("run metadata: " + std::to_string(m.ranks) + " islands");
    if (!std::isfinite(m.wallSeconds) || m.wallSeconds < 0)
        throw std::invalid_argument("run metadata: wall time is not a finite non-negative number");
    const std::vector<std::uint8_t> curve = encodeCurve(m.curve);
    h5::H5Writer w(path);
    w.attribute(w.root(), "schema_version", kCheckpointSchemaVersion);
    w.attribute(w.root(), "run_id", m.runId);
    w.attribute(w.root(), "seed", m.seed);
    w.attribute(w.root(), "generation", m.generation);
    w.attribute(w.root(), "ranks", m.ranks);
    w.attribute(w.root(), "wall_seconds", m.wallSeconds);
    w.attribute(w.root(), "target_hash", m.targetHash);
    w.attribute(w.root(), "name", m.name);
    for (auto [group, text, source] : {std::tuple{"config", &m.configText, &m.configPath},
                                       std::tuple{"grammar", &m.grammarText, &m.grammarPath}}) {
        h5::Handle g = w.group(w.root(), group);
        h5::Handle d = w.text(g.get(), "text", *text);
        w.attribute(d.get(), "path", *source);
    }
    {
        h5::Handle g = w.group(w.root(), "inputs");
        w.text(g.get(), "text", formatInputs(m.inputs));
    }
    const hsize_t dims[] = {m.curve.size(), kCurveWidth};
    h5::Handle d = w.dataset(w.root(), "curve", H5T_IEEE_F64LE, curve, dims, /*extendible=*/true);
    w.attribute(d.get(), "columns", std::string(kCurveColumns));
    d.reset();
    w.finish();
}

RunMetadata readRunMetadata(const std::string& path) {
    using namespace island_layout;
    const h5::H5Reader r(path, kOldestReadableSchemaVersion, kCheckpointSchemaVersion);
    RunMetadata m;
    m.schemaVersion = r.schema();
    const bool schema2 = r.schema() == 2;  // its curve has no iou column
    m.runId = r.string("/", "run_id");
    m.seed = r.u64("/", "seed");
    m.generation = r.u32("/", "generation");
    m.ranks = r.i32("/", "ranks");
    if (m.ranks < 1) throw InputError(path, "/@ranks", std::to_string(m.ranks) + " islands; expected at least 1");
    m.wallSeconds = r.f64("/", "wall_seconds");
    if (!std::isfinite(m.wallSeconds) || m.wallSeconds < 0)
        throw InputError(path, "/@wall_seconds", "not a finite non-negative number of seconds");
    m.targetHash = r.u64("/", "target_hash");
    m.name = r.string("/", "name");
    m.configText = r.text("/config/text");
    m.configPath = r.string("/config/text", "path");
    m.grammarText = r.text("/grammar/text");
    m.grammarPath = r.string("/grammar/text", "path");
    m.inputs = parseInputs(r.text("/inputs/text"), path);
    const std::size_t width = schema2 ? kCurveWidthSchema2 : kCurveWidth;
    m.curve = decodeCurve(r.dataset(kCurve, H5T_IEEE_F64LE, 2, width), path, kCurve, width);
    const char* columns = schema2 ? kCurveColumnsSchema2 : kCurveColumns;
    if (r.string(kCurve, "columns") != columns)
        throw InputError(path, std::string(kCurve) + "@columns", std::string("expected \"") + columns + "\"");
    return m;
}

}  // namespace shapevo
