// targetFromGenome (target_from_genome.hpp).
#include "run/target_from_genome.hpp"

#include <array>
#include <ostream>

#include "base/input_error.hpp"
#include "genome/genome_file.hpp"
#include "run/command_options.hpp"
#include "run/config_file.hpp"
#include "run/model_export.hpp"
#include "run/scene.hpp"

namespace shapevo {

void makeTargetFromGenome(const TargetRequest& r, std::ostream& out) {
    if (r.imageConfig.empty())
        throw InputError("--image", "", "a genome becomes a picture target through an image config's frame: give --image CONFIG");
    if (r.voxelSize) throw InputError("--voxel-size", "", "applies to a mesh made into a volume, not to a genome");
    requireOutputFormat(r.output, std::array<std::string_view, 1>{"png"}, "-o");
    refuseExisting(r.output);
    const RunSettings s = loadConfig(r.imageConfig, {});
    const std::unique_ptr<LoadedModel> model = LoadedModel::load(s);
    const Chromosome c = readGenome(model->family(), s.grammarPath, s.limits, r.meshPath);
    const std::uint64_t covered = Scene::load(s, *model)->drawModelTarget(c, r.output);
    out << "genome: " << model->describe(c) << "; covers " << covered << " pixels\nwrote " << r.output << "\n";
}

}  // namespace shapevo
