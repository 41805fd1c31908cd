// BestModelIoU: score the best model again only when it changed (see the header).
#include "run/best_model_iou.hpp"

#include <chrono>

namespace shapevo {

double BestModelIoU::of(const Scene& scene, const Chromosome& best) {
    using Clock = std::chrono::steady_clock;
    if (!known_ || !(best == model_)) {
        const auto start = Clock::now();
        const Scorer::Anomalies before = scene.scorer().anomalies();
        if (!workspace_) workspace_ = scene.scorer().makePlainWorkspace();
        iou_ = scene.iou(best, *workspace_);
        const Scorer::Anomalies after = scene.scorer().anomalies();
        added_.nonFinite += after.nonFinite - before.nonFinite;
        added_.truncated += after.truncated - before.truncated;
        model_ = best;
        known_ = true;
        seconds_ += std::chrono::duration<double>(Clock::now() - start).count();
    }
    return iou_;
}

}  // namespace shapevo
