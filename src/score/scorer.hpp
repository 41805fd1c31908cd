// Scorer: the one interface search methods see: chromosome -> fitness, a pure function.
// Volume (score/volume_scorer.hpp) and image (score/image_scorer.hpp) targets implement it;
// each thread brings its own workspace, made by the scorer that uses it.
#pragma once
#include <memory>

#include "genome/chromosome.hpp"
#include "geometry/derive.hpp"

namespace shapevo {

/// Per-thread scratch space of a scorer. A scorer's fitness() only ever receives the workspaces
/// its own makeWorkspace() made, so it may static_cast to its derived type.
struct ScoreWorkspace {
    virtual ~ScoreWorkspace() = default;
    DeriveScratch derive;
    Geometry geometry;
};

class Scorer {
public:
    virtual ~Scorer() = default;
    virtual std::unique_ptr<ScoreWorkspace> makeWorkspace() const = 0;
    /// Higher is better. Must not allocate once the workspace is warm.
    virtual double fitness(const Chromosome& c, ScoreWorkspace& w) const = 0;
    virtual const Grammar& grammar() const = 0;
};

}  // namespace shapevo
