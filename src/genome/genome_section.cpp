// The [genome] section's reader.
#include "genome/genome_section.hpp"

namespace shapevo {

void readGenomeSection(SectionReader& r, GenomeLimits& limits) {
    r.count("max_genes", limits.maxGenes, 1, 1e7);
    r.count("max_primitives", limits.maxPrimitives, 1, 1 << 26);
}

}  // namespace shapevo
