// BestModelIoU: the IoU of an island's best model, for the curve and the progress line. It is
// scored again only when the best model changes (often early in a run, rarely later: ~400 of 1,100
// generations in tree-logo's first 20 s), on the loop's thread between generations, in one kept
// workspace; the time goes to summary.json's iou_seconds (~0.3 % of the run). IoU is derived data:
// scoring draws no random number, and what it adds to the scorer's anomaly counts is kept here so
// that summary.json counts only the search's evaluations.
#pragma once
#include <memory>

#include "genome/chromosome.hpp"
#include "run/scene.hpp"

namespace shapevo {

class BestModelIoU {
public:
    double of(const Scene& scene, const Chromosome& best);
    const Scorer::Anomalies& addedAnomalies() const { return added_; }
    double seconds() const { return seconds_; }  ///< time spent scoring for IoU

private:
    Chromosome model_;
    std::unique_ptr<ScoreWorkspace> workspace_;
    double iou_ = 0, seconds_ = 0;
    bool known_ = false;
    Scorer::Anomalies added_;
};

}  // namespace shapevo
