// The [genome] section: the limits every chromosome keeps (GenomeLimits), read by the genome
// stage itself:  max_genes (1..1e7), max_primitives (1..2^26).
#pragma once
#include "base/section_reader.hpp"
#include "genome/chromosome.hpp"

namespace shapevo {

void readGenomeSection(SectionReader& genome, GenomeLimits& limits);

}  // namespace shapevo
