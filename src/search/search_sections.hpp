// The search stage's sections, read by the stage itself:
//  [ga]      population, generations, elitism, tournament, mutation, grow / cut / alter weights,
//            crossover_retries, initial_genes_min / _max (sizes every method uses; the GA's own
//            operators' settings), checked against each other;
//  [search]  method (a name in search/search_methods.cpp's table), diagnostics, and every
//            method's own keys, each read by the method's entry (so a key of another method is
//            known, not an error).
// Checks across stages (initial genes vs genome.max_genes) are run/config_file.cpp's.
#pragma once
#include "base/section_reader.hpp"
#include "search/search_settings.hpp"

namespace shapevo {

void readGaSection(SectionReader& ga, GaSettings& settings);
void readSearchSection(SectionReader& search, SearchSettings& settings);

}  // namespace shapevo
