// DrawingScorer: a graph-grammar genome -> its derivation (genome/families/graph_family.hpp) ->
// its drawing (graph/drawing.hpp) -> an exact raster in the target's frame (graph/
// drawing_raster.hpp) -> pixel counts against one ImageTarget -> fitness (image_fitness.hpp, the
// same forms as a silhouette's). A pure function of the genome; each thread brings a Workspace.
//
// Tolerance (target.tolerance = t pixels, for thin line art; 0: none): a covered pixel within t
// pixels (Euclidean, centre to centre) of a hit pixel is not counted as avoided, and a hit pixel
// within t of a covered pixel counts as hit. The target's side (its hit pixels grown by t) is
// computed once; the model's side is its bit rows grown by the same disc, per model. The IoU is
// the exact one (no tolerance), as the silhouette IoU.
// Length (the size penalty of the smootherstep form, score.length_optimal / length_max): the
// derivation's steps. A genome whose derivation fails (an expression error, a limit passed) or
// whose drawing is invalid scores kWorstFitness and is counted as non-finite.
// What scoring leaves for the genome's children is its decision record (GraphDerivationRecord).
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "genome/families/graph_family.hpp"
#include "graph/drawing.hpp"
#include "graph/drawing_raster.hpp"
#include "score/image/image_fitness.hpp"
#include "score/image/image_target.hpp"
#include "score/scorer.hpp"

namespace shapevo {

class DrawingScorer final : public Scorer {
public:
    struct Workspace final : ScoreWorkspace {
        graph::DrawingRaster raster;
        std::vector<std::uint64_t> grown, row;  ///< the model's pixels grown by the tolerance; one row's spread
        std::int64_t steps = 0;                 ///< the last derivation's steps
        std::size_t shapes = 0;                 ///< the last drawing's shapes
    };

    /// `target` must outlive the scorer; `frame` has the target's size.
    DrawingScorer(const GraphFamily& family, const ImageTarget& target, const graph::RasterFrame& frame,
                  const FitnessSettings& settings, int tolerancePixels);

    std::unique_ptr<ScoreWorkspace> makeWorkspace() const override { return std::make_unique<Workspace>(); }
    double fitness(const Chromosome& c, ScoreWorkspace& w) const override {
        return score(c, static_cast<Workspace&>(w), nullptr);
    }
    /// The fitness, and (if `counts`) the exact counts (no tolerance) for the IoU and reports.
    double score(const Chromosome& c, Workspace& w, SilhouetteCounts* counts) const;
    /// The drawing of `c` (throws InputError as the derivation does).
    graph::Drawing drawing(const Chromosome& c) const;
    const graph::RasterFrame& frame() const { return frame_; }
    const GraphFamily& family() const { return family_; }
    int tolerance() const { return tolerance_; }

private:
    /// w.grown = w.raster's bits grown by the tolerance disc.
    void grow(Workspace& w) const;

    const GraphFamily& family_;
    const ImageTarget& target_;
    graph::RasterFrame frame_;
    FitnessSettings settings_;
    int tolerance_;
    std::vector<std::uint64_t> nearHit_;  ///< pixels within the tolerance of a hit pixel
    std::vector<int> reach_;              ///< per row offset dy in [-t, t]: the disc's half width
};

}  // namespace shapevo
