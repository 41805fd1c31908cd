// The search stage's sections, read by the stage itself:
//  [ga]      population, generations, initial_genes_min / _max (PopulationSettings: the sizes
//            every method uses, not only the GA; kept in [ga] so that configs stay as they are)
//            and elitism, tournament, mutation, grow / cut / alter weights, crossover_retries
//            (GaSettings: the GA's own operators), checked against each other;
//  [search]  method (a name in search/search_methods.cpp's table), diagnostics, and every
//            method's own keys, each read by the method's entry (so a key of another method is
//            known, not an error).
// Checks across stages (initial genes vs genome.max_genes) are run/config_file.cpp's.
#pragma once
#include "base/section_reader.hpp"
#include "search/population_settings.hpp"
#include "search/search_settings.hpp"

namespace shapevo {

/// Fills both structs from [ga]: `population` gets the sizes, `ga` the GA's operators.
void readGaSection(SectionReader& r, PopulationSettings& population, GaSettings& ga);
void readSearchSection(SectionReader& search, SearchSettings& settings);

}  // namespace shapevo
