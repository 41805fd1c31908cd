// The image kind's target for 2D graph grammars (loaded_drawing.hpp).
#include "score/image/loaded_drawing.hpp"

#include <cmath>

#include "base/input_error.hpp"
#include "score/image/drawing_scorer.hpp"
#include "score/image/overlay_image.hpp"

namespace shapevo {

graph::RasterFrame drawingFrame(const CameraSpec& cam, const std::string& file) {
    const glm::dvec3 view = cam.lookAt - cam.eye;
    const bool front = cam.projection == Projection::Orthographic && view.z < 0 && view.x == 0 && view.y == 0 &&
                       cam.up.x == 0 && cam.up.y > 0;
    if (!front)
        throw InputError(file, "[camera]",
                         "a 2D graph grammar's drawing is seen from the front: projection = \"orthographic\", eye = [x, y, "
                         "z] with look_at = [x, y, z'] below it (z' < z) and up = [0, 1, 0]; view_height model units span "
                         "the picture's height");
    const double k = graph::kUserUnitsPerModelUnit;
    graph::RasterFrame f;
    f.width = cam.width;
    f.height = cam.height;
    f.pixelsPerUnit = double(cam.height) / (cam.viewHeight * k);
    f.originX = cam.lookAt.x * k - 0.5 * double(cam.width) / f.pixelsPerUnit;
    f.originY = -cam.lookAt.y * k - 0.5 * double(cam.height) / f.pixelsPerUnit;
    return f;
}

namespace {

std::string fitText(const ImageTarget& t) {
    const auto wh = [](int w, int h) { return std::to_string(w) + "x" + std::to_string(h); };
    if (t.pictureWidth == t.width && t.pictureHeight == t.height) return wh(t.width, t.height) + " pixels";
    return wh(t.pictureWidth, t.pictureHeight) + " pixels fitted into " + wh(t.width, t.height) + " as " +
           wh(t.placement.width, t.placement.height) + " at (" + std::to_string(t.placement.x) + ", " + std::to_string(t.placement.y) + ")";
}

class LoadedDrawing final : public LoadedTarget {
public:
    LoadedDrawing(const ImageTargetSettings& s, const TargetLoadContext& c, const GraphFamily& family)
        : frame_(drawingFrame(s.camera, c.configPath)),
          target_(loadImageTarget(s.png, s.rule, frame_.width, frame_.height, s.fit, s.scale)),
          scorer_(family, target_, frame_, c.fitness, s.tolerance) {
        hash_ = target_.hash;
        primaryFile_ = s.png;
        requireVisible(c);
        description_ = s.png + " (" + fitText(target_) + ", " + std::to_string(target_.hitCount) + " to cover, a drawing" +
                       (s.tolerance > 0 ? ", tolerance " + std::to_string(s.tolerance) + " px" : std::string()) + ")";
        if (target_.autoCover == TargetCover::Opaque) choices_ = "cover: auto → opaque (the picture has transparency)";
        if (target_.autoCover == TargetCover::Dark) choices_ = "cover: auto → dark (the picture has no transparency)";
    }
    const Scorer& scorer() const override { return scorer_; }

    Evaluation evaluate(const Chromosome& c) const override {
        Evaluation e;
        DrawingScorer::Workspace ws;
        SilhouetteCounts n;
        e.fitness = scorer_.score(c, ws, &n);
        e.iou = silhouetteIoU(n, target_.hitCount);
        e.text = evaluationText(imageTargetKind, e.fitness, e.iou, c.genes, ws.shapes,
                                countsText({{"covered", n.covered}, {"hit", n.hit}, {"avoided", n.avoided}, {"target", target_.hitCount}}));
        return e;
    }
    double iou(const Chromosome& c, ScoreWorkspace& workspace) const override {
        SilhouetteCounts n;
        scorer_.score(c, static_cast<DrawingScorer::Workspace&>(workspace), &n);
        return silhouetteIoU(n, target_.hitCount);
    }
    double writeBest(const Chromosome& best, const std::string& folder) const override { return writeOverlay(best, folder + "/best-overlay.png"); }
    void exportBest(const Chromosome& best, const std::string&, const std::string& path) const override { writeOverlay(best, path); }
    std::uint64_t drawModelTarget(const Chromosome& c, const std::string& path) const override {
        DrawingScorer::Workspace ws;
        SilhouetteCounts counts;
        scorer_.score(c, ws, &counts);
        std::vector<std::uint8_t> mask(std::size_t(target_.width) * std::size_t(target_.height), 0);
        for (int y = 0; y < target_.height && counts.covered > 0; ++y)
            for (int x = 0; x < target_.width; ++x) mask[std::size_t(y) * std::size_t(target_.width) + std::size_t(x)] = ws.raster.covered(x, y);
        writeMaskPng(path, target_.width, target_.height, mask);
        return counts.covered;
    }

private:
    /// Some of the check models must cover a pixel: a frame that shows nothing makes the search blind.
    void requireVisible(const TargetLoadContext& c) const {
        DrawingScorer::Workspace ws;
        if (c.checkModels.any(c.family, [&](const Chromosome& m) {
                SilhouetteCounts counts;
                scorer_.score(m, ws, &counts);
                return counts.covered > 0;
            }))
            return;
        throw InputError(c.configPath, "[camera]",
                         "sees nothing: none of " + std::to_string(CheckModels::kCount) + " random drawings of " +
                             scorer_.family().grammar().path +
                             " covers a single pixel of the picture; set look_at and view_height to where the grammar draws");
    }

    double writeOverlay(const Chromosome& best, const std::string& path) const {
        DrawingScorer::Workspace ws;
        SilhouetteCounts counts;
        scorer_.score(best, ws, &counts);
        const int W = target_.width, H = target_.height;
        std::vector<std::uint8_t> model(std::size_t(W) * std::size_t(H)), target(model.size());
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                const std::size_t i = std::size_t(y) * std::size_t(W) + std::size_t(x);
                model[i] = counts.covered > 0 && ws.raster.covered(x, y) ? 1 : 0;
                target[i] = target_.isHit(x, y) ? 1 : target_.isAvoid(x, y) ? 2 : 0;
            }
        writeOverlayPng(path, W, H, target.data(), model.data());
        return silhouetteIoU(counts, target_.hitCount);
    }

    graph::RasterFrame frame_;
    ImageTarget target_;
    DrawingScorer scorer_;
};

}  // namespace

std::unique_ptr<LoadedTarget> loadDrawingTarget(const ImageTargetSettings& s, const TargetLoadContext& c, const GraphFamily& family) {
    return std::make_unique<LoadedDrawing>(s, c, family);
}

}  // namespace shapevo
