// The image target kind: its reader ([target] picture keys, [camera]), its loaded target (scorer,
// start-up visibility check, IoU, best-overlay.png) and its entry.
#include "score/image/image_kind.hpp"

#include <algorithm>
#include <array>
#include <iterator>
#include <sstream>

#include "base/format_double.hpp"
#include "base/input_error.hpp"
#include "mesh/mesh_repair.hpp"
#include "score/image/image_scorer.hpp"
#include "score/image/loaded_drawing.hpp"
#include "score/image/mesh_image_target.hpp"
#include "score/image/overlay_image.hpp"

namespace shapevo {

namespace {

/// A whole number in [lo, hi] (lo >= 0) into an int.
void readInt(SectionReader& r, std::string_view key, int& value, double lo, double hi, std::string_view meaning) {
    std::uint32_t v = std::uint32_t(value);
    r.count(key, v, lo, hi, meaning);
    value = int(v);
}

/// [camera]: projection = "perspective" | "orthographic" | "shadow" and its settings; checked by
/// Camera::compile now (located errors) and again when the target is loaded.
void readCamera(SectionReader& r, CameraSpec& c) {
    std::string projection = "perspective";
    r.string("projection", projection,
             "\"perspective\", \"orthographic\" (parallel rays) or \"shadow\" (the model's shadow on a ground plane)");
    if (projection == "perspective") c.projection = Projection::Perspective;
    else if (projection == "orthographic") c.projection = Projection::Orthographic;
    else if (projection == "shadow") c.projection = Projection::Shadow;
    else r.fail("projection", "camera.projection must be \"perspective\", \"orthographic\" or \"shadow\", got \"" + shortened(projection) + "\"");
    readInt(r, "width", c.width, 1, 16384,
            "picture width in pixels (a target picture is fitted into width x height, see target.fit)");
    readInt(r, "height", c.height, 1, 16384, "picture height in pixels");
    r.vec("eye", c.eye, "perspective and orthographic: the camera's position");
    r.vec("look_at", c.lookAt, "perspective and orthographic: the point the camera looks at");
    r.vec("up", c.up, "perspective and orthographic: the direction that is up in the picture");
    r.number("fov_degrees", c.fovDegrees, -1e9, 1e9, "perspective: vertical field of view in degrees, strictly between 0 and 180");
    r.number("view_height", c.viewHeight, -1e12, 1e12, "orthographic: world units across the picture's height (positive)");
    r.number("near", c.near, -1e12, 1e12,
             "perspective: nothing closer to the eye than this is seen (at least 1e-9; there is no far plane)");
    r.vec("light", c.light, "shadow: the direction of the light's rays");
    r.number("ground_y", c.groundY, -1e12, 1e12,
             "shadow: the ground plane y = ground_y; only what is above it casts a shadow");
    r.vec("ground_min", c.groundMin,
          "shadow: the (x, z) corner of the ground rectangle that fills the picture (x to the right, z downwards)");
    r.vec("ground_max", c.groundMax,
          "shadow: the opposite (x, z) corner; a rectangle whose aspect differs from width / height is extended about "
          "its centre");
    r.located([&] { Camera::compile(c, r.file(), "camera"); });
}

/// "800x600 pixels", or how a picture of another size was fitted: "229x304 pixels fitted
/// (contain) into 800x600 as 452x600 at (174, 0)".
std::string imagePlacement(const ImageTarget& t, TargetFit fit) {
    const auto wh = [](int w, int h) { return std::to_string(w) + "x" + std::to_string(h); };
    const TargetPlacement& p = t.placement;
    if (t.pictureWidth == t.width && t.pictureHeight == t.height && p == TargetPlacement{0, 0, t.width, t.height})
        return wh(t.width, t.height) + " pixels";
    return wh(t.pictureWidth, t.pictureHeight) + " pixels fitted (" + targetFitName(fit) + ") into " + wh(t.width, t.height) +
           " as " + wh(p.width, p.height) + " at (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")";
}

/// For a shadow camera whose ground rectangle was extended to square pixels: the one used.
std::string groundNote(const Camera& c) {
    if (c.projection() != Projection::Shadow || !c.groundExtended()) return "";
    return "; ground rectangle extended to the picture's aspect: [" + formatDouble(c.groundMin().x) + ", " +
           formatDouble(c.groundMin().y) + "]..[" + formatDouble(c.groundMax().x) + ", " + formatDouble(c.groundMax().y) + "]";
}

/// A camera that sees nothing makes every fitness equal and the search blind: refuse it. The
/// check models must cover at least one pixel between them.
void requireVisible(const TargetLoadContext& c, const ImageScorer& scorer) {
    ImageScorer::Workspace ws(scorer.camera());
    if (c.checkModels.any(c.family, [&](const Chromosome& m) {
            SilhouetteCounts counts;
            scorer.fitness(m, ws, &counts);
            return counts.covered > 0;
        }))
        return;
    throw InputError(c.configPath, "[camera]",
                     "sees nothing: none of " + std::to_string(CheckModels::kCount) + " random models of " + scorer.grammar().path +
                         " covers a single pixel of the picture; point the camera (or the shadow's ground rectangle) at "
                         "where the grammar builds");
}

class LoadedImage final : public LoadedTarget {
public:
    LoadedImage(const ImageTargetSettings& s, const TargetLoadContext& c)
        : camera_(Camera::compile(s.camera, c.configPath)),
          target_(loadImageTarget(s.png, s.rule, camera_.width(), camera_.height(), s.fit, s.scale)),
          scorer_(requireTreeGrammar(c, imageTargetKind), camera_, target_, c.fitness) {
        if (s.tolerance > 0)
            throw InputError(c.configPath, "[target] tolerance",
                             "applies to the drawings of 2D graph grammars; a silhouette is matched pixel for pixel");
        scorer_.setMaxPrimitives(c.maxPrimitives);
        scorer_.setIncremental(c.incremental.cacheBytes(), c.incremental.check);
        hash_ = target_.hash;
        primaryFile_ = s.png;
        const char* kind = s.camera.projection == Projection::Shadow         ? "shadow"
                           : s.camera.projection == Projection::Orthographic ? "orthographic silhouette"
                                                                             : "perspective silhouette";
        requireVisible(c, scorer_);
        description_ = s.png + " (" + imagePlacement(target_, s.fit) + ", " + std::to_string(target_.hitCount) + " to cover, " +
                       kind + groundNote(camera_) + ")";
        if (target_.autoCover == TargetCover::Opaque) choices_ = "cover: auto → opaque (the picture has transparency)";
        if (target_.autoCover == TargetCover::Dark) choices_ = "cover: auto → dark (the picture has no transparency)";
    }
    const Scorer& scorer() const override { return scorer_; }

