// The [genome] section's reader.
#include "genome/genome_section.hpp"

namespace shapevo {

void readGenomeSection(SectionReader& r, GenomeLimits& limits) {
    r.count("max_genes", limits.maxGenes, 1, 1e7, "no operator makes a chromosome longer than this");
    r.count("max_primitives", limits.maxPrimitives, 1, 1 << 26,
            "a derivation stops after this many primitives; a model that reaches it is scored on those and counted "
            "(truncated_models in summary.json)");
}

}  // namespace shapevo