    Evaluation evaluate(const Chromosome& c) const override {
        Evaluation e;
        e.fitness = scorer_.fitness(c, *scorer_.makePlainWorkspace());
        ImageScorer::Workspace ws(camera_);
        SilhouetteCounts n;
        scorer_.fitness(c, ws, &n);
        e.iou = silhouetteIoU(n, target_.hitCount);
        e.text = evaluationText(imageTargetKind, e.fitness, e.iou, c.genes, ws.geometry.primitives.size(),
                                countsText({{"covered", n.covered}, {"hit", n.hit}, {"avoided", n.avoided}, {"target", target_.hitCount}}));
        return e;
    }
    double iou(const Chromosome& c, ScoreWorkspace& workspace) const override {
        SilhouetteCounts n;
        scorer_.fitness(c, static_cast<ImageScorer::Workspace&>(workspace), &n);
        return silhouetteIoU(n, target_.hitCount);
    }
    double writeBest(const Chromosome& best, const std::string& folder) const override {
        return writeOverlay(best, folder + "/best-overlay.png");
    }
    void exportBest(const Chromosome& best, const std::string&, const std::string& path) const override {
        writeOverlay(best, path);
    }
    std::uint64_t drawModelTarget(const Chromosome& c, const std::string& path) const override {
        ImageScorer::Workspace ws(camera_);
        std::vector<std::uint8_t> mask;
        scorer_.modelMask(c, ws, mask);
        writeMaskPng(path, target_.width, target_.height, mask);
        std::uint64_t covered = 0;
        for (std::uint8_t m : mask) covered += m != 0;
        return covered;
    }

private:
    /// The model's silhouette over the target as a PNG; returns its IoU.
    double writeOverlay(const Chromosome& best, const std::string& path) const {
        ImageScorer::Workspace ws(camera_);
        SilhouetteCounts counts;
        scorer_.fitness(best, ws, &counts);
        const double iou = silhouetteIoU(counts, target_.hitCount);
        std::vector<std::uint8_t> model, target(std::size_t(target_.width) * std::size_t(target_.height));
        scorer_.modelMask(best, ws, model);
        for (int y = 0; y < target_.height; ++y)
            for (int x = 0; x < target_.width; ++x)
                target[std::size_t(y) * std::size_t(target_.width) + std::size_t(x)] =
                    target_.isHit(x, y) ? 1 : target_.isAvoid(x, y) ? 2 : 0;
        writeOverlayPng(path, target_.width, target_.height, target.data(), model.data());
        return iou;
    }

    Camera camera_;
    ImageTarget target_;
    ImageScorer scorer_;
};

std::string drawMesh(const TargetSettings& settings, const Mesh& mesh, const std::string& meshPath,
                     const std::string& configPath, const std::string& out) {
    const auto& s = static_cast<const ImageTargetSettings&>(settings);  // the entry's own kind
    const Camera camera = Camera::compile(s.camera, configPath);
    const std::uint64_t covered = writeMeshImageTarget(mesh, camera, s.rule, meshPath, configPath + " [target]", out);
    std::ostringstream text;
    text << "mesh: " << groupedNumber(mesh.triangles.size()) << " triangles; "
         << (camera.projection() == Projection::Shadow ? "shadow" : "silhouette") << " covers " << groupedNumber(covered)
         << " of " << camera.width() << " x " << camera.height() << " pixels\n"
         << "wrote " << out << "\n";
    return text.str();
}

constexpr std::array<std::string_view, 1> kImageSections{"camera"};
constexpr std::array<std::string_view, 1> kImageShellRelativeFiles{"image"};
constexpr std::array<std::string_view, 1> kImageExportFormats{"png"};

}  // namespace

std::unique_ptr<TargetSettings> ImageTargetSettings::read(SectionReader& r) {
    auto s = std::make_unique<ImageTargetSettings>();
    PixelRule& rule = s->rule;
    r.string("image", s->image_,
             "image: the target picture, a PNG (grey, grey + alpha, palette, RGB or RGBA, 8 or 16 bits); relative to "
             "the config's folder (to the current directory when given with --set); names the image kind");
    readInt(r, "hit_min", rule.hitMin, 0, 255,
            "image: lowest luminance (Rec. 601, 0-255) of the pixels the model must cover");
    readInt(r, "hit_max", rule.hitMax, 0, 255, "image: highest luminance of the pixels the model must cover");
    readInt(r, "avoid_min", rule.avoidMin, 0, 255, "image: lowest luminance of the pixels the model must leave empty");
    readInt(r, "avoid_max", rule.avoidMax, 0, 255, "image: highest luminance of the pixels the model must leave empty");
    readInt(r, "alpha_threshold", rule.alphaThreshold, 0, 256,
            "image: pixels with alpha below this are transparent: don't care (avoided with cover = \"opaque\"; what "
            "makes cover = \"auto\" choose \"opaque\")");
    // target.cover: a preset for the four ranges, so it is either it or them; alpha_threshold
    // goes with both. Neither given: "auto" (the picture's transparency chooses when it is loaded).
    const char* const rangeKeys[] = {"hit_min", "hit_max", "avoid_min", "avoid_max"};
    std::string cover(targetCoverName(TargetCover::Auto));  // the default when no range is given either
    r.string("cover", cover,
             "image: which pixels to cover, a preset of hit_min, hit_max, avoid_min and avoid_max: \"auto\" (when the "
             "picture is loaded: \"opaque\" if it has transparency, a pixel with alpha below alpha_threshold, else "
             "\"dark\"; the run's first line says which), \"dark\" (luminance 0-127 hit, 128-255 avoid), \"light\" (the "
             "reverse) or \"opaque\" (opaque pixels hit, transparent ones avoid); not with those four keys, and giving "
             "any of them without cover sets the ranges instead");
    if (r.has("cover")) {
        const TargetCover presets[] = {TargetCover::Auto, TargetCover::Dark, TargetCover::Light, TargetCover::Opaque};
        const TargetCover* preset = nullptr;
        for (const TargetCover& c : presets)
            if (cover == targetCoverName(c)) preset = &c;
        if (!preset)
            r.fail("cover", "target.cover must be \"auto\", \"dark\", \"light\" or \"opaque\", got \"" + shortened(cover) + "\"");
        for (const char* k : rangeKeys)
            if (r.has(k))
                r.failKeys({"target.cover", "target.hit_min", "target.hit_max", "target.avoid_min", "target.avoid_max"}, "[target]",
                           "target.cover and target." + std::string(k) +
                               " both say which pixels to cover: give the preset (cover = \"auto\", \"dark\", \"light\" or "
                               "\"opaque\") or the luminance ranges (hit_min, hit_max, avoid_min, avoid_max), not both");
        rule = PixelRule::forCover(*preset, rule.alphaThreshold);
    } else if (std::none_of(std::begin(rangeKeys), std::end(rangeKeys), [&](const char* k) { return r.has(k); })) {
        rule = PixelRule::forCover(TargetCover::Auto, rule.alphaThreshold);
    }
    std::string fit = targetFitName(s->fit);
    r.string("fit", fit,
             "image: how the picture meets the camera's frame: \"contain\" (aspect kept, as large as fits, margins "
             "don't care), \"cover\" (aspect kept, fills the frame, overflow cut), \"stretch\" or \"exact\" (the "
             "picture must have the frame's size)");
    if (r.has("fit")) {
        bool known = false;
        for (TargetFit f : {TargetFit::Contain, TargetFit::Cover, TargetFit::Stretch, TargetFit::Exact})
            if (fit == targetFitName(f)) s->fit = f, known = true;
        if (!known)
            r.fail("fit", "target.fit must be \"contain\", \"cover\", \"stretch\" or \"exact\", got \"" + shortened(fit) + "\"");
    }
    readInt(r, "tolerance", s->tolerance, 0, 32,
            "image, for a 2D graph grammar's drawing: a drawn pixel within this many pixels of a pixel to cover is not "
            "counted as avoided, and a pixel to cover within it of a drawn pixel counts as covered (thin line art); 0 = "
            "exact");
    r.number("scale", s->scale, 0.01, 1.0,
             "image, with fit = \"contain\" or \"stretch\": the share of the frame's width and height the fitted "
             "picture may take, centred (the rest is don't care)");
    if (r.has("scale") && s->scale < 1.0 && s->fit != TargetFit::Contain && s->fit != TargetFit::Stretch)
        r.failKeys({"target.scale", "target.fit"}, "[target]",
                   "target.scale makes the picture take part of the frame, which only target.fit = \"contain\" or "
                   "\"stretch\" do (\"" + std::string(targetFitName(s->fit)) + "\" takes the whole frame)");
    return s;
}

void ImageTargetSettings::finish(ConfigReader& config, const std::string&) {
    SectionReader& target = config.section("target");
    png = target.resolvePath(image_);
    target.located([&] { rule.check(target.file(), "target"); });
    readCamera(config.section("camera"), camera);
}

std::unique_ptr<LoadedTarget> ImageTargetSettings::load(const TargetLoadContext& context) const {
    if (const GraphFamily* graph = context.family.graphFamily()) return loadDrawingTarget(*this, context, *graph);
    return std::make_unique<LoadedImage>(*this, context);
}

const TargetKind imageTargetKind{
    .name = "image",
    .summary = "a PNG picture (hit / avoid / don't care pixels) matched by the model's silhouette or shadow through [camera]",
    .readTarget = ImageTargetSettings::read,
    .sections = kImageSections,
    .shellRelativeFiles = kImageShellRelativeFiles,
    .noun = "an image target",
    .namedBy = "image = \"FILE.png\"",
    .namingLine = "image = \"target.png\"",
    .keysPhrase = "an image",
    .iouName = "silhouette IoU",
    .iouKey = "silhouette_iou",
    .exportFormats = kImageExportFormats,
    .drawMeshTarget = drawMesh,
};

}  // namespace shapevo
